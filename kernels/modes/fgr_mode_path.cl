// SPDX-License-Identifier: Apache-2.0
/* fgr render mode "path": unbiased Monte Carlo path tracing of the scene's DE surface.
 *
 * Each launch adds one sample to every pixel: a camera ray (jittered in the pixel and, with depth
 * of field, on the lens) is marched to the surface; there the scene's material (scene_material, by
 * default a diffuse surface of the scene's colour) scatters it by BSDF sampling, bounce after
 * bounce, until it leaves the scene into the environment, is absorbed by Russian roulette or hits
 * the bounce cap. At every diffuse or glossy vertex one light is also sampled (next-event
 * estimation): the environment by its importance (fgr_environment.cl), a sun disc uniformly in
 * its cone, a point light at its position; a shadow ray decides whether it is seen. Both
 * strategies can reach the environment and sun discs, so their contributions are weighted by the
 * power heuristic (Veach 1997, multiple importance sampling): a sun of any size converges, from a
 * point-like one (light sampling wins) to a broad one (BSDF sampling wins). The sample generator
 * (fgr_sampler.cl) is indexed by dimension, so every decision draws its own stratified numbers.

 *
 * Arguments (FGR_PATH_ARG_*, shared/fgr_layout_arguments.h): those every mode takes (planes ..
 * has_hints, see fgr_camera.cl), then the lights (the scene's and the sky's sun,
 * FGR_PATH_LIGHT_FLOATS each, shared/fgr_layout_lights.h), the settings (path_settings,
 * shared/fgr_layout_path.h), and the environment (ENVIRONMENT, fgr_environment.cl).
 *
 * Planes (FGR_PATH_*_PLANE, shared/fgr_layout_planes.h): radiance (summed over samples), depth
 * of the first hit (sample 0), then the auxiliary outputs summed over samples: albedo of the
 * first hit, its normal, alpha (1 where the camera ray met the surface), the radiance of the
 * odd-numbered samples (accumulate_odd_half), and the per-pixel sample limit the kernel reads
 * (sample_wanted, adaptive sampling); with FGR_STATS the DE
 * evaluations each lane took part in and those its packet made (for lane utilisation), summed
 * over samples; with FGR_AOVS (a still that writes alpha) then the radiance of the samples whose
 * camera ray met the surface: the foreground without the environment seen past it, for straight
 * or premultiplied alpha. */

#ifndef FGR_SCENE_HAS_MATERIAL
/* A scene without its own materials is diffuse, coloured by scene_colour. */
inline material scene_material(vec3 p, PARAMS) {
    return diffuse_material(scene_colour(p, PARAMS_PASS));
}
#endif

/* The material where `hit` met the surface at p: the scene's, or for IFS scenes a diffuse one of
 * the colour the trace found. */
inline material surface_material(march_result hit, vec3 p, PARAMS) {
#ifdef FGR_GEOMETRY_IFS
    (void)p;
    (void)fgr_params;
    return diffuse_material(hit.albedo);
#else
    (void)hit;
    return scene_material(p, PARAMS_PASS);
#endif
}

/* The power heuristic with exponent 2 for one sample of each strategy: the weight of the strategy
 * with pdf `a` when the other has pdf `b`. */
inline real power_heuristic(real a, real b) {
    const real a2 = a * a, b2 = b * b;
    return select(a2 / (a2 + b2), fgr_real(0.0f), a2 + b2 <= 0.0f);
}

/* The environment as a light: sampled by its importance (fgr_environment.cl), or uniformly over
 * the sphere when that is switched off (to show what importance sampling buys). */
inline vec3 environment_light_sample(real u1, real u2, path_settings settings, ENVIRONMENT,
                                     real* pdf) {
    if (settings.flags & FGR_PATH_ENVIRONMENT_IS) {
        return environment_sample(u1, u2, ENVIRONMENT_PASS, pdf);
    }
    const real z = 1.0f - 2.0f * u1;
    const real r = sqrt(fmax(1.0f - z * z, 0.0f));
    const real phi = 6.28318530717958647692f * u2;
    *pdf = fgr_real(1.0f / (4.0f * 3.14159265358979323846f));
    return v3(r * fgr_cos(phi), r * fgr_sin(phi), z);
}

inline real environment_light_pdf(vec3 dir, path_settings settings, ENVIRONMENT) {
    if (settings.flags & FGR_PATH_ENVIRONMENT_IS) return environment_pdf(dir, ENVIRONMENT_PASS);
    return fgr_real(1.0f / (4.0f * 3.14159265358979323846f));
}

/* Unit direction uniformly inside the cone of cosine cos_max around axis (a sun disc). */
inline vec3 sample_cone(vec3 axis, real cos_max, real u1, real u2) {
    const real cos_theta = 1.0f - u1 * (1.0f - cos_max);
    const real sin_theta = sqrt(fmax(1.0f - cos_theta * cos_theta, 0.0f));
    const real phi = 6.28318530717958647692f * u2;
    return bsdf_to_world(bsdf_frame_of(axis),
                         v3(sin_theta * fgr_cos(phi), sin_theta * fgr_sin(phi), cos_theta));
}

/* Solid-angle pdf of sample_cone. */
inline real cone_pdf(real cos_max) { return 1.0f / (6.28318530717958647692f * (1.0f - cos_max)); }

/* The weight of radiance a BSDF-sampled ray found on a light that light sampling also reaches:
 * `light_sampled` lanes left a vertex where light sampling ran (not a camera ray, not a mirror
 * bounce); with MIS they take the power heuristic's share, without it none (light sampling
 * counted that light in full), and the other lanes count it in full. */
inline real escaped_weight(mask light_sampled, bool mis, real bsdf_pdf, real light_pdf) {
    const real shared = mis ? power_heuristic(bsdf_pdf, light_pdf) : fgr_real(0.0f);
    return select(fgr_real(1.0f), shared, light_sampled);
}

/* Radiance arriving along `dir` from the environment and the sun discs, for a ray that left the
 * scene, weighted as escaped_weight says (bsdf_pdf: the BSDF's pdf of dir at the last vertex). */
inline vec3 escaped_radiance(vec3 dir, mask light_sampled, bool mis, real bsdf_pdf,
                             __constant const float* lights, path_settings settings, ENVIRONMENT) {
    vec3 radiance = environment_radiance(dir, ENVIRONMENT_PASS);
    const real env_pdf =
        settings.environment_pick * environment_light_pdf(dir, settings, ENVIRONMENT_PASS);
    radiance = v3_scale(radiance, escaped_weight(light_sampled, mis, bsdf_pdf, env_pdf));
    float picked_before = settings.environment_pick;
    for (int i = 0; i < settings.light_count; ++i) {
        __constant const float* light = lights + i * FGR_PATH_LIGHT_FLOATS;
        const float pick = light[FGR_PATH_LIGHT_PICK_UNTIL] - picked_before;
        picked_before = light[FGR_PATH_LIGHT_PICK_UNTIL];
        const float cos_max = light[FGR_PATH_LIGHT_COS_MAX];
        if ((int)light[FGR_PATH_LIGHT_KIND] == FGR_LIGHT_KIND_POINT || cos_max >= 1.0f) {
            continue; /* delta lights */
        }
        const mask in_disc = v3_dot(dir, light_vec3(light, FGR_PATH_LIGHT_VECTOR)) >= cos_max;
        if (!fgr_any(in_disc)) continue;
        const real w =
            escaped_weight(light_sampled, mis, bsdf_pdf, fgr_real(pick * cone_pdf(cos_max)));
        const vec3 disc = v3_scale(light_vec3(light, FGR_PATH_LIGHT_RADIANCE), w);
        radiance = v3_add(radiance, v3_select(v3_splat(0.0f, 0.0f, 0.0f), disc, in_disc));
    }
    return radiance;
}

/* One light sample for next-event estimation at p: a direction, the radiance arriving along it
 * if nothing blocks it, its pdf (solid angle, including the pick; 0 for delta lights, which MIS
 * leaves alone) and how far a shadow ray must look. */
typedef struct light_sample {
    vec3 dir;
    vec3 radiance; /* already divided by the pick probability for delta lights */
    real pdf;      /* solid-angle pdf, pick included; 0 marks a delta light */
    real reach;
} light_sample;

inline light_sample sample_light(vec3 p, real u_pick, real u1, real u2,
                                 __constant const float* lights, path_settings settings,
                                 float max_distance, ENVIRONMENT) {
    light_sample s;
    /* The environment, when it is picked. */
    real env_pdf = fgr_real(0.0f);
    s.dir = environment_light_sample(u1, u2, settings, ENVIRONMENT_PASS, &env_pdf);
    s.radiance = environment_radiance(s.dir, ENVIRONMENT_PASS);
    s.pdf = settings.environment_pick * env_pdf;
    s.reach = fgr_real(max_distance);
    float picked_before = settings.environment_pick;
    for (int i = 0; i < settings.light_count; ++i) {
        __constant const float* light = lights + i * FGR_PATH_LIGHT_FLOATS;
        const float pick = light[FGR_PATH_LIGHT_PICK_UNTIL] - picked_before;
        const mask chosen = (u_pick >= picked_before) & (u_pick < light[FGR_PATH_LIGHT_PICK_UNTIL]);
        picked_before = light[FGR_PATH_LIGHT_PICK_UNTIL];
        if (!fgr_any(chosen)) continue;
        const vec3 vector = light_vec3(light, FGR_PATH_LIGHT_VECTOR);
        const vec3 colour = light_vec3(light, FGR_PATH_LIGHT_RADIANCE);
        const float cos_max = light[FGR_PATH_LIGHT_COS_MAX];
        vec3 dir;
        vec3 radiance;
        real pdf, reach;
        if ((int)light[FGR_PATH_LIGHT_KIND] == FGR_LIGHT_KIND_POINT) {
            const vec3 to_light = v3_sub(vector, p);
            const real dist2 = fmax(v3_length2(to_light), FGR_MIN_LENGTH * FGR_MIN_LENGTH);
            dir = v3_scale(to_light, rsqrt(dist2));
            radiance = v3_scale(colour, 1.0f / (pick * dist2));
            pdf = fgr_real(0.0f);
            reach = fmin(sqrt(dist2), max_distance);
        } else if (cos_max >= 1.0f) {
            dir = vector;
            radiance = v3_scale(colour, 1.0f / pick);
            pdf = fgr_real(0.0f);
            reach = fgr_real(max_distance);
        } else {
            dir = sample_cone(vector, fgr_real(cos_max), u1, u2);
            radiance = colour;
            pdf = fgr_real(pick * cone_pdf(cos_max));
            reach = fgr_real(max_distance);
        }
        s.dir = v3_select(s.dir, dir, chosen);
        s.radiance = v3_select(s.radiance, radiance, chosen);
        s.pdf = select(s.pdf, pdf, chosen);
        s.reach = select(s.reach, reach, chosen);
    }
    return s;
}

/* Adaptive sampling: the lanes whose pixel takes sample `sample`, those whose index is below the
 * pixel's limit in FGR_PATH_SAMPLE_LIMIT_PLANE (the host's; lanes it leaves out trace nothing and
 * add nothing to the sums). */
inline mask sample_wanted(int sample, int tile, __global const float* planes, int plane_size) {
    return fgr_load(tile, planes + FGR_PATH_SAMPLE_LIMIT_PLANE * plane_size) > (float)sample;
}

/* The radiance of the odd-numbered samples, summed apart from the others: the two halves' means
 * differ by about the pixel's noise, which gives the host each pixel's variance (two
 * half-buffers, as Rousselle et al. 2012 and Cycles' adaptive sampling use). */
inline void accumulate_odd_half(vec3 radiance, int sample, int tile, __global float* planes,
                                int plane_size) {
    const real odd = fgr_real((float)(sample & 1));
    __global float* odd_planes = planes + FGR_PATH_ODD_RADIANCE_PLANE * plane_size;
    accumulate_plane(radiance.x * odd, sample, tile, odd_planes);
    accumulate_plane(radiance.y * odd, sample, tile, odd_planes + plane_size);
    accumulate_plane(radiance.z * odd, sample, tile, odd_planes + 2 * plane_size);
}

__kernel void fgr_render(FGR_RENDER_ARGS, __constant const float* lights, path_settings settings,
                         ENVIRONMENT) {
    const int tile = get_global_id(0);
    if (tile >= tile_count) return;
    const tile_pixels pixels = pixels_of_tile(tile, camera);
    mask active = pixels.inside & sample_wanted(sample, tile, planes, plane_size);

    /* Stratified: sample `sample` of one scrambled Sobol sequence per pixel. Independent (to
     * measure what stratification buys): the first point of a sequence scrambled anew for every
     * sample, which is a uniformly random point. */
    const bool independent = (settings.flags & FGR_PATH_INDEPENDENT) != 0;
    sampler rng =
        sampler_start(pixels.px, pixels.py, independent ? 0 : sample,
                      independent ? settings.seed + (uint)sample * 0x9e3779b9u : settings.seed);
    const real2 in_pixel = sampler_next_2d(&rng);
    const real2 on_lens = sampler_next_2d(&rng);
    camera_sample jitter;
    jitter.pixel_x = in_pixel.x;
    jitter.pixel_y = in_pixel.y;
    /* Uniform on the unit disc: radius sqrt(u), angle 2 pi v. */
    const real lens_radius = sqrt(on_lens.x), lens_angle = 6.28318530717958647692f * on_lens.y;
    jitter.lens_x = lens_radius * fgr_cos(lens_angle);
    jitter.lens_y = lens_radius * fgr_sin(lens_angle);
    const camera_ray ray = camera_ray_through(camera, pixels.px, pixels.py, jitter, PARAMS_PASS);

    const march_limits limits = scene_march_limits(camera.pixel_angle, PARAMS_PASS);
    const bool light_sampling = (settings.flags & FGR_PATH_LIGHT_SAMPLING) != 0;
    const bool mis = (settings.flags & FGR_PATH_MIS) != 0;

    vec3 origin = ray.origin, dir = ray.dir;
    vec3 radiance = v3_splat(0.0f, 0.0f, 0.0f);
    vec3 throughput = v3_splat(1.0f, 1.0f, 1.0f);
    /* How far the camera saw the surface: the distance whose pixel footprint sets how finely
     * every later vertex of the path resolves the surface (0 before the first hit). A bounce
     * resolves the surface no finer than its pixel shows it, and no coarser either: a footprint
     * that kept growing with the path's length would thicken the surface bounce after bounce
     * until crevices closed around the path and trapped its light. */
    real seen_at = fgr_real(0.0f);
    /* Whether light sampling also covered the last bounce's BSDF sample, and that sample's pdf. */
    mask light_sampled = (mask)(0);
    real last_pdf = fgr_real(0.0f);
    /* The first hit, for depth and the auxiliary planes. */
    real depth = fgr_real(-1.0f);
    vec3 first_albedo = v3_splat(0.0f, 0.0f, 0.0f), first_normal = v3_splat(0.0f, 0.0f, 0.0f);
    real alpha = fgr_real(0.0f);
#ifdef FGR_STATS
    mask lane_steps = (mask)(0);
    int packet_steps = 0;
#endif

    mask hint_evaluations = (mask)(0); /* counted with the stats */
    const real camera_start =
        camera_ray_start(march_starts, march_hints, has_hints, tile, pixels, camera, origin, dir,
                         active, limits, &hint_evaluations, PARAMS_PASS);
    for (int bounce = 0; fgr_any(active); ++bounce) {
        const march_result hit =
            bounce == 0 ? march_camera_rays(origin, dir, active, camera_start, limits, PARAMS_PASS)
                        : march_rays_departing(origin, dir, active, seen_at,
                                               fgr_real(limits.max_distance), limits, PARAMS_PASS);
#ifdef FGR_STATS
        lane_steps += hit.steps + (bounce == 0 ? hint_evaluations : (mask)(0));
        packet_steps += fgr_lanes_max(hit.steps);
#endif
        const mask escaped = active & !hit.hit;
        if (fgr_any(escaped)) {
            const vec3 arriving = escaped_radiance(dir, light_sampled, mis, last_pdf, lights,
                                                   settings, ENVIRONMENT_PASS);
            radiance = v3_select(radiance, v3_add(radiance, v3_mul(throughput, arriving)), escaped);
        }
        active &= hit.hit;
        if (!fgr_any(active)) break;

        const vec3 p = v3_mad(origin, dir, hit.t);
        if (bounce == 0) seen_at = hit.t;
        const real path_length = seen_at;
        const real eps =
            fmax(path_length * camera.pixel_angle * param_normal_epsilon, FGR_MIN_LENGTH);
        vec3 n = surface_normal(hit, p, eps, PARAMS_PASS);
#if defined(FGR_STATS) && !defined(FGR_GEOMETRY_IFS)
        lane_steps += select((mask)(0), (mask)(4), active);
        packet_steps += 4;
#endif
        const vec3 wo = v3_neg(dir);
        /* Where the DE's gradient vanishes over the stencil (a point midway between two walls
         * of a slot), there is no normal to estimate: the surface faces the ray. */
        n = v3_select(n, wo, !(v3_length2(n) > 0.5f));
        /* A ray that meets a surface from behind its normal (a camera ray inside a sliver it
         * stepped into, a bounce grazing a thickened edge) sees the side it came from. */
        n = v3_select(n, v3_neg(n), active & (v3_dot(n, wo) < 0.0f));
        const material m = surface_material(hit, p, PARAMS_PASS);
        radiance = v3_select(radiance, v3_add(radiance, v3_mul(throughput, m.emission)), active);
        if (bounce == 0) {
            depth = select(depth, hit.t, active);
            first_albedo =
                v3_select(first_albedo,
                          v3_min(v3_add(m.albedo, m.specular), v3_splat(1.0f, 1.0f, 1.0f)), active);
            first_normal = v3_select(first_normal, n, active);
            alpha = select(alpha, fgr_real(1.0f), active);
        }
        if (bounce >= settings.max_bounces) break;

        const vec3 leave = leave_surface(p, n, path_length, limits);
        const real2 light_u = sampler_next_2d(&rng);
        const real light_pick = sampler_next_1d(&rng);
        const real2 bsdf_u = sampler_next_2d(&rng);
        const real lobe_u = sampler_next_1d(&rng);
        const real roulette_u = sampler_next_1d(&rng);

        /* Next-event estimation, where the surface is not a perfect mirror there. */
        if (light_sampling) {
            const light_sample light =
                sample_light(p, light_pick, light_u.x, light_u.y, lights, settings,
                             limits.max_distance, ENVIRONMENT_PASS);
            const vec3 f = bsdf_eval(m, n, wo, light.dir);
            mask lit = active & (v3_dot(light.dir, n) > 0.0f) & (fmax(fmax(f.x, f.y), f.z) > 0.0f) &
                       (fmax(fmax(light.radiance.x, light.radiance.y), light.radiance.z) > 0.0f);
            if (fgr_any(lit)) {
                const march_result shadow = march_rays_occluded(
                    leave, light.dir, lit, path_length, light.reach, limits, 1, PARAMS_PASS);
#ifdef FGR_STATS
                lane_steps += shadow.steps;
                packet_steps += fgr_lanes_max(shadow.steps);
#endif
                lit &= !shadow.hit;
                const mask delta_light = light.pdf <= 0.0f;
                const real w =
                    select(mis ? power_heuristic(light.pdf, bsdf_pdf(m, n, wo, light.dir))
                               : fgr_real(1.0f),
                           fgr_real(1.0f), delta_light);
                const real scale = select(w / light.pdf, fgr_real(1.0f), delta_light);
                const vec3 contribution = v3_scale(v3_mul(f, light.radiance), scale);
                radiance =
                    v3_select(radiance, v3_add(radiance, v3_mul(throughput, contribution)), lit);
            }
        }

        /* Continue the path by sampling the BSDF. */
        const bsdf_sample scattered = bsdf_sample_direction(m, n, wo, lobe_u, bsdf_u.x, bsdf_u.y);
        active &= scattered.valid;
        throughput = v3_mul(throughput, scattered.weight);
        light_sampled = light_sampling ? !scattered.delta : (mask)(0);
        last_pdf = scattered.pdf;

        /* Russian roulette: a path continues with probability q (its throughput's largest
         * component, at most 1) and is weighted by 1/q when it does: unbiased. */
        if (bounce + 1 >= settings.roulette_depth) {
            const real q = fmin(fmax(fmax(throughput.x, throughput.y), throughput.z), 1.0f);
            const mask survives = roulette_u < q;
            throughput = v3_scale(throughput, select(fgr_real(0.0f), 1.0f / q, survives));
            active &= survives;
        }
        origin = leave;
        dir = scattered.wi;
    }

    if (settings.radiance_clamp > 0.0f) {
        const real largest = fmax(fmax(radiance.x, radiance.y), radiance.z);
        const real scale = select(fgr_real(1.0f), settings.radiance_clamp / largest,
                                  largest > settings.radiance_clamp);
        radiance = v3_scale(radiance, scale);
    }
    __global float* colour_planes = planes + FGR_COLOUR_PLANE * plane_size;
    accumulate_plane(radiance.x, sample, tile, colour_planes);
    accumulate_plane(radiance.y, sample, tile, colour_planes + plane_size);
    accumulate_plane(radiance.z, sample, tile, colour_planes + 2 * plane_size);
    accumulate_odd_half(radiance, sample, tile, planes, plane_size);
    if (sample == 0) fgr_store(depth, tile, planes + FGR_DEPTH_PLANE * plane_size);
    __global float* albedo_planes = planes + FGR_PATH_ALBEDO_PLANE * plane_size;
    accumulate_plane(first_albedo.x, sample, tile, albedo_planes);
    accumulate_plane(first_albedo.y, sample, tile, albedo_planes + plane_size);
    accumulate_plane(first_albedo.z, sample, tile, albedo_planes + 2 * plane_size);
    __global float* normal_planes = planes + FGR_PATH_NORMAL_PLANE * plane_size;
    accumulate_plane(first_normal.x, sample, tile, normal_planes);
    accumulate_plane(first_normal.y, sample, tile, normal_planes + plane_size);
    accumulate_plane(first_normal.z, sample, tile, normal_planes + 2 * plane_size);
    accumulate_plane(alpha, sample, tile, planes + FGR_PATH_ALPHA_PLANE * plane_size);
#ifdef FGR_STATS
    accumulate_plane(convert_real(lane_steps), sample, tile,
                     planes + FGR_PATH_LANE_STEPS_PLANE * plane_size);
    accumulate_plane(fgr_real((float)packet_steps), sample, tile,
                     planes + FGR_PATH_PACKET_STEPS_PLANE * plane_size);
#endif
#ifdef FGR_AOVS
    /* alpha is 1 or 0 for one sample: the whole radiance of a sample whose camera ray hit. */
    __global float* foreground = planes + FGR_PATH_FOREGROUND_PLANE(FGR_STATS_ON) * plane_size;
    accumulate_plane(radiance.x * alpha, sample, tile, foreground);
    accumulate_plane(radiance.y * alpha, sample, tile, foreground + plane_size);
    accumulate_plane(radiance.z * alpha, sample, tile, foreground + 2 * plane_size);
#endif
}
