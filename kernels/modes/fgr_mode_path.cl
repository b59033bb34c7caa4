// SPDX-License-Identifier: Apache-2.0
/* fgr render mode "path": unbiased Monte Carlo path tracing of the scene's DE surface.
 *
 * Each sample of a pixel is a path: a camera ray (jittered in the pixel and, with depth of field,
 * on the lens) is marched to the surface; there the scene's material (scene_material, by
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
 * Two kernels trace the same paths: the regrouped one (the default, render_regrouped below), whose
 * launch traces settings.launch_samples samples of every pixel and keeps its lanes busy by
 * handing each lane the next path as soon as its last one ends; and the packet kernel
 * (render_packet_sample, FGR_PATH_REGROUP unset: `--no-regroup`, and IFS scenes), whose launch
 * adds one sample to every pixel, each lane tracing its own pixel's path.
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
 * (sample_wanted, adaptive sampling: both kernels trace no sample of a pixel past its limit);
 * with FGR_STATS the DE evaluations the pixel's paths took (in whichever lane) and those the
 * packet made (for lane utilisation; the same in every lane of the tile), summed over samples;
 * with FGR_AOVS (a still that writes alpha) then the radiance of the samples whose camera ray
 * met the surface: the foreground without the environment seen past it, for straight or
 * premultiplied alpha. */

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

/* A camera ray's jitter from two uniform pairs: a point in the pixel, and one uniform on the lens's
 * unit disc (radius sqrt(u), angle 2 pi v). */
inline camera_sample camera_jitter(real2 in_pixel, real2 on_lens) {
    camera_sample jitter;
    jitter.pixel_x = in_pixel.x;
    jitter.pixel_y = in_pixel.y;
    const real lens_radius = sqrt(on_lens.x), lens_angle = 6.28318530717958647692f * on_lens.y;
    jitter.lens_x = lens_radius * fgr_cos(lens_angle);
    jitter.lens_y = lens_radius * fgr_sin(lens_angle);
    return jitter;
}

/* The power heuristic with exponent 2 for one sample of each strategy: the weight of the strategy
 * with pdf `a` when the other has pdf `b`. */
inline real power_heuristic(real a, real b) {
    const real a2 = a * a, b2 = b * b;
    return select(a2 / (a2 + b2), fgr_real(0.0f), a2 + b2 <= 0.0f);
}

/* The environment as a light: sampled by its importance (fgr_environment.cl), or uniformly over
 * the sphere when that is switched off (to show what importance sampling buys), with the radiance
 * along the direction drawn in *radiance. */
inline vec3 environment_light_sample(real u1, real u2, mask wanted, path_settings settings,
                                     ENVIRONMENT, real* pdf, vec3* radiance) {
    if (settings.flags & FGR_PATH_ENVIRONMENT_IS) {
        return environment_sample_radiance(u1, u2, wanted, ENVIRONMENT_PASS, pdf, radiance);
    }
    const real z = 1.0f - 2.0f * u1;
    const real r = sqrt(fmax(1.0f - z * z, 0.0f));
    const real phi = 6.28318530717958647692f * u2;
    *pdf = fgr_real(1.0f / (4.0f * 3.14159265358979323846f));
    const vec3 dir = v3(r * fgr_cos(phi), r * fgr_sin(phi), z);
    *radiance = environment_radiance(dir, wanted, ENVIRONMENT_PASS);
    return dir;
}

/* The environment's radiance along dir, and the pdf with which environment_light_sample draws
 * dir, from one lookup. */
inline vec3 environment_light_radiance(vec3 dir, mask wanted, path_settings settings, ENVIRONMENT,
                                       real* pdf) {
    if (settings.flags & FGR_PATH_ENVIRONMENT_IS) {
        return environment_radiance_pdf(dir, wanted, ENVIRONMENT_PASS, pdf);
    }
    *pdf = fgr_real(1.0f / (4.0f * 3.14159265358979323846f));
    return environment_radiance(dir, wanted, ENVIRONMENT_PASS);
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

/* What light sampling weighs its sources by at a shading point: the point, the frame of its
 * normal, wo in that frame and the material's lobes seen from wo. */
typedef struct shading_point {
    vec3 p;
    bsdf_frame frame;
    vec3 wo; /* in the frame */
    bsdf_lobes lobes;
} shading_point;

inline shading_point shading_point_of(vec3 p, material m, vec3 n, vec3 wo) {
    shading_point at;
    at.p = p;
    at.frame = bsdf_frame_of(n);
    at.wo = bsdf_to_local(at.frame, wo);
    at.lobes = bsdf_lobes_of(m, at.wo.z);
    return at;
}

/* f(wo, wi) max(n.wi, 0) and the BSDF's sampling pdf of wi at a shading point: bsdf_eval and
 * bsdf_pdf from one evaluation, with the frame and lobes the point already holds. */
inline vec3 bsdf_eval_at(const shading_point* at, vec3 wi, real* pdf) {
    vec3 f_cos;
    bsdf_eval_pdf_local(at->lobes, at->wo, bsdf_to_local(at->frame, wi), &f_cos, pdf);
    return f_cos;
}

/* A light's direction at p and the irradiance it gives a surface facing it there. */
inline vec3 light_irradiance(__constant const float* light, vec3 p, vec3* dir) {
    const vec3 vector = light_vec3(light, FGR_PATH_LIGHT_VECTOR);
    const vec3 colour = light_vec3(light, FGR_PATH_LIGHT_RADIANCE);
    const float cos_max = light[FGR_PATH_LIGHT_COS_MAX];
    if ((int)light[FGR_PATH_LIGHT_KIND] == FGR_LIGHT_KIND_POINT) {
        const vec3 to_light = v3_sub(vector, p);
        const real dist2 = fmax(v3_length2(to_light), FGR_MIN_LENGTH * FGR_MIN_LENGTH);
        *dir = v3_scale(to_light, rsqrt(dist2));
        return v3_scale(colour, 1.0f / dist2);
    }
    *dir = vector;
    /* A disc of radiance L gives L times its solid angle. */
    return cos_max >= 1.0f ? colour : v3_scale(colour, 6.28318530717958647692f * (1.0f - cos_max));
}

/* How much light sampling weighs a light at a shading point: the luminance of what it would
 * add there if nothing blocked it, E f(wo, wi) cos, with wi its direction (a disc's centre).
 * For a delta light that is exact: a light behind the surface, or one whose highlight the
 * surface does not show, takes no samples; a metal's highlight takes most. A disc adds a floor
 * of 1% of what it would give a white diffuse surface while any of it stands above the horizon,
 * so every direction it can light keeps a chance however f varies across it. */
inline real light_pick_weight(__constant const float* light, const shading_point* at) {
    vec3 dir;
    const vec3 irradiance = light_irradiance(light, at->p, &dir);
    real pdf;
    real weight = bsdf_luminance(v3_mul(irradiance, bsdf_eval_at(at, dir, &pdf)));
    const float cos_max = light[FGR_PATH_LIGHT_COS_MAX];
    if ((int)light[FGR_PATH_LIGHT_KIND] != FGR_LIGHT_KIND_POINT && cos_max < 1.0f) {
        const real sin_max = fgr_real(sqrt(fmax(1.0f - cos_max * cos_max, 0.0f)));
        const real above = fmax(v3_dot(dir, at->frame.n) + sin_max, 0.0f);
        weight =
            mad(0.01f * FGR_LANES(M_1_PI_F, M_1_PI) * bsdf_luminance(irradiance), above, weight);
    }
    return weight;
}

/* How much light sampling weighs the environment at a shading point: what the surface would
 * return of a uniform environment of the same mean luminance, that mean times the luminance of
 * its diffuse reflectance and of its glossy lobe's Fresnel at wo. */
inline real environment_pick_weight(path_settings settings, const shading_point* at) {
    const real reflectance =
        bsdf_luminance(at->lobes.kd) + bsdf_luminance(bsdf_fresnel(at->lobes, at->wo.z));
    return settings.environment_weight * reflectance;
}

/* The environment's weight at a shading point and all the lights', summed in the order
 * sample_light lays out their intervals, so that the last one ends at the total. */
inline real pick_weight_total(real environment_weight, const shading_point* at,
                              __constant const float* lights, path_settings settings) {
    real total = environment_weight;
    for (int i = 0; i < settings.light_count; ++i) {
        total += light_pick_weight(lights + i * FGR_PATH_LIGHT_FLOATS, at);
    }
    return total;
}

/* The probability of picking a weight out of a total (0 where nothing can be picked). */
inline real pick_probability(real weight, real total) {
    return select(weight / total, fgr_real(0.0f), total <= 0.0f);
}

/* Radiance arriving along `dir` from the sun discs, for a ray that left a shading point (`at`,
 * where light sampling's weights summed to `pick_total`) by BSDF sampling with pdf bsdf_pdf,
 * weighted as escaped_weight says; `at` is read only where MIS needs the discs' pick there. It is
 * reckoned where the ray starts, from the weights there, and added if the ray escapes. */
inline vec3 disc_radiance(vec3 dir, mask light_sampled, bool mis, real bsdf_pdf,
                          const shading_point* at, real pick_total, __constant const float* lights,
                          path_settings settings) {
    vec3 radiance = v3_splat(0.0f, 0.0f, 0.0f);
    for (int i = 0; i < settings.light_count; ++i) {
        __constant const float* light = lights + i * FGR_PATH_LIGHT_FLOATS;
        const float cos_max = light[FGR_PATH_LIGHT_COS_MAX];
        if ((int)light[FGR_PATH_LIGHT_KIND] == FGR_LIGHT_KIND_POINT || cos_max >= 1.0f) {
            continue; /* delta lights */
        }
        const mask in_disc = v3_dot(dir, light_vec3(light, FGR_PATH_LIGHT_VECTOR)) >= cos_max;
        if (!fgr_any(in_disc)) continue;
        real w = fgr_real(1.0f);
        if (fgr_any(in_disc & light_sampled)) {
            const real pick = pick_probability(light_pick_weight(light, at), pick_total);
            w = escaped_weight(light_sampled, mis, bsdf_pdf, pick * cone_pdf(cos_max));
        }
        const vec3 disc = v3_scale(light_vec3(light, FGR_PATH_LIGHT_RADIANCE), w);
        radiance = v3_add(radiance, v3_select(v3_splat(0.0f, 0.0f, 0.0f), disc, in_disc));
    }
    return radiance;
}

/* Radiance arriving along `dir` from the environment, for the lanes of `wanted` whose ray left
 * the scene, weighted as escaped_weight says (bsdf_pdf: the BSDF's pdf of dir at the last vertex,
 * environment_pick: the probability light sampling picked the environment there), plus the sun
 * discs' share (disc_radiance, reckoned where the ray started); the environment's tables are read
 * for those lanes alone. */
inline vec3 escaped_radiance(vec3 dir, mask wanted, mask light_sampled, bool mis, real bsdf_pdf,
                             real environment_pick, vec3 discs, path_settings settings,
                             ENVIRONMENT) {
    real env_pdf;
    const vec3 radiance =
        environment_light_radiance(dir, wanted, settings, ENVIRONMENT_PASS, &env_pdf);
    const real w = escaped_weight(light_sampled, mis, bsdf_pdf, environment_pick * env_pdf);
    return v3_add(v3_scale(radiance, w), discs);
}

/* One light sample for next-event estimation at a shading point: a direction, the radiance
 * arriving along it if nothing blocks it, its pdf (solid angle, including the pick; 0 for delta
 * lights, which MIS leaves alone) and how far a shadow ray must look; and what the escaped ray of
 * the same vertex needs for MIS: the sum of the sources' weights and the environment's pick. */
typedef struct light_sample {
    vec3 dir;
    vec3 radiance; /* already divided by the pick probability for delta lights; 0 where no
                      source could be picked */
    real pdf;      /* solid-angle pdf, pick included; 0 marks a delta light */
    real reach;
    real pick_total;
    real environment_pick;
} light_sample;

/* Where u, uniform in [low, low + width), falls in that interval, as a uniform number in [0, 1)
 * (lanes outside it get a number in [0, 1) too, which they ignore). */
inline real rescaled_within(real u, real low, real width) {
    const real safe_width = select(width, fgr_real(1.0f), width <= 0.0f);
    return fmax(fmin((u - low) / safe_width, fgr_real(0.99999994f)), fgr_real(0.0f));
}

/* The source is picked in proportion to its weight at the point (light_pick_weight,
 * environment_pick_weight) by u1, which the picked source then uses again, rescaled to [0, 1),
 * for its direction. A pixel's (u1, u2) are a stratified 2D set, and those that fall in one
 * source's interval of u1 stay one, stretched: each source's directions are stratified over the
 * samples that pick it. A pick of its own dimension would hand each source a random subset of the
 * points, no better spread than independent ones. */
inline light_sample sample_light(const shading_point* at, real u1, real u2, mask wanted,
                                 __constant const float* lights, path_settings settings,
                                 float max_distance, ENVIRONMENT) {
    light_sample s;
    const real env_weight = environment_pick_weight(settings, at);
    const real total = pick_weight_total(env_weight, at, lights, settings);
    s.pick_total = total;
    /* Just below the total, so that rounding never takes u1 past the last interval's end. */
    const real target = u1 * (total * 0.99999988f);
    s.environment_pick = pick_probability(env_weight, total);
    real env_pdf = fgr_real(0.0f);
    const mask env_picked = wanted & (target < env_weight);
    s.dir = environment_light_sample(rescaled_within(target, fgr_real(0.0f), env_weight), u2,
                                     env_picked, settings, ENVIRONMENT_PASS, &env_pdf, &s.radiance);
    s.radiance = v3_select(v3_splat(0.0f, 0.0f, 0.0f), s.radiance, env_picked);
    s.pdf = s.environment_pick * env_pdf;
    s.reach = fgr_real(max_distance);
    real picked_before = env_weight;
    for (int i = 0; i < settings.light_count; ++i) {
        __constant const float* light = lights + i * FGR_PATH_LIGHT_FLOATS;
        const real weight = light_pick_weight(light, at);
        const real picked_from = picked_before;
        picked_before = picked_from + weight;
        const mask chosen = wanted & (target >= picked_from) & (target < picked_before);
        if (!fgr_any(chosen)) continue;
        const real pick = pick_probability(weight, total);
        vec3 dir;
        const vec3 irradiance = light_irradiance(light, at->p, &dir);
        const float cos_max = light[FGR_PATH_LIGHT_COS_MAX];
        vec3 radiance;
        real pdf, reach = fgr_real(max_distance);
        if ((int)light[FGR_PATH_LIGHT_KIND] == FGR_LIGHT_KIND_POINT) {
            radiance = v3_scale(irradiance, 1.0f / pick);
            pdf = fgr_real(0.0f);
            const vec3 to_light = v3_sub(light_vec3(light, FGR_PATH_LIGHT_VECTOR), at->p);
            reach = fmin(sqrt(fmax(v3_length2(to_light), FGR_MIN_LENGTH * FGR_MIN_LENGTH)),
                         fgr_real(max_distance));
        } else if (cos_max >= 1.0f) {
            radiance = v3_scale(irradiance, 1.0f / pick);
            pdf = fgr_real(0.0f);
        } else {
            dir = sample_cone(dir, fgr_real(cos_max), rescaled_within(target, picked_from, weight),
                              u2);
            radiance = light_vec3(light, FGR_PATH_LIGHT_RADIANCE);
            pdf = pick * cone_pdf(cos_max);
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

/* One sample of every pixel of `tile`, each lane tracing its own pixel's path to its end: lanes
 * whose path has ended idle until the packet's last path ends (--no-regroup). */
inline void render_packet_sample(int tile, FGR_RENDER_ARGS, __constant const float* lights,
                                 path_settings settings, ENVIRONMENT) {
    (void)tile_count;
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
    const camera_ray ray = camera_ray_through(camera, pixels.px, pixels.py,
                                              camera_jitter(in_pixel, on_lens), PARAMS_PASS);

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
    /* The environment's pick at the last vertex, and the sun discs the ray from it would see. */
    real last_environment_pick = fgr_real(0.0f);
    shading_point at; /* the last vertex, read for the discs' picks only where light_sampled */
    vec3 discs =
        disc_radiance(dir, (mask)(0), mis, fgr_real(0.0f), &at, fgr_real(0.0f), lights, settings);
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
            const vec3 arriving =
                escaped_radiance(dir, (mask)(FGR_TRUE), light_sampled, mis, last_pdf,
                                 last_environment_pick, discs, settings, ENVIRONMENT_PASS);
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
        const real2 bsdf_u = sampler_next_2d(&rng);
        const real lobe_u = sampler_next_1d(&rng);
        const real roulette_u = sampler_next_1d(&rng);

        /* Next-event estimation, where the surface is not a perfect mirror there. */
        at = shading_point_of(p, m, n, wo);
        real pick_total = fgr_real(0.0f);
        last_environment_pick = fgr_real(0.0f);
        if (light_sampling) {
            const light_sample light =
                sample_light(&at, light_u.x, light_u.y, (mask)(FGR_TRUE), lights, settings,
                             limits.max_distance, ENVIRONMENT_PASS);
            pick_total = light.pick_total;
            last_environment_pick = light.environment_pick;
            real bsdf_pdf_of_light;
            const vec3 f = bsdf_eval_at(&at, light.dir, &bsdf_pdf_of_light);
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
                    select(mis ? power_heuristic(light.pdf, bsdf_pdf_of_light) : fgr_real(1.0f),
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
        discs = disc_radiance(scattered.wi, light_sampled, mis, scattered.pdf, &at, pick_total,
                              lights, settings);

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

/* --- Regrouped packets: path regeneration (Novak, Havran and Dachsbacher, "Path Regeneration for
 * Interactive Path Tracing", 2010), down to single DE evaluations. A launch traces
 * `launch_samples` samples of every pixel of the tile: a queue of paths, path k being sample
 * first + k / W of the tile's pixel k % W (W = FGR_WIDTH, pixels outside the image skipped).
 * Every turn of the packet's loop evaluates the DE once in every lane, each lane at the point its
 * own path wants: the next step of its ray's march (a camera ray, a bounce or a shadow ray) or the
 * next tap of the normal where its ray hit. A lane whose phase ends moves on at once (shading,
 * its next ray) and a lane whose path ends adds it to its pixel's sums and takes the next path of
 * the queue, so the lanes stay busy until the queue runs dry: regrouping whole bounces instead
 * leaves them idle inside each march, where one ray escapes in ten steps while its neighbour
 * takes a hundred. A lane serves any pixel of its tile, not only its own, or a tile on the
 * silhouette would wait on its surface pixels while its sky lanes idle. Each path draws exactly
 * the numbers of its (pixel, sample) (lane_sampler) and marches exactly as march_rays_core would
 * (march_lanes), so the image is the packet kernel's but for the order in which a pixel's samples
 * are summed. IFS scenes, which trace their rays whole, keep the packet kernel. */

#ifndef FGR_GEOMETRY_IFS
/* What the launch sums per pixel of the tile, in its private sums: float `sums[PATH_SUMS][W]`. */
#define PATH_SUM_RADIANCE 0    /* 3: radiance, clamped when settings.radiance_clamp > 0 */
#define PATH_SUM_ALBEDO 3      /* 3: the first hit's albedo */
#define PATH_SUM_NORMAL 6      /* 3: the first hit's normal */
#define PATH_SUM_ALPHA 9       /* 1: 1 where the camera ray met the surface */
#define PATH_SUM_LANE_STEPS 10 /* 1: DE evaluations of the pixel's paths (FGR_STATS) */
#define PATH_SUM_FOREGROUND 11 /* 3: radiance of the paths whose camera ray met the surface */
#define PATH_SUM_ODD_RADIANCE                                           \
    14 /* 3: radiance of the odd-numbered samples (accumulate_odd_half) \
        */
#define PATH_SUMS 17

/* A path's state in its lane (one per lane of the packet). Each lane is in one phase at a time,
 * each phase a DE evaluation a step: its ray's march (a camera ray or a bounce), the four taps of
 * the normal at the point it hit, or the shadow ray of its light sample. */
typedef struct path_lanes {
    march_lanes ray; /* the march under way: the path's ray, or its shadow ray */
    mask shadow_ray; /* lanes whose march is the shadow ray */
    mask tapping;    /* lanes estimating the normal: tap `tap` next */
    mask tap;
    vec3 p, gradient; /* the hit being shaded, and the DE's gradient from the taps so far */
    real eps;         /* the normal's stencil */
    vec3 radiance, throughput;
    vec3 unshadowed;            /* the light sample's contribution, if the shadow ray is clear */
    vec3 next_origin, next_dir; /* where the path goes on after its shadow ray */
    mask goes_on;               /* lanes whose path goes on after the shadow ray */
    vec3 dir;                   /* the path's ray's direction (the BSDF's wo at its hit) */
    real seen_at;               /* how far the camera saw the surface (0 before the first hit) */
    mask light_sampled;         /* light sampling also covered the last bounce's BSDF sample */
    real last_pdf;              /* that sample's pdf */
    real environment_pick;      /* the environment's pick there */
    vec3 discs;                 /* the sun discs the path's ray sees (disc_radiance) */
    mask bounce;                /* the vertices met so far: 0 for a camera ray */
    real depth;                 /* the first hit's distance, -1 before or without one */
    vec3 first_albedo, first_normal;
    real alpha;
    mask steps; /* DE evaluations of the path (FGR_STATS) */
} path_lanes;

/* Which lanes hold (1.0f) or not (0.0f), lane by lane in a private array. */
inline void lanes_of_mask(mask m, float* lanes) {
    fgr_store(select(fgr_real(0.0f), fgr_real(1.0f), m), 0, lanes);
}

/* How many lanes hold: the mask's lanes (-1 or 0; 1 or 0 for one lane) summed by halves. */
inline int lanes_in(mask m) {
#if FGR_WIDTH == 1
    return m != 0;
#else
    const FGR_LANE_TYPE(int) ones = FGR_LANE_TYPE(convert_int)(m) & 1;
#if FGR_WIDTH == 16
    const int8 eights = ones.lo + ones.hi;
    const int4 fours = eights.lo + eights.hi;
#elif FGR_WIDTH == 8
    const int4 fours = ones.lo + ones.hi;
#else
    const int4 fours = ones;
#endif
    const int2 twos = fours.lo + fours.hi;
    return twos.x + twos.y;
#endif
}

/* Lanes that wait, their phase ended, before they move on together (see render_regrouped):
 * 6 of 16. Waiting for 8 left 0.77 of the lanes at work for the same speed, for 4 0.85 but 11-15%
 * slower (the shading passes come twice as often). */
#ifndef FGR_REGROUP_BATCH
#define FGR_REGROUP_BATCH (3 * FGR_WIDTH / 8 > 0 ? 3 * FGR_WIDTH / 8 : 1)
#endif

/* Values of the tile's pixels (`by_slot`, one per pixel of the tile) gathered into the lanes
 * serving them (`lane_slot`). */
inline real gather_slots(const float* by_slot, const int* lane_slot) {
    float lanes[FGR_WIDTH];
    for (int lane = 0; lane < FGR_WIDTH; ++lane) lanes[lane] = by_slot[lane_slot[lane]];
    return fgr_load(0, lanes);
}

/* Whether the queue's path `k` is one to trace: its pixel is inside the image and, under adaptive
 * sampling, its sample is below the pixel's limit (`slot_limit`, 0 outside the image; see
 * sample_wanted). Paths that are not are never queued, so the lanes stay full with the pixels
 * that still want samples. */
inline bool queued_path_wanted(int k, int first, const float* slot_limit) {
    return slot_limit[k % FGR_WIDTH] > (float)(first + k / FGR_WIDTH);
}

/* Hands the paths still queued to the lanes of `free_lanes`, in queue order; returns the lanes
 * that got one (`lane_slot`, `lane_sample`: each lane's pixel and sample). */
inline mask take_queued_paths(mask free_lanes, int* next, int paths, int first,
                              const float* slot_limit, int* lane_slot, float* lane_sample) {
    float free_lane[FGR_WIDTH], taken[FGR_WIDTH];
    lanes_of_mask(free_lanes, free_lane);
    for (int lane = 0; lane < FGR_WIDTH; ++lane) taken[lane] = 0.0f;
    for (int lane = 0; lane < FGR_WIDTH; ++lane) {
        if (free_lane[lane] == 0.0f) continue;
        while (*next < paths && !queued_path_wanted(*next, first, slot_limit)) ++*next;
        if (*next >= paths) break;
        lane_slot[lane] = *next % FGR_WIDTH;
        lane_sample[lane] = (float)(first + *next / FGR_WIDTH);
        taken[lane] = 1.0f;
        ++*next;
    }
    return fgr_load(0, taken) != 0.0f;
}

/* Adds the paths that ended in the lanes of `ended` to their pixels' sums (and the depth of a
 * pixel's sample 0 to `slot_depth`). Two lanes may end paths of the same pixel at once, so the
 * lanes are added one after the other: a vector scatter would keep only one of them. Each path's
 * values reach its pixel here and nowhere else. */
inline void add_ended_paths(float sums[PATH_SUMS][FGR_WIDTH], float* slot_depth, mask ended,
                            const path_lanes* path, const int* lane_slot, const float* lane_sample,
                            path_settings settings) {
    vec3 radiance = path->radiance;
    if (settings.radiance_clamp > 0.0f) {
        const real largest = fmax(fmax(radiance.x, radiance.y), radiance.z);
        radiance = v3_scale(radiance, select(fgr_real(1.0f), settings.radiance_clamp / largest,
                                             largest > settings.radiance_clamp));
    }
    float values[PATH_SUMS][FGR_WIDTH], depth[FGR_WIDTH], ended_lane[FGR_WIDTH];
    fgr_store(radiance.x, 0, values[PATH_SUM_RADIANCE]);
    fgr_store(radiance.y, 0, values[PATH_SUM_RADIANCE + 1]);
    fgr_store(radiance.z, 0, values[PATH_SUM_RADIANCE + 2]);
    fgr_store(path->first_albedo.x, 0, values[PATH_SUM_ALBEDO]);
    fgr_store(path->first_albedo.y, 0, values[PATH_SUM_ALBEDO + 1]);
    fgr_store(path->first_albedo.z, 0, values[PATH_SUM_ALBEDO + 2]);
    fgr_store(path->first_normal.x, 0, values[PATH_SUM_NORMAL]);
    fgr_store(path->first_normal.y, 0, values[PATH_SUM_NORMAL + 1]);
    fgr_store(path->first_normal.z, 0, values[PATH_SUM_NORMAL + 2]);
    fgr_store(path->alpha, 0, values[PATH_SUM_ALPHA]);
    fgr_store(convert_real(path->steps), 0, values[PATH_SUM_LANE_STEPS]);
    /* alpha is 1 or 0 for one path: the whole radiance of a path whose camera ray hit. */
    fgr_store(radiance.x * path->alpha, 0, values[PATH_SUM_FOREGROUND]);
    fgr_store(radiance.y * path->alpha, 0, values[PATH_SUM_FOREGROUND + 1]);
    fgr_store(radiance.z * path->alpha, 0, values[PATH_SUM_FOREGROUND + 2]);
    fgr_store(path->depth, 0, depth);
    lanes_of_mask(ended, ended_lane);
    for (int lane = 0; lane < FGR_WIDTH; ++lane) {
        if (ended_lane[lane] == 0.0f) continue;
        const int slot = lane_slot[lane];
        for (int c = 0; c < PATH_SUM_ODD_RADIANCE; ++c) sums[c][slot] += values[c][lane];
        if (((int)lane_sample[lane] & 1) != 0) {
            for (int c = 0; c < 3; ++c) {
                sums[PATH_SUM_ODD_RADIANCE + c][slot] += values[PATH_SUM_RADIANCE + c][lane];
            }
        }
        if (lane_sample[lane] == 0.0f) slot_depth[slot] = depth[lane];
    }
}

/* The sums of the launch added to the planes of the tile (sample `first` on: the first launch
 * writes them). */
inline void store_path_sums(float sums[PATH_SUMS][FGR_WIDTH], const float* slot_depth,
                            int packet_steps, int first, int tile, __global float* planes,
                            int plane_size) {
    __global float* colour_planes = planes + FGR_COLOUR_PLANE * plane_size;
    for (int c = 0; c < 3; ++c) {
        accumulate_plane(fgr_load(0, sums[PATH_SUM_RADIANCE + c]), first, tile,
                         colour_planes + c * plane_size);
        accumulate_plane(fgr_load(0, sums[PATH_SUM_ALBEDO + c]), first, tile,
                         planes + (FGR_PATH_ALBEDO_PLANE + c) * plane_size);
        accumulate_plane(fgr_load(0, sums[PATH_SUM_NORMAL + c]), first, tile,
                         planes + (FGR_PATH_NORMAL_PLANE + c) * plane_size);
        accumulate_plane(fgr_load(0, sums[PATH_SUM_ODD_RADIANCE + c]), first, tile,
                         planes + (FGR_PATH_ODD_RADIANCE_PLANE + c) * plane_size);
    }
    if (first == 0) fgr_store(fgr_load(0, slot_depth), tile, planes + FGR_DEPTH_PLANE * plane_size);
    accumulate_plane(fgr_load(0, sums[PATH_SUM_ALPHA]), first, tile,
                     planes + FGR_PATH_ALPHA_PLANE * plane_size);
#ifdef FGR_STATS
    accumulate_plane(fgr_load(0, sums[PATH_SUM_LANE_STEPS]), first, tile,
                     planes + FGR_PATH_LANE_STEPS_PLANE * plane_size);
    accumulate_plane(fgr_real((float)packet_steps), first, tile,
                     planes + FGR_PATH_PACKET_STEPS_PLANE * plane_size);
#else
    (void)packet_steps;
#endif
#ifdef FGR_AOVS
    __global float* foreground = planes + FGR_PATH_FOREGROUND_PLANE(FGR_STATS_ON) * plane_size;
    for (int c = 0; c < 3; ++c) {
        accumulate_plane(fgr_load(0, sums[PATH_SUM_FOREGROUND + c]), first, tile,
                         foreground + c * plane_size);
    }
#endif
}

/* The lanes of `fresh` start the camera rays of their new paths (lane_slot, lane_sample). */
inline void start_camera_paths(path_lanes* path, lane_sampler* rng, mask fresh,
                               const int* lane_slot, const float* lane_sample, const float* slot_px,
                               const float* slot_py, const float* slot_start,
                               const float* slot_hint, int has_hints, bool independent,
                               camera_frame camera, march_limits limits,
                               __constant const float* lights, path_settings settings,
                               int* packet_steps, PARAMS) {
    const real px = gather_slots(slot_px, lane_slot), py = gather_slots(slot_py, lane_slot);
    const uint_lanes index = convert_uint_lanes(fgr_load(0, lane_sample));
    /* As the packet kernel seeds each sample (render_packet_sample). */
    lane_sampler started =
        independent ? lane_sampler_start(px, py, (uint_lanes)(0u),
                                         (uint_lanes)(settings.seed) + index * 0x9e3779b9u)
                    : lane_sampler_start(px, py, index, (uint_lanes)(settings.seed));
    const real2 in_pixel = lane_sampler_next_2d(&started, (mask)(FGR_TRUE));
    const real2 on_lens = lane_sampler_next_2d(&started, (mask)(FGR_TRUE));
    lane_sampler_take(rng, started, fresh);
    const camera_ray ray =
        camera_ray_through(camera, px, py, camera_jitter(in_pixel, on_lens), PARAMS_PASS);
    const vec3 zero = v3_splat(0.0f, 0.0f, 0.0f);
    path->radiance = v3_select(path->radiance, zero, fresh);
    path->throughput = v3_select(path->throughput, v3_splat(1.0f, 1.0f, 1.0f), fresh);
    path->first_albedo = v3_select(path->first_albedo, zero, fresh);
    path->first_normal = v3_select(path->first_normal, zero, fresh);
    path->dir = v3_select(path->dir, ray.dir, fresh);
    path->seen_at = select(path->seen_at, fgr_real(0.0f), fresh);
    path->last_pdf = select(path->last_pdf, fgr_real(0.0f), fresh);
    path->environment_pick = select(path->environment_pick, fgr_real(0.0f), fresh);
    shading_point nowhere; /* camera rays take no pick: disc_radiance reads no point */
    path->discs = v3_select(path->discs,
                            disc_radiance(ray.dir, (mask)(0), false, fgr_real(0.0f), &nowhere,
                                          fgr_real(0.0f), lights, settings),
                            fresh);
    path->alpha = select(path->alpha, fgr_real(0.0f), fresh);
    path->depth = select(path->depth, fgr_real(-1.0f), fresh);
    path->light_sampled &= ~fresh;
    path->bounce = select(path->bounce, (mask)(0), fresh);
    mask hint_evaluations = (mask)(0); /* counted with the stats */
    real start = gather_slots(slot_start, lane_slot);
    if (has_hints) {
        start = march_start_with_hint(start, gather_slots(slot_hint, lane_slot), ray.origin,
                                      ray.dir, fresh, limits, &hint_evaluations, PARAMS_PASS);
        *packet_steps += fgr_any(hint_evaluations != (mask)(0)) ? 1 : 0;
    }
    path->steps = select(path->steps, hint_evaluations, fresh);
    path->shadow_ray &= ~fresh;
    march_lanes_start(&path->ray, fresh, ray.origin, ray.dir, start, fgr_real(0.0f),
                      fgr_real(limits.max_distance), (mask)(0));
}

/* The lanes of `escaped`, whose path's ray left the scene: the environment and sun discs it
 * sees, weighted as escaped_radiance says. */
inline void add_escaped_radiance(path_lanes* path, mask escaped, path_settings settings, bool mis,
                                 ENVIRONMENT) {
    const vec3 arriving =
        escaped_radiance(path->dir, escaped, path->light_sampled, mis, path->last_pdf,
                         path->environment_pick, path->discs, settings, ENVIRONMENT_PASS);
    path->radiance = v3_select(path->radiance,
                               v3_add(path->radiance, v3_mul(path->throughput, arriving)), escaped);
}

/* The lanes of `hit`, whose path's ray met the surface: the normal's taps start there. */
inline void path_ray_hit(path_lanes* path, mask hit, camera_frame camera, PARAMS) {
    path->p = v3_select(path->p, march_lanes_point(&path->ray), hit);
    path->seen_at = select(path->seen_at, path->ray.t, hit & (path->bounce == (mask)(0)));
    path->eps = select(
        path->eps, fmax(path->seen_at * camera.pixel_angle * param_normal_epsilon, FGR_MIN_LENGTH),
        hit);
    path->gradient = v3_select(path->gradient, v3_splat(0.0f, 0.0f, 0.0f), hit);
    path->tap = select(path->tap, (mask)(0), hit);
    path->tapping |= hit;
}

/* Where the lanes estimating a normal evaluate the DE next: estimate_normal's tetrahedron, tap by
 * tap, (+,-,-), (-,-,+), (-,+,-), (+,+,+) times eps. */
inline void normal_tap_signs(mask tap, real* sx, real* sy, real* sz) {
    *sx = select(fgr_real(-1.0f), fgr_real(1.0f), (tap == (mask)(0)) | (tap == (mask)(3)));
    *sy = select(fgr_real(-1.0f), fgr_real(1.0f), tap >= (mask)(2));
    *sz = select(fgr_real(-1.0f), fgr_real(1.0f), (tap == (mask)(1)) | (tap == (mask)(3)));
}

/* The lanes of `lanes`, their vertex done: the path's next ray starts, or the path ends. */
inline void path_goes_on(path_lanes* path, mask lanes, mask* path_ends, march_limits limits) {
    const mask next = lanes & path->goes_on;
    *path_ends |= lanes & !path->goes_on;
    if (!fgr_any(next)) return;
    path->dir = v3_select(path->dir, path->next_dir, next);
    path->bounce = select(path->bounce, path->bounce + 1, next);
    march_lanes_start(&path->ray, next, path->next_origin, path->next_dir, fgr_real(0.0f),
                      path->seen_at, fgr_real(limits.max_distance), (mask)(FGR_TRUE));
}

/* The lanes of `shaded`, whose normal is known: what the surface emits, the first hit's layers,
 * then (below the bounce cap) a light sample, whose shadow ray starts, and the BSDF's sample,
 * where the path goes on (next_origin, next_dir; *path_ends where it ends). The random numbers
 * are render_packet_sample's for the same bounce. */
inline void shade_path_vertex(path_lanes* path, lane_sampler* rng, mask shaded, mask* path_ends,
                              __constant const float* lights, path_settings settings,
                              bool light_sampling, bool mis, march_limits limits, PARAMS,
                              ENVIRONMENT) {
    mask active = shaded;
    const vec3 p = path->p;
    const real path_length = path->seen_at;
    vec3 n = v3_normalize(path->gradient);
    const vec3 wo = v3_neg(path->dir);
    n = v3_select(n, wo, !(v3_length2(n) > 0.5f));
    n = v3_select(n, v3_neg(n), active & (v3_dot(n, wo) < 0.0f));
    march_result hit; /* what surface_material reads of the march (nothing, for DE scenes) */
    hit.t = path->ray.t;
    hit.hit = active;
    hit.steps = path->ray.steps;
    const material m = surface_material(hit, p, PARAMS_PASS);
    path->radiance = v3_select(
        path->radiance, v3_add(path->radiance, v3_mul(path->throughput, m.emission)), active);
    const mask first_hit = active & (path->bounce == (mask)(0));
    if (fgr_any(first_hit)) {
        path->depth = select(path->depth, path->ray.t, first_hit);
        path->first_albedo =
            v3_select(path->first_albedo,
                      v3_min(v3_add(m.albedo, m.specular), v3_splat(1.0f, 1.0f, 1.0f)), first_hit);
        path->first_normal = v3_select(path->first_normal, n, first_hit);
        path->alpha = select(path->alpha, fgr_real(1.0f), first_hit);
    }
    *path_ends |= active & !(path->bounce < (mask)(settings.max_bounces));
    active &= path->bounce < (mask)(settings.max_bounces);
    if (!fgr_any(active)) return;

    const vec3 leave = leave_surface(p, n, path_length, limits);
    const real2 light_u = lane_sampler_next_2d(rng, active);
    const real2 bsdf_u = lane_sampler_next_2d(rng, active);
    const real lobe_u = lane_sampler_next_1d(rng, active);
    const real roulette_u = lane_sampler_next_1d(rng, active);

    mask lit = (mask)(0);
    const shading_point at = shading_point_of(p, m, n, wo);
    real pick_total = fgr_real(0.0f), environment_pick = fgr_real(0.0f);
    if (light_sampling) {
        /* Only the lanes shaded here search the environment's tables. */
        const light_sample light = sample_light(&at, light_u.x, light_u.y, active, lights, settings,
                                                limits.max_distance, ENVIRONMENT_PASS);
        pick_total = light.pick_total;
        environment_pick = light.environment_pick;
        real bsdf_pdf_of_light;
        const vec3 f = bsdf_eval_at(&at, light.dir, &bsdf_pdf_of_light);
        lit = active & (v3_dot(light.dir, n) > 0.0f) & (fmax(fmax(f.x, f.y), f.z) > 0.0f) &
              (fmax(fmax(light.radiance.x, light.radiance.y), light.radiance.z) > 0.0f);
        if (fgr_any(lit)) {
            const mask delta_light = light.pdf <= 0.0f;
            const real w =
                select(mis ? power_heuristic(light.pdf, bsdf_pdf_of_light) : fgr_real(1.0f),
                       fgr_real(1.0f), delta_light);
            const real scale = select(w / light.pdf, fgr_real(1.0f), delta_light);
            const vec3 contribution = v3_scale(v3_mul(f, light.radiance), scale);
            path->unshadowed =
                v3_select(path->unshadowed, v3_mul(path->throughput, contribution), lit);
            march_lanes_start(&path->ray, lit, leave, light.dir, fgr_real(0.0f), path_length,
                              light.reach, (mask)(FGR_TRUE));
            path->shadow_ray |= lit;
        }
    }

    const bsdf_sample scattered = bsdf_sample_direction(m, n, wo, lobe_u, bsdf_u.x, bsdf_u.y);
    mask goes_on = active & scattered.valid;
    path->throughput =
        v3_select(path->throughput, v3_mul(path->throughput, scattered.weight), active);
    const mask light_sampled = light_sampling ? !scattered.delta : (mask)(0);
    path->light_sampled = select(path->light_sampled, light_sampled, active);
    path->last_pdf = select(path->last_pdf, scattered.pdf, active);
    path->environment_pick = select(path->environment_pick, environment_pick, active);
    path->discs = v3_select(path->discs,
                            disc_radiance(scattered.wi, light_sampled, mis, scattered.pdf, &at,
                                          pick_total, lights, settings),
                            active);
    /* Russian roulette, in the lanes whose path has reached its depth. */
    const mask roulette = goes_on & (path->bounce + 1 >= (mask)(settings.roulette_depth));
    if (fgr_any(roulette)) {
        const vec3 t = path->throughput;
        const real q = fmin(fmax(fmax(t.x, t.y), t.z), 1.0f);
        const mask survives = roulette_u < q;
        path->throughput =
            v3_select(t, v3_scale(t, select(fgr_real(0.0f), 1.0f / q, survives)), roulette);
        goes_on &= survives | !roulette;
    }
    path->next_origin = v3_select(path->next_origin, leave, active);
    path->next_dir = v3_select(path->next_dir, scattered.wi, active);
    path->goes_on = select(path->goes_on, goes_on, active);
    /* Lanes without a shadow ray go on (or end) at once. */
    path_goes_on(path, active & !lit, path_ends, limits);
}

/* The lanes of `stopped`, whose march ended: a path's ray that hit starts its normal's taps, one
 * that missed waits in *escaped for the environment; a shadow ray adds its light sample if it is
 * clear and lets its path go on (or end, in *ending). */
inline void rays_stopped(path_lanes* path, mask stopped, mask* escaped, mask* ending,
                         camera_frame camera, march_limits limits, PARAMS) {
    const mask shadows = stopped & path->shadow_ray;
    const mask rays = stopped & !path->shadow_ray;
    *escaped |= rays & !path->ray.hit;
    if (fgr_any(rays & path->ray.hit))
        path_ray_hit(path, rays & path->ray.hit, camera, PARAMS_PASS);
    if (fgr_any(shadows)) {
        const mask clear = shadows & !path->ray.hit;
        path->radiance = v3_select(path->radiance, v3_add(path->radiance, path->unshadowed), clear);
        path->shadow_ray &= ~shadows;
        path_goes_on(path, shadows, ending, limits);
    }
}

/* `launch_samples` samples of every pixel of `tile`, regrouped (see above). Each turn of the loop
 * evaluates the DE once for the whole packet, each lane at the point its path's phase wants; the
 * lanes whose phase ended then move on (shading, a new ray, a new path) before the next turn. */
inline void render_regrouped(int tile, FGR_RENDER_ARGS, __constant const float* lights,
                             path_settings settings, ENVIRONMENT) {
    (void)tile_count;
    const int first = sample;
    const tile_pixels pixels = pixels_of_tile(tile, camera);
    const march_limits limits = scene_march_limits(camera.pixel_angle, PARAMS_PASS);
    const bool light_sampling = (settings.flags & FGR_PATH_LIGHT_SAMPLING) != 0;
    const bool mis = (settings.flags & FGR_PATH_MIS) != 0;
    const bool independent = (settings.flags & FGR_PATH_INDEPENDENT) != 0;

    /* The tile's pixels by slot (the lane each has in the packet kernel), for lanes to gather. */
    float slot_px[FGR_WIDTH], slot_py[FGR_WIDTH], slot_limit[FGR_WIDTH];
    float slot_start[FGR_WIDTH], slot_hint[FGR_WIDTH], slot_depth[FGR_WIDTH];
    fgr_store(pixels.px, 0, slot_px);
    fgr_store(pixels.py, 0, slot_py);
    /* Each pixel's sample limit (adaptive sampling), none outside the image. */
    fgr_store(
        select(fgr_real(0.0f), fgr_load(tile, planes + FGR_PATH_SAMPLE_LIMIT_PLANE * plane_size),
               pixels.inside),
        0, slot_limit);
    fgr_store(march_start_of(march_starts, pixels, camera), 0, slot_start);
    fgr_store(has_hints ? fgr_load(tile, march_hints) : fgr_real(0.0f), 0, slot_hint);
    float sums[PATH_SUMS][FGR_WIDTH];
    for (int lane = 0; lane < FGR_WIDTH; ++lane) {
        slot_depth[lane] = -1.0f;
        for (int c = 0; c < PATH_SUMS; ++c) sums[c][lane] = 0.0f;
    }
    int lane_slot[FGR_WIDTH];
    float lane_sample[FGR_WIDTH];
    for (int lane = 0; lane < FGR_WIDTH; ++lane) {
        lane_slot[lane] = lane;
        lane_sample[lane] = (float)first;
    }
    const int paths = FGR_WIDTH * max(settings.launch_samples, 1);
    int next = 0;
    int packet_steps = 0;

    path_lanes path;
    const vec3 zero = v3_splat(0.0f, 0.0f, 0.0f);
    path.ray = march_lanes_none();
    path.p = path.gradient = path.radiance = path.throughput = path.unshadowed = zero;
    path.next_origin = path.next_dir = path.dir = path.first_albedo = path.first_normal = zero;
    path.eps = path.seen_at = path.last_pdf = path.alpha = path.environment_pick = fgr_real(0.0f);
    path.discs = zero;
    path.depth = fgr_real(-1.0f);
    path.shadow_ray = path.tapping = path.tap = path.goes_on = (mask)(0);
    path.light_sampled = path.bounce = path.steps = (mask)(0);
    lane_sampler rng =
        lane_sampler_start(pixels.px, pixels.py, (uint_lanes)(0u), (uint_lanes)(settings.seed));
    mask fresh = take_queued_paths((mask)(FGR_TRUE), &next, paths, first, slot_limit, lane_slot,
                                   lane_sample);
    /* Lanes whose phase ended and that wait to move on: rays that stopped, normals whose taps
     * are done (to be shaded), paths that left the scene or ended otherwise. */
    mask ray_ended = (mask)(0), taps_done = (mask)(0), escaped = (mask)(0), ending = (mask)(0);
    for (;;) {
        /* The waiting lanes move on until each is evaluating the DE again or has nothing left
         * to do. A path that ends takes the next of the queue, whose camera ray may end at once
         * (a prepass start past its reach), so this goes round while new paths start. */
        for (int turn = 0; turn <= paths; ++turn) {
            if (fgr_any(fresh)) {
                start_camera_paths(&path, &rng, fresh, lane_slot, lane_sample, slot_px, slot_py,
                                   slot_start, slot_hint, has_hints, independent, camera, limits,
                                   lights, settings, &packet_steps, PARAMS_PASS);
                ray_ended = fresh & !path.ray.marching;
                fresh = (mask)(0);
                if (fgr_any(ray_ended)) {
                    rays_stopped(&path, ray_ended, &escaped, &ending, camera, limits, PARAMS_PASS);
                }
            }
            if (fgr_any(taps_done)) {
                shade_path_vertex(&path, &rng, taps_done, &ending, lights, settings, light_sampling,
                                  mis, limits, PARAMS_PASS, ENVIRONMENT_PASS);
                taps_done = (mask)(0);
            }
            const mask ends = escaped | ending;
            if (!fgr_any(ends)) break;
            if (fgr_any(escaped)) {
                add_escaped_radiance(&path, escaped, settings, mis, ENVIRONMENT_PASS);
            }
            add_ended_paths(sums, slot_depth, ends, &path, lane_slot, lane_sample, settings);
            escaped = ending = (mask)(0);
            fresh =
                take_queued_paths(ends, &next, paths, first, slot_limit, lane_slot, lane_sample);
            if (!fgr_any(fresh)) break;
        }
        if (!fgr_any(path.ray.marching | path.tapping)) break;
        /* One DE evaluation for the packet a turn, each lane at its march's point or its
         * normal's tap, until FGR_REGROUP_BATCH lanes wait to be shaded or to end their paths
         * (that work costs the packet as much for one lane as for all, and more than a DE
         * evaluation) or none is left evaluating. A ray that hits starts its normal at once,
         * and a shadow ray that ends lets its path go on, both cheap. */
        for (;;) {
            const mask marching = path.ray.marching;
            const mask tapping = path.tapping;
            real sx, sy, sz;
            normal_tap_signs(path.tap, &sx, &sy, &sz);
            const vec3 tap_point =
                v3(path.p.x + path.eps * sx, path.p.y + path.eps * sy, path.p.z + path.eps * sz);
            const vec3 point = v3_select(march_lanes_point(&path.ray), tap_point, tapping);
            const real dist = scene_de(point, PARAMS_PASS);
#ifdef FGR_STATS
            fgr_count_if(path.steps, marching | tapping);
            packet_steps += 1;
#endif
            /* estimate_normal's sums, in its order. */
            path.gradient = v3_select(path.gradient,
                                      v3(path.gradient.x + sx * dist, path.gradient.y + sy * dist,
                                         path.gradient.z + sz * dist),
                                      tapping);
            path.tap = select(path.tap, path.tap + 1, tapping);
            const mask tapped = tapping & (path.tap == (mask)(4));
            path.tapping &= ~tapped;
            taps_done |= tapped;
            march_lanes_step(&path.ray, dist, limits);
            ray_ended = marching & !path.ray.marching;
            if (fgr_any(ray_ended)) {
                rays_stopped(&path, ray_ended, &escaped, &ending, camera, limits, PARAMS_PASS);
            }
            if (!fgr_any(path.ray.marching | path.tapping) ||
                lanes_in(taps_done | escaped | ending) >= FGR_REGROUP_BATCH) {
                break;
            }
        }
    }
    store_path_sums(sums, slot_depth, packet_steps, first, tile, planes, plane_size);
}

#endif /* !FGR_GEOMETRY_IFS */

__kernel void fgr_render(FGR_RENDER_ARGS, __constant const float* lights, path_settings settings,
                         ENVIRONMENT) {
    const int tile = get_global_id(0);
    if (tile >= tile_count) return;
#ifndef FGR_GEOMETRY_IFS
    if (settings.flags & FGR_PATH_REGROUP) {
        render_regrouped(tile, planes, plane_size, tile_count, camera, sample, PARAMS_PASS,
                         march_starts, march_hints, has_hints, lights, settings, ENVIRONMENT_PASS);
        return;
    }
#endif
    {
        render_packet_sample(tile, planes, plane_size, tile_count, camera, sample, PARAMS_PASS,
                             march_starts, march_hints, has_hints, lights, settings,
                             ENVIRONMENT_PASS);
    }
}
