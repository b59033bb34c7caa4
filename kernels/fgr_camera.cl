/* fgr kernel library: the camera and the image's layout, shared by every render mode's entry
 * point (fgr_mode_*.cl).
 *
 * Work decomposition: work-item g renders tile g, FGR_TILE_W x FGR_TILE_H pixels in the lanes of
 * one packet (a 1x1 tile when FGR_WIDTH is 1). Neighbouring pixels march nearly the same path, so
 * the lanes of a packet stay busy together. Results are stored tile-major in planes
 * (r, g, b, depth), each lane at tile * FGR_WIDTH + lane, with vector stores; the host re-orders
 * them into rows while encoding the image. */

#if FGR_WIDTH == 1
#define FGR_TILE_W 1
#define FGR_LANE_X ((real)(0.0f))
#define FGR_LANE_Y ((real)(0.0f))
#define fgr_store(value, tile, plane) ((plane)[tile] = convert_float_lanes(value))
#define fgr_load(tile, plane) convert_real((plane)[tile])
#elif FGR_WIDTH == 4
#define FGR_TILE_W 2
#define FGR_LANE_X ((real)(0, 1, 0, 1))
#define FGR_LANE_Y ((real)(0, 0, 1, 1))
#define fgr_store(value, tile, plane) vstore4(convert_float_lanes(value), (tile), (plane))
#define fgr_load(tile, plane) convert_real(vload4((tile), (plane)))
#elif FGR_WIDTH == 8
#define FGR_TILE_W 4
#define FGR_LANE_X ((real)(0, 1, 2, 3, 0, 1, 2, 3))
#define FGR_LANE_Y ((real)(0, 0, 0, 0, 1, 1, 1, 1))
#define fgr_store(value, tile, plane) vstore8(convert_float_lanes(value), (tile), (plane))
#define fgr_load(tile, plane) convert_real(vload8((tile), (plane)))
#elif FGR_WIDTH == 16
#define FGR_TILE_W 4
#define FGR_LANE_X ((real)(0, 1, 2, 3, 0, 1, 2, 3, 0, 1, 2, 3, 0, 1, 2, 3))
#define FGR_LANE_Y ((real)(0, 0, 0, 0, 1, 1, 1, 1, 2, 2, 2, 2, 3, 3, 3, 3))
#define fgr_store(value, tile, plane) vstore16(convert_float_lanes(value), (tile), (plane))
#define fgr_load(tile, plane) convert_real(vload16((tile), (plane)))
#endif
#define FGR_TILE_H (FGR_WIDTH / FGR_TILE_W)

/* The camera as the host sends it: eye, then the orthonormal basis, each padded to a float4. The
 * host keeps the eye in double and sends it split, eye = hi + lo: hi (eye.xyz) is the nearest
 * float, lo the float nearest the rest, carried in the otherwise unused w components
 * (eye.w, forward.w, right.w). Double lanes see the eye to about 2^-48 of its size, so a deep
 * zoom's eye can move by less than float's step. */
typedef struct camera_frame {
    float4 eye;
    float4 forward;
    float4 right;
    float4 up;
    float tan_half_fov;
    float pixel_angle; /* 2 * tan_half_fov / width: one pixel's angular footprint */
    int width;  /* of the whole image: directions and footprints follow it */
    int height;
    /* The rectangle of the image this launch renders (tiled stills render the image a region at
     * a time): tiles and planes cover the region, pixel coordinates stay the whole image's, so
     * every pixel gets exactly the ray, samples and random numbers of an untiled render. */
    int region_x;
    int region_y;
    int region_width;
    int region_height;
} camera_frame;

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

/* Direction (unit length along `forward`, not normalised) through the point (s.pixel_x,
 * s.pixel_y) of pixel (px, py): jittered in the pixel for anti-aliasing. */
inline vec3 primary_direction(camera_frame camera, real px, real py, camera_sample s) {
    const float aspect = (float)camera.height / (float)camera.width;
    const real u = (2.0f * (px + s.pixel_x) / (float)camera.width - 1.0f) * camera.tan_half_fov;
    const real v = (1.0f - 2.0f * (py + s.pixel_y) / (float)camera.height) * camera.tan_half_fov *
                   aspect;
    return v3_add(splat_float4(camera.forward), v3_add(v3_scale(splat_float4(camera.right), u),
                                                       v3_scale(splat_float4(camera.up), v)));
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
    ray.origin = camera_eye(camera);
    ray.dir = v3_normalize(through_pixel);
#ifdef FGR_EFFECT_DEPTH_OF_FIELD
    /* through_pixel has unit length along `forward`, so the focus plane is at
     * eye + through_pixel * focus_distance. */
    const vec3 focus = v3_mad(ray.origin, through_pixel, fgr_real(param_focus_distance));
    ray.origin = v3_add(ray.origin,
                        v3_add(v3_scale(splat_float4(camera.right), s.lens_x * param_aperture),
                               v3_scale(splat_float4(camera.up), s.lens_y * param_aperture)));
    ray.dir = v3_normalize(v3_sub(focus, ray.origin));
#endif
    return ray;
}

/* The arguments every render mode's entry point `fgr_render` starts with, in this order (the host
 * sets them in host/src/renderer.cpp; a mode's own arguments follow from index 6):
 *   planes      the output: plane p of the image at planes + p * plane_size, tile-major
 *   plane_size  floats per plane (whole tiles)
 *   tile_count  tiles in the image; the global size is rounded up past it
 *   camera      the view
 *   sample      which sample of each pixel this launch renders (0, 1, 2, ...)
 *   PARAMS      the scene's parameter buffer */
#define FGR_RENDER_ARGS                                                                        \
    __global float *planes, int plane_size, int tile_count, camera_frame camera, int sample, \
        PARAMS

/* The pixels of one tile, one per lane. */
typedef struct tile_pixels {
    real px, py;  /* each lane's pixel, in the whole image */
    mask inside;  /* lanes past the region's edge (partial tiles) start inactive and cost no steps */
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
                    (pixels.py < (float)(camera.region_y + camera.region_height));
    return pixels;
}

/* Adds `value` to plane `plane` of the tile from sample 1 on (sample 0 writes it): samples
 * accumulate in the planes and the host divides by their count. */
inline void accumulate_plane(real value, int sample, int tile, __global float* plane) {
    if (sample > 0) value += fgr_load(tile, plane);
    fgr_store(value, tile, plane);
}
