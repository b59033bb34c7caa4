// SPDX-License-Identifier: Apache-2.0
/* fgr kernel library: the camera and the image's layout, shared by every render mode's entry
 * point (fgr_mode_*.cl).
 *
 * Work decomposition: work-item g renders tile g, FGR_TILE_W x FGR_TILE_H pixels in the lanes of
 * one packet (a 1x1 tile when FGR_WIDTH is 1). Neighbouring pixels march nearly the same path, so
 * the lanes of a packet stay busy together. Results are stored tile-major in planes, each lane at
 * tile * FGR_WIDTH + lane, with vector stores; the host re-orders them into rows while encoding
 * the image. The tiles' shape and what each plane holds are shared with the host
 * (shared/fgr_layout_planes.h). */

#define FGR_TILE_W FGR_TILE_WIDTH(FGR_WIDTH)
#define FGR_TILE_H FGR_TILE_HEIGHT(FGR_WIDTH)
/* Each lane's column and row in its tile. */
#if FGR_WIDTH == 1
#define FGR_LANE_X ((real)(0.0f))
#define FGR_LANE_Y ((real)(0.0f))
#define fgr_store(value, tile, plane) ((plane)[tile] = convert_float_lanes(value))
#define fgr_load(tile, plane) convert_real((plane)[tile])
#elif FGR_WIDTH == 4
#define FGR_LANE_X ((real)(0, 1, 0, 1))
#define FGR_LANE_Y ((real)(0, 0, 1, 1))
#define fgr_store(value, tile, plane) vstore4(convert_float_lanes(value), (tile), (plane))
#define fgr_load(tile, plane) convert_real(vload4((tile), (plane)))
#elif FGR_WIDTH == 8
#define FGR_LANE_X ((real)(0, 1, 2, 3, 0, 1, 2, 3))
#define FGR_LANE_Y ((real)(0, 0, 0, 0, 1, 1, 1, 1))
#define fgr_store(value, tile, plane) vstore8(convert_float_lanes(value), (tile), (plane))
#define fgr_load(tile, plane) convert_real(vload8((tile), (plane)))
#elif FGR_WIDTH == 16
#define FGR_LANE_X ((real)(0, 1, 2, 3, 0, 1, 2, 3, 0, 1, 2, 3, 0, 1, 2, 3))
#define FGR_LANE_Y ((real)(0, 0, 0, 0, 1, 1, 1, 1, 2, 2, 2, 2, 3, 3, 3, 3))
#define fgr_store(value, tile, plane) vstore16(convert_float_lanes(value), (tile), (plane))
#define fgr_load(tile, plane) convert_real(vload16((tile), (plane)))
#endif

/* The switches as 0 or 1, for the plane layouts that depend on them (fgr_layout_planes.h). */
#ifdef FGR_STATS
#define FGR_STATS_ON 1
#else
#define FGR_STATS_ON 0
#endif
#ifdef FGR_GEOMETRY_IFS
#define FGR_IFS_ON 1
#else
#define FGR_IFS_ON 0
#endif

/* The camera arrives as a camera_frame (shared/fgr_layout_camera.h): the eye, split into hi + lo
 * for double lanes, the basis, the projection and the region rendered. The projection
 * (host/camera/projection.hpp describes each layout) maps pixels to rays: pinhole,
 * equirectangular (the whole sphere), equidistant fisheye, or a stereo pair of off-axis pinholes
 * side by side or top/bottom. */

inline vec3 splat_float4(float4 v) { return v3_splat(v.x, v.y, v.z); }

/* The eye in the lanes' precision: hi + lo summed in double; float can only use hi, which keeps
 * float images exactly as they were before the split. */
inline vec3 camera_eye(camera_frame camera) {
#ifdef FGR_DOUBLE
    return v3_add(splat_float4(camera.eye),
                  v3_splat(camera.eye.w, camera.forward.w, camera.right.w));
#else
    return splat_float4(camera.eye);
#endif
}

/* A point of the image within the view it belongs to: a stereo pair's eye, or the whole image.
 * The eye is chosen by the pixel (px, py), the point is the sample s within it. */
typedef struct camera_view_point {
    real x, y;           /* in the view's pixels */
    float width, height; /* the view's size in pixels */
    real eye_side;       /* -1 left eye, +1 right eye, 0 a single view */
} camera_view_point;

inline camera_view_point camera_view_point_of(camera_frame camera, real px, real py,
                                              camera_sample s) {
    camera_view_point point;
    point.x = px + s.pixel_x;
    point.y = py + s.pixel_y;
    point.width = (float)camera.width;
    point.height = (float)camera.height;
    point.eye_side = fgr_real(0.0f);
    if (camera.projection == FGR_PROJECTION_STEREO_SBS) {
        point.width *= 0.5f;
        const mask right_eye = px >= point.width;
        point.x -= select(fgr_real(0.0f), fgr_real(point.width), right_eye);
        point.eye_side = select(fgr_real(-1.0f), fgr_real(1.0f), right_eye);
    } else if (camera.projection == FGR_PROJECTION_STEREO_TB) {
        point.height *= 0.5f;
        const mask right_eye = py >= point.height;
        point.y -= select(fgr_real(0.0f), fgr_real(point.height), right_eye);
        point.eye_side = select(fgr_real(-1.0f), fgr_real(1.0f), right_eye);
    }
    return point;
}

/* The fisheye's point in units of the image circle's radius, from its centre (y up). */
inline void fisheye_offset(camera_view_point point, real* dx, real* dy) {
    const float radius = 0.5f * fmin(point.width, point.height);
    *dx = (point.x - 0.5f * point.width) / radius;
    *dy = (0.5f * point.height - point.y) / radius;
}

/* Whether pixel (px, py) shows anything: all do but those outside a fisheye's image circle,
 * which start inactive and cost no march. */
inline mask camera_covers(camera_frame camera, real px, real py) {
    if (camera.projection != FGR_PROJECTION_FISHEYE) return (mask)(FGR_TRUE);
    camera_sample centre;
    centre.pixel_x = centre.pixel_y = fgr_real(0.5f);
    centre.lens_x = centre.lens_y = fgr_real(0.0f);
    real dx, dy;
    fisheye_offset(camera_view_point_of(camera, px, py, centre), &dx, &dy);
    return dx * dx + dy * dy <= 1.0f;
}

/* Direction through the point (s.pixel_x, s.pixel_y) of pixel (px, py): jittered in the pixel
 * for anti-aliasing. A pinhole's (and each stereo eye's) has unit length along `forward`, not
 * normalised, so depth of field finds its focus plane along it; the panoramas' are unit (their
 * focus is a sphere). */
inline vec3 primary_direction(camera_frame camera, real px, real py, camera_sample s) {
    const camera_view_point point = camera_view_point_of(camera, px, py, s);
    const vec3 forward = splat_float4(camera.forward);
    const vec3 right = splat_float4(camera.right);
    const vec3 up = splat_float4(camera.up);
    if (camera.projection == FGR_PROJECTION_EQUIRECTANGULAR) {
        const real longitude = (2.0f * point.x / point.width - 1.0f) * M_PI_F;
        const real latitude = (1.0f - 2.0f * point.y / point.height) * M_PI_2_F;
        const real across = fgr_cos(latitude);
        return v3_add(v3_scale(up, fgr_sin(latitude)),
                      v3_add(v3_scale(right, across * fgr_sin(longitude)),
                             v3_scale(forward, across * fgr_cos(longitude))));
    }
    if (camera.projection == FGR_PROJECTION_FISHEYE) {
        /* Equidistant: the angle from the axis is proportional to the radius. */
        real dx, dy;
        fisheye_offset(point, &dx, &dy);
        const real r = sqrt(dx * dx + dy * dy);
        const real theta = fmin(r, 1.0f) * camera.fisheye_half_fov;
        /* sin(theta) / r, tending to the half fov at the centre. */
        const real across =
            select(fgr_sin(theta) / fmax(r, 1e-7f), fgr_real(camera.fisheye_half_fov), r < 1e-7f);
        return v3_add(v3_scale(forward, fgr_cos(theta)),
                      v3_add(v3_scale(right, across * dx), v3_scale(up, across * dy)));
    }
    /* Pinhole, and each stereo eye: an off-axis frustum, shifted so its centre line crosses the
     * view's axis at the convergence distance (eye_side is 0 for a single view). */
    const real shift = -point.eye_side * (0.5f * camera.eye_separation / camera.convergence);
    const real u = (2.0f * point.x / point.width - 1.0f) * camera.tan_half_fov + shift;
    const real v =
        (1.0f - 2.0f * point.y / point.height) * camera.tan_half_fov * (point.height / point.width);
    return v3_add(forward, v3_add(v3_scale(right, u), v3_scale(up, v)));
}

/* Where the rays of pixel (px, py) start: the eye, or for a stereo pair the pixel's eye, half the
 * separation to its side. */
inline vec3 camera_origin(camera_frame camera, real px, real py) {
    const vec3 eye = camera_eye(camera);
    if (camera.projection != FGR_PROJECTION_STEREO_SBS &&
        camera.projection != FGR_PROJECTION_STEREO_TB) {
        return eye;
    }
    camera_sample centre;
    centre.pixel_x = centre.pixel_y = fgr_real(0.5f);
    centre.lens_x = centre.lens_y = fgr_real(0.0f);
    const real side = camera_view_point_of(camera, px, py, centre).eye_side;
    return v3_mad(eye, splat_float4(camera.right), side * (0.5f * camera.eye_separation));
}

/* Whether pixels (ax, ay) and (bx, by) belong to the same view (a stereo pair's eye): screen-space
 * neighbours across the seam between the eyes are not neighbours in the world. */
inline mask camera_same_view(camera_frame camera, real ax, real ay, real bx, real by) {
    if (camera.projection == FGR_PROJECTION_STEREO_SBS) {
        const float middle = 0.5f * (float)camera.width;
        return (ax >= middle) == (bx >= middle);
    }
    if (camera.projection == FGR_PROJECTION_STEREO_TB) {
        const float middle = 0.5f * (float)camera.height;
        return (ay >= middle) == (by >= middle);
    }
    return (mask)(FGR_TRUE);
}

/* A primary ray: from the eye (or a point on the lens) through the pixel. */
typedef struct camera_ray {
    vec3 origin;
    vec3 dir; /* unit */
} camera_ray;

/* The ray of camera sample `s` through pixel (px, py). With depth of field the ray leaves a point
 * on the lens (radius `aperture`) towards the point of the pixel's ray at the focus distance,
 * which therefore stays sharp. */
inline camera_ray camera_ray_through(camera_frame camera, real px, real py, camera_sample s,
                                     PARAMS) {
    (void)fgr_params;
    const vec3 through_pixel = primary_direction(camera, px, py, s);
    camera_ray ray;
    ray.origin = camera_origin(camera, px, py);
    ray.dir = v3_normalize(through_pixel);
#ifdef FGR_EFFECT_DEPTH_OF_FIELD
    /* A pinhole's through_pixel has unit length along `forward`, so the focus plane is at
     * eye + through_pixel * focus_distance; a panorama's is unit, focusing on a sphere. The lens
     * lies across the view's axis, so a panorama's sideways rays blur less. */
    const vec3 focus = v3_mad(ray.origin, through_pixel, fgr_real(param_focus_distance));
    ray.origin =
        v3_add(ray.origin, v3_add(v3_scale(splat_float4(camera.right), s.lens_x * param_aperture),
                                  v3_scale(splat_float4(camera.up), s.lens_y * param_aperture)));
    ray.dir = v3_normalize(v3_sub(focus, ray.origin));
#endif
    return ray;
}

/* The arguments every render mode's entry point `fgr_render` starts with, in the order of
 * FGR_RENDER_ARG_* (shared/fgr_layout_arguments.h), by which the host sets them
 * (host/render/renderer.cpp); a mode's own arguments follow from FGR_RENDER_ARGS_COUNT:
 *   planes      the output: plane p of the image at planes + p * plane_size, tile-major
 *   plane_size  floats per plane (whole tiles)
 *   tile_count  tiles in the image; the global size is rounded up past it
 *   camera      the view
 *   sample      which sample of each pixel this launch renders (0, 1, 2, ...)
 *   PARAMS      the scene's parameter buffer
 *   march_starts where each tile's camera rays start (the cone prepass, fgr_prepass.cl; zeros
 *               where it did not run): march_start_of
 *   march_hints, has_hints  reprojected start hints, a plane laid out as the image's (when
 *               has_hints is set): march_start_with_hint */
#define FGR_RENDER_ARGS                                                                      \
    __global float *planes, int plane_size, int tile_count, camera_frame camera, int sample, \
        PARAMS, __global const float *march_starts, __global const float *march_hints,       \
        int has_hints

/* The pixels of one tile, one per lane. */
typedef struct tile_pixels {
    real px, py; /* each lane's pixel, in the whole image */
    mask inside; /* lanes past the region's edge (partial tiles) or outside a fisheye's image
                  * circle start inactive and cost no steps */
} tile_pixels;

/* Tiles across the region. */
inline int region_tiles_x(camera_frame camera) {
    return (camera.region_width + FGR_TILE_W - 1) / FGR_TILE_W;
}

inline tile_pixels pixels_of_tile(int tile, camera_frame camera) {
    tile_pixels pixels;
    const int tiles_x = region_tiles_x(camera);
    pixels.px = (float)(camera.region_x + (tile % tiles_x) * FGR_TILE_W) + FGR_LANE_X;
    pixels.py = (float)(camera.region_y + (tile / tiles_x) * FGR_TILE_H) + FGR_LANE_Y;
    pixels.inside = (pixels.px < (float)(camera.region_x + camera.region_width)) &
                    (pixels.py < (float)(camera.region_y + camera.region_height)) &
                    camera_covers(camera, pixels.px, pixels.py);
    return pixels;
}

/* Adds `value` to plane `plane` of the tile from sample 1 on (sample 0 writes it): samples
 * accumulate in the planes and the host divides by their count. */
inline void accumulate_plane(real value, int sample, int tile, __global float* plane) {
    if (sample > 0) value += fgr_load(tile, plane);
    fgr_store(value, tile, plane);
}
