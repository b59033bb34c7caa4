/* fgr kernel library: the entry points.
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
    int width;
    int height;
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

/* Primary ray of sample `sample` through pixel (px, py): jittered in the pixel for anti-aliasing
 * and, with depth of field, from a point on the lens (radius `aperture`) towards the point of
 * the pixel's ray at the focus distance, which therefore stays sharp. */
inline vec3 primary_direction(camera_frame camera, real px, real py, camera_sample s) {
    const float aspect = (float)camera.height / (float)camera.width;
    const real u = (2.0f * (px + s.pixel_x) / (float)camera.width - 1.0f) * camera.tan_half_fov;
    const real v = (1.0f - 2.0f * (py + s.pixel_y) / (float)camera.height) * camera.tan_half_fov *
                   aspect;
    return v3_add(splat_float4(camera.forward), v3_add(v3_scale(splat_float4(camera.right), u),
                                                       v3_scale(splat_float4(camera.up), v)));
}

/* Renders sample `sample` of every pixel of the tile. Sample 0 writes the planes; later samples
 * add to them (the host divides by the sample count), and only sample 0 writes depth (and, with
 * FGR_STATS, the step count and out-of-steps planes 4 and 5). */
__kernel void fgr_render(__global float* planes, int plane_size, int tile_count,
                         camera_frame camera, int sample, PARAMS, __constant const float* lights,
                         int light_count) {
    const int tile = get_global_id(0);
    /* The host rounds the global size up to whole work-groups. */
    if (tile >= tile_count) return;
    const int tiles_x = (camera.width + FGR_TILE_W - 1) / FGR_TILE_W;
    const real px = (float)((tile % tiles_x) * FGR_TILE_W) + FGR_LANE_X;
    const real py = (float)((tile / tiles_x) * FGR_TILE_H) + FGR_LANE_Y;
    /* Lanes past the image edge (partial tiles) start inactive and cost no steps. */
    const mask inside = (px < (float)camera.width) & (py < (float)camera.height);

    const camera_sample jitter = sample_camera(px, py, sample);
    vec3 through_pixel = primary_direction(camera, px, py, jitter);
    vec3 eye = camera_eye(camera);
    vec3 dir = v3_normalize(through_pixel);
#ifdef FGR_EFFECT_DEPTH_OF_FIELD
    /* through_pixel has unit length along `forward`, so the focus plane is at
     * eye + through_pixel * focus_distance. */
    vec3 focus = v3_mad(eye, through_pixel, fgr_real(param_focus_distance));
    eye = v3_add(eye, v3_add(v3_scale(splat_float4(camera.right), jitter.lens_x * param_aperture),
                             v3_scale(splat_float4(camera.up), jitter.lens_y * param_aperture)));
    dir = v3_normalize(v3_sub(focus, eye));
#endif

    const march_limits limits = scene_march_limits(camera.pixel_angle, PARAMS_PASS);
    march_result hit = march_rays(eye, dir, inside, limits, PARAMS_PASS);

    vec3 colour = background(dir);
    real depth = fgr_real(-1.0f);
    if (fgr_any(hit.hit)) {
        vec3 p = v3_mad(eye, dir, hit.t);
        real eps = fmax(hit.t * camera.pixel_angle * param_normal_epsilon, FGR_MIN_LENGTH);
        vec3 n = estimate_normal(p, eps, PARAMS_PASS);
        vec3 lit = shade_surface(p, n, dir, eps, hit.steps, hit.t, hit.hit, 1, limits, lights,
                                 light_count, PARAMS_PASS);
#ifdef FGR_EFFECT_REFRACTION
        lit = add_refraction(lit, p, n, dir, eps, hit.t, hit.hit, limits, lights, light_count,
                             PARAMS_PASS);
#endif
#ifdef FGR_EFFECT_REFLECTIONS
        lit = add_reflection(lit, p, n, dir, eps, hit.t, hit.hit, limits, lights, light_count,
                             PARAMS_PASS);
#endif
        colour = v3_select(colour, lit, hit.hit);
        depth = select(depth, hit.t, hit.hit);
    }
#ifdef FGR_EFFECT_GLOW
    colour = apply_glow(colour, hit.closest, !hit.hit, PARAMS_PASS);
#endif
#ifdef FGR_EFFECT_FOG
    colour = apply_fog(colour, hit.t, hit.hit, limits.max_distance, PARAMS_PASS);
#endif
    if (sample > 0) {
        colour = v3_add(colour, v3(fgr_load(tile, planes), fgr_load(tile, planes + plane_size),
                                   fgr_load(tile, planes + 2 * plane_size)));
    }
    fgr_store(colour.x, tile, planes);
    fgr_store(colour.y, tile, planes + plane_size);
    fgr_store(colour.z, tile, planes + 2 * plane_size);
    if (sample == 0) fgr_store(depth, tile, planes + 3 * plane_size);
#ifdef FGR_STATS
    /* The work behind each pixel, for `fgr render --stats`: the primary march's DE evaluations
     * (steps), and whether the ray ran out of steps before it hit or left the scene. */
    if (sample == 0) {
        mask exhausted = inside & !hit.hit & (hit.steps >= limits.max_steps) &
                         (hit.t <= limits.max_distance);
        fgr_store(convert_real(hit.steps), tile, planes + 4 * plane_size);
        fgr_store(select(fgr_real(0.0f), fgr_real(1.0f), exhausted), tile,
                  planes + 5 * plane_size);
    }
#endif
}

/* A probe's points: planes x, y, z of floats, then x, y, z of what those miss of the host's double
 * points, which double lanes add back (float lanes cannot use them). */
inline vec3 load_probe_point(__global const float* points, int plane_size, int packet) {
    vec3 p = v3(fgr_load(packet, points), fgr_load(packet, points + plane_size),
                fgr_load(packet, points + 2 * plane_size));
#ifdef FGR_DOUBLE
    p = v3_add(p, v3(fgr_load(packet, points + 3 * plane_size),
                     fgr_load(packet, points + 4 * plane_size),
                     fgr_load(packet, points + 5 * plane_size)));
#endif
    return p;
}

/* Evaluates the scene's DE at `count` points (see load_probe_point; padded to whole packets):
 * used by tests to compare the kernel's DE with a host implementation, and by tools that need the
 * distance at a point (e.g. camera speed). */
__kernel void fgr_probe_de(__global const float* points, int plane_size, int packet_count,
                           __global float* out, PARAMS) {
    const int packet = get_global_id(0);
    if (packet >= packet_count) return;
    vec3 p = load_probe_point(points, plane_size, packet);
    fgr_store(scene_de(p, PARAMS_PASS), packet, out);
}

/* The surface normal the shading uses at each point (planes x, y, z in and out), with stencil
 * size eps: lets tests check normals are finite and unit length wherever rays can hit. */
__kernel void fgr_probe_normal(__global const float* points, int plane_size, int packet_count,
                               __global float* out, PARAMS, float eps) {
    const int packet = get_global_id(0);
    if (packet >= packet_count) return;
    vec3 p = load_probe_point(points, plane_size, packet);
    vec3 n = estimate_normal(p, fgr_real(eps), PARAMS_PASS);
    fgr_store(n.x, packet, out);
    fgr_store(n.y, packet, out + plane_size);
    fgr_store(n.z, packet, out + 2 * plane_size);
}
