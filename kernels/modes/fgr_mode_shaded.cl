// SPDX-License-Identifier: Apache-2.0
/* fgr render mode "shaded": Blinn-Phong with the scene's lights plus the effects it asks for
 * (shadows, occlusion, reflections, refraction, glow, fog, depth of field), one primary ray per
 * pixel and sample. The fast mode, and the one the viewer previews with.
 *
 * Arguments (FGR_SHADED_ARG_*, shared/fgr_layout_arguments.h): those every mode takes (planes ..
 * has_hints, see fgr_camera.cl), then the scene's lights (FGR_LIGHT_FLOATS floats each,
 * shared/fgr_layout_lights.h) and their count.
 *
 * Planes (FGR_SHADED_*, shared/fgr_layout_planes.h): colour and depth; with FGR_STATS the work
 * behind each pixel; for IFS scenes the level each pixel's hit reached; with FGR_AOVS (a still
 * that writes alpha or layers) the layers. */

#ifdef FGR_AOVS
/* The layers, summed over samples like the colour: the first hit's albedo and shading normal,
 * coverage (1 for a sample whose camera ray met the surface), and the colour of those samples
 * alone (the foreground without the background, for straight or premultiplied alpha). Zero for a
 * sample that missed, as in the path mode. */
inline void store_aovs(vec3 albedo, vec3 normal, mask hit, vec3 colour, int sample, int tile,
                       __global float* planes, int plane_size) {
    const vec3 none = v3_splat(0.0f, 0.0f, 0.0f);
    const vec3 foreground = v3_select(none, colour, hit);
    const real coverage = select(fgr_real(0.0f), fgr_real(1.0f), hit);
    __global float* aov = planes + FGR_SHADED_AOV_PLANE(FGR_STATS_ON, FGR_IFS_ON) * plane_size;
    __global float* albedo_planes = aov + FGR_SHADED_AOV_ALBEDO * plane_size;
    accumulate_plane(albedo.x, sample, tile, albedo_planes);
    accumulate_plane(albedo.y, sample, tile, albedo_planes + plane_size);
    accumulate_plane(albedo.z, sample, tile, albedo_planes + 2 * plane_size);
    __global float* normal_planes = aov + FGR_SHADED_AOV_NORMAL * plane_size;
    accumulate_plane(normal.x, sample, tile, normal_planes);
    accumulate_plane(normal.y, sample, tile, normal_planes + plane_size);
    accumulate_plane(normal.z, sample, tile, normal_planes + 2 * plane_size);
    accumulate_plane(coverage, sample, tile, aov + FGR_SHADED_AOV_COVERAGE * plane_size);
    __global float* foreground_planes = aov + FGR_SHADED_AOV_FOREGROUND * plane_size;
    accumulate_plane(foreground.x, sample, tile, foreground_planes);
    accumulate_plane(foreground.y, sample, tile, foreground_planes + plane_size);
    accumulate_plane(foreground.z, sample, tile, foreground_planes + 2 * plane_size);
}
#endif

/* A tile's camera rays for this sample and where their march starts (the cone prepass and its
 * hints). */
typedef struct tile_rays {
    vec3 eye, dir;
    mask inside;
    real start;
    mask hint_evaluations; /* DE evaluations the hints took, per lane */
} tile_rays;

inline tile_rays camera_rays_of_tile(int tile, camera_frame camera, int sample,
                                     __global const float* march_starts,
                                     __global const float* march_hints, int has_hints,
                                     march_limits limits, PARAMS) {
    tile_rays rays;
    const tile_pixels pixels = pixels_of_tile(tile, camera);
    const camera_sample jitter = sample_camera(pixels.px, pixels.py, sample);
    const camera_ray ray = camera_ray_through(camera, pixels.px, pixels.py, jitter, PARAMS_PASS);
    rays.eye = ray.origin;
    rays.dir = ray.dir;
    rays.inside = pixels.inside;
    rays.hint_evaluations = (mask)(0);
    rays.start =
        camera_ray_start(march_starts, march_hints, has_hints, tile, pixels, camera, rays.eye,
                         rays.dir, rays.inside, limits, &rays.hint_evaluations, PARAMS_PASS);
    return rays;
}

/* Shades the tile's march and writes its planes (sample 0 writes them; later samples add to
 * them, and the host divides by the sample count; only sample 0 writes depth, and, with
 * FGR_STATS, the stats planes, and the IFS level plane). */
inline void shade_tile(int tile, tile_rays rays, march_result hit, camera_frame camera, int sample,
                       march_limits limits, __constant const float* lights, int light_count,
                       __global float* planes, int plane_size, PARAMS) {
    const vec3 eye = rays.eye, dir = rays.dir;
    const mask inside = rays.inside;
    hit.steps += rays.hint_evaluations;

    vec3 colour = background(dir);
    real depth = fgr_real(-1.0f);
    /* Shadow, reflection and refraction rays' DE evaluations: per lane, per packet. */
    mask secondary_steps[2] = {(mask)(0), (mask)(0)};
#ifdef FGR_AOVS
    vec3 first_albedo = v3_splat(0.0f, 0.0f, 0.0f), first_normal = first_albedo;
#endif
    if (fgr_any(hit.hit)) {
        vec3 p = v3_mad(eye, dir, hit.t);
        real eps = fmax(hit.t * camera.pixel_angle * param_normal_epsilon, FGR_MIN_LENGTH);
        vec3 n = surface_normal(hit, p, eps, PARAMS_PASS);
        const vec3 hit_albedo = surface_albedo(hit, p, PARAMS_PASS);
#ifdef FGR_AOVS
        first_albedo = v3_select(first_albedo, hit_albedo, hit.hit);
        first_normal = v3_select(first_normal, n, hit.hit);
#endif
        vec3 lit = shade_surface(p, n, hit_albedo, dir, eps, hit.steps, hit.t, hit.hit, 1, limits,
                                 lights, light_count, secondary_steps, PARAMS_PASS);
#ifdef FGR_EFFECT_REFRACTION
        lit = add_refraction(lit, p, n, dir, eps, hit.t, hit.hit, limits, lights, light_count,
                             secondary_steps, PARAMS_PASS);
#endif
#ifdef FGR_EFFECT_REFLECTIONS
        lit = add_reflection(lit, p, n, dir, eps, hit.t, hit.hit, limits, lights, light_count,
                             secondary_steps, PARAMS_PASS);
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
    /* Pixels the projection does not cover (outside a fisheye's circle) are black. */
    colour = v3_select(v3_splat(0.0f, 0.0f, 0.0f), colour, inside);
    __global float* colour_planes = planes + FGR_COLOUR_PLANE * plane_size;
    accumulate_plane(colour.x, sample, tile, colour_planes);
    accumulate_plane(colour.y, sample, tile, colour_planes + plane_size);
    accumulate_plane(colour.z, sample, tile, colour_planes + 2 * plane_size);
    if (sample == 0) fgr_store(depth, tile, planes + FGR_DEPTH_PLANE * plane_size);
#ifdef FGR_AOVS
    store_aovs(first_albedo, first_normal, hit.hit, colour, sample, tile, planes, plane_size);
#endif
#ifdef FGR_GEOMETRY_IFS
    if (sample == 0) {
        fgr_store(convert_real(hit.leaf_depth), tile,
                  planes + FGR_SHADED_LEVEL_PLANE(FGR_STATS_ON) * plane_size);
    }
#endif
#ifdef FGR_STATS
    /* The work behind each pixel, for `fgr render --stats`: the primary march's DE evaluations
     * (steps), whether the ray ran out of steps before it hit or left the scene, and the DE
     * evaluations of the secondary rays its lane took part in. IFS scenes count nodes visited
     * as steps, and the most nodes the ray's heap held. */
    if (sample == 0) {
#ifdef FGR_GEOMETRY_IFS
        const int step_cap = limits.max_steps * FGR_IFS_NODES_PER_STEP;
        fgr_store(convert_real(hit.heap_peak), tile,
                  planes + FGR_SHADED_HEAP_PEAK_PLANE * plane_size);
#else
        const int step_cap = limits.max_steps;
        fgr_store(convert_real(secondary_steps[1]), tile,
                  planes + FGR_SHADED_SECONDARY_PACKET_STEPS_PLANE * plane_size);
#endif
        mask exhausted =
            inside & !hit.hit & (hit.steps >= step_cap) & (hit.t <= limits.max_distance);
        fgr_store(convert_real(hit.steps), tile, planes + FGR_SHADED_STEPS_PLANE * plane_size);
        fgr_store(select(fgr_real(0.0f), fgr_real(1.0f), exhausted), tile,
                  planes + FGR_SHADED_OUT_OF_STEPS_PLANE * plane_size);
        fgr_store(convert_real(secondary_steps[0]), tile,
                  planes + FGR_SHADED_SECONDARY_STEPS_PLANE * plane_size);
    }
#endif
}

/* Renders sample `sample` of every pixel of its tile, or with FGR_PAIRED_TILES of two tiles
 * side by side (2i and 2i + 1), whose camera rays march together (march_camera_ray_pair): the
 * host launches a work-item per tile or per pair. */
__kernel void fgr_render(FGR_RENDER_ARGS, __constant const float* lights, int light_count) {
    const march_limits limits = scene_march_limits(camera.pixel_angle, PARAMS_PASS);
#ifdef FGR_PAIRED_TILES
    const int tile = 2 * (int)get_global_id(0);
    if (tile >= tile_count) return;
    const int has_second = tile + 1 < tile_count;
    const tile_rays first = camera_rays_of_tile(tile, camera, sample, march_starts, march_hints,
                                                has_hints, limits, PARAMS_PASS);
    /* A last pair without its second tile marches the first's rays again, all lanes idle. */
    tile_rays second =
        camera_rays_of_tile(has_second ? tile + 1 : tile, camera, sample, march_starts, march_hints,
                            has_hints, limits, PARAMS_PASS);
    if (!has_second) second.inside = (mask)(0);
    march_result hit_first, hit_second;
    march_camera_ray_pair(first.eye, first.dir, first.inside, first.start, second.eye, second.dir,
                          second.inside, second.start, limits, &hit_first, &hit_second,
                          PARAMS_PASS);
    shade_tile(tile, first, hit_first, camera, sample, limits, lights, light_count, planes,
               plane_size, PARAMS_PASS);
    if (has_second) {
        shade_tile(tile + 1, second, hit_second, camera, sample, limits, lights, light_count,
                   planes, plane_size, PARAMS_PASS);
    }
#else
    const int tile = get_global_id(0);
    if (tile >= tile_count) return;
    const tile_rays rays = camera_rays_of_tile(tile, camera, sample, march_starts, march_hints,
                                               has_hints, limits, PARAMS_PASS);
    const march_result hit =
        march_camera_rays(rays.eye, rays.dir, rays.inside, rays.start, limits, PARAMS_PASS);
    shade_tile(tile, rays, hit, camera, sample, limits, lights, light_count, planes, plane_size,
               PARAMS_PASS);
#endif
}
