// SPDX-License-Identifier: Apache-2.0
/* fgr kernel library: lighting. Blinn-Phong with the scene's lights, in linear RGB; the host
 * encodes to sRGB afterwards. Lights arrive as FGR_LIGHT_FLOATS floats each: type, vector,
 * colour, intensity (shared/fgr_layout_lights.h). */

/* The three floats of a light from `first` on (a vector or a colour), in every lane. */
#define light_vec3(light, first) \
    v3_splat((light)[first], (light)[(first) + 1], (light)[(first) + 2])
#define FGR_AMBIENT 0.06f
#define FGR_SPECULAR 0.35f
#define FGR_SHININESS 32 /* an integer: fgr_pown, five multiplications */

#ifndef FGR_SCENE_HAS_COLOUR
/* Default albedo for scenes that do not colour themselves: a neutral warm grey. */
inline vec3 scene_colour(vec3 p, PARAMS) {
    (void)fgr_params;
    return v3_splat(0.75f, 0.72f, 0.68f);
}
#endif

/* Sky seen by rays that miss: a soft vertical gradient so silhouettes read clearly. */
inline vec3 background(vec3 dir) {
    real h = clamp(dir.z * 0.5f + 0.5f, 0.0f, 1.0f);
    return v3(mix(fgr_real(0.020f), fgr_real(0.10f), h), mix(fgr_real(0.022f), fgr_real(0.13f), h),
              mix(fgr_real(0.030f), fgr_real(0.20f), h));
}

/* Direction towards `light` from p, the light's irradiance scale there (1/d^2 for points), and
 * how far a shadow ray must look for occluders (to the light, or max_distance for the sun). */
inline vec3 light_direction(__constant const float* light, vec3 p, float max_distance,
                            real* falloff, real* reach) {
    vec3 v = light_vec3(light, FGR_LIGHT_VECTOR);
    if ((int)light[FGR_LIGHT_KIND] == FGR_LIGHT_KIND_POINT) {
        vec3 to_light = v3_sub(v, p);
        /* The floor only keeps a point on the light from dividing by zero: far below any
         * footprint at every scale the precision resolves. */
        real dist2 = fmax(v3_length2(to_light), FGR_MIN_LENGTH * FGR_MIN_LENGTH);
        *falloff = 1.0f / dist2;
        *reach = fmin(sqrt(dist2), max_distance);
        return v3_scale(to_light, rsqrt(dist2));
    }
    *falloff = fgr_real(1.0f);
    *reach = fgr_real(max_distance);
    return v; /* the host normalised directional vectors */
}

/* The largest value among the lanes. */
inline int fgr_lanes_max(mask values) {
#if FGR_WIDTH == 1
    return (int)values;
#else
    int largest = 0;
    for (int i = 0; i < FGR_WIDTH; ++i) largest = max(largest, (int)values[i]);
    return largest;
#endif
}

/* Secondary rays (shadow, reflection, refraction) count their work in counter[0], the DE
 * evaluations each lane took part in, and counter[1], the packet's DE evaluations (every lane
 * holds the count: one march's is its longest lane's), which `fgr render --stats` reports
 * (planes 6 and 7 of the shaded mode) as their lane utilisation. Without stats the counts are
 * never stored and the compiler drops them. */
#define fgr_count_work(counter, steps) \
    ((counter)[0] += (steps), (counter)[1] += (mask)(fgr_lanes_max(steps)))

#ifdef FGR_EFFECT_SAMPLED_OCCLUSION
/* Ambient occlusion from five DE probes along the normal at distances h = r/5 .. r (r is the
 * built-in parameter ao_radius): in open space DE(p + h n) = h, so every unit the DE falls short
 * of h is geometry crowding the point. Nearer probes weigh more. */
inline real sampled_occlusion(vec3 p, vec3 n, PARAMS) {
    real shortfall = fgr_real(0.0f);
    float weight = 1.0f;
    for (int i = 1; i <= 5; ++i) {
        float h = param_ao_radius * (float)i / 5.0f;
        real dist = scene_de(v3_mad(p, n, fgr_real(h)), PARAMS_PASS);
        shortfall += weight * fmax(h - dist, 0.0f);
        weight *= 0.6f;
    }
    return clamp(1.0f - 3.0f * shortfall / param_ao_radius, 0.0f, 1.0f);
}
#endif

/* The smallest length rounding leaves meaningful at p: FGR_SURFACE_OFFSET (about 16 ulps) of
 * its largest coordinate. It scales with p, not with the scene, so a scene a thousandth the size
 * keeps the same offsets in pixels. */
inline real rounding_floor(vec3 p) {
    return FGR_SURFACE_OFFSET * fmax(fmax(fabs(p.x), fabs(p.y)), fabs(p.z));
}

/* How far off a surface point p reached after `travelled` a ray crossing the surface starts:
 * `footprints` hit footprints (a length proportional to the path, as the hit test is), plus the
 * rounding floor. */
inline real surface_offset(vec3 p, real travelled, float footprints, march_limits limits) {
    return footprints * travelled * limits.footprint + rounding_floor(p);
}

/* Where a secondary ray (shadow, reflection) starts from a surface point p reached after
 * `travelled`: two hit thresholds out along the normal, so the ray does not count the surface it
 * leaves as a hit (at exactly one threshold, rounding decides per pixel: visible contour lines). */
inline vec3 leave_surface(vec3 p, vec3 n, real travelled, march_limits limits) {
    return v3_mad(p, n, surface_offset(p, travelled, 2.0f, limits));
}

#if defined(FGR_EFFECT_SOFT_SHADOWS)
/* Soft visibility in [0, 1] of the light along to_light from p. `travelled` is the primary ray's
 * length, which sets the footprint below which the shadow ray counts as blocked. */
inline real light_visibility(vec3 p, vec3 to_light, mask lit, real travelled, real reach,
                             march_limits limits, mask* work, PARAMS) {
    real visibility = select(fgr_real(0.0f), fgr_real(1.0f), lit);
    real t = fgr_real(0.0f);
    real previous = fgr_real(0.0f);   /* the DE at the last sample */
    real previous_t = fgr_real(0.0f); /* and where it was taken */
    mask active = lit;
    const real floor_length = rounding_floor(p);
    for (int step = 0; step < limits.max_steps; ++step) {
        if (!fgr_any(active)) break;
        real dist = scene_de(v3_mad(p, to_light, t), PARAMS_PASS);
        fgr_count_if(work[0], active);
        work[1] += (mask)(1);
        mask blocked = active & (dist < (t + travelled) * limits.footprint);
        /* Closest approach between this sample and the previous one, not just at the samples
         * (without it, long steps leave bands): the circle where the two DE spheres, of radii
         * `previous` and `dist` with centres `gap` apart, meet; its plane lies `along` back from
         * this sample and its radius is `closest`. It says how near the ray may pass the surface
         * between the two samples only where its plane lies between them (0 < along < gap).
         * Elsewhere one sphere covers the other over the whole step and the nearest the surface
         * comes is at a sample: this one's DE here, the previous one's counted a step ago. Fractal
         * DEs are no exact distances: the Mandelbulb's grows by 1 to 1.4 per unit along a shadow
         * ray leaving it (0.5 r log r from r = e on), the spheres then touch or nest with their
         * circle, of radius near 0, behind the previous sample, and taking it there put black
         * specks on lit surfaces. The first sample has no previous one (gap 0). */
        const real gap = t - previous_t;
        real along =
            ((dist - previous) * (dist + previous) + gap * gap) / fmax(2.0f * gap, floor_length);
        along = select(fgr_real(0.0f), along, (along > 0.0f) & (along < gap));
        const real closest = sqrt(fmax(dist * dist - along * along, 0.0f));
        /* Penumbra: visibility is min over the ray of k * DE / t, so a ray that passes an
         * occluder at distance d after travelling t is dimmed by how narrowly it missed; the
         * sharpness k is the built-in parameter shadow_sharpness. t - along is never below the
         * previous sample's t, so off a lit surface (t = 0 at the first sample) only the floor
         * divides, and a sample that is not blocked has a DE far above it. */
        real penumbra = param_shadow_sharpness * closest / fmax(t - along, floor_length);
        visibility = select(visibility, fmin(visibility, penumbra), active);
        visibility = select(visibility, fgr_real(0.0f), blocked);
        previous = select(previous, dist, active);
        previous_t = select(previous_t, t, active);
        active &= !blocked & (visibility > 0.002f);
        /* Capped steps sample the penumbra of thin occluders the shadow ray passes. The cap is a
         * quarter of the distance covered plus 2% of the primary ray's length: lengths of the
         * view, so the penumbra looks the same at any scale. A step needs no cap where nothing
         * along it can dim the light further: over a step s <= step_factor * dist the DE stays
         * above dist - s, so the penumbra k (dist - s) / (t + s) stays at or above the
         * visibility so far when k (1 - step_factor) dist >= visibility (t + step_factor dist).
         * A shadow ray leaving the scene then strides out instead of growing a quarter a step. */
        const real stride = dist * limits.step_factor;
        const mask clear = param_shadow_sharpness * (dist - stride) >= visibility * (t + stride);
        t = select(t, t + select(fmin(stride, 0.25f * t + 0.02f * travelled), stride, clear),
                   active);
        active &= t <= reach;
    }
    visibility = clamp(visibility, 0.0f, 1.0f);
    return visibility * visibility * (3.0f - 2.0f * visibility); /* smoothstep: softer edge */
}
#elif defined(FGR_EFFECT_SHADOWS)
/* 1 where the light is visible from p, 0 where the surface blocks it: a march towards the light
 * that counts any hit before the light (`reach`) as an occluder. */
inline real light_visibility(vec3 p, vec3 to_light, mask lit, real travelled, real reach,
                             march_limits limits, mask* work, PARAMS) {
    march_result shadow =
        march_rays_occluded(p, to_light, lit, travelled, reach, limits, 0, PARAMS_PASS);
    fgr_count_work(work, shadow.steps);
    return select(fgr_real(1.0f), fgr_real(0.0f), shadow.hit);
}
#endif

/* The albedo where `hit` met the surface at p: the scene's colour, or for IFS scenes the one the
 * trace found. */
inline vec3 surface_albedo(march_result hit, vec3 p, PARAMS) {
#ifdef FGR_GEOMETRY_IFS
    (void)p;
    (void)fgr_params;
    return hit.albedo;
#else
    (void)hit;
    return scene_colour(p, PARAMS_PASS);
#endif
}

/* Linear colour of surface point p with normal n and albedo `albedo` seen along view_dir, reached
 * after `travelled` along the (possibly reflected) ray, for the lanes in `surface` (the others get
 * a colour nobody uses, and no shadow rays). `steps` feeds the cheap step-count ambient occlusion
 * when the scene asks for it; `with_shadows` lets reflections skip shadow rays. Shadow rays' DE
 * evaluations are added to *work. */
inline vec3 shade_surface(vec3 p, vec3 n, vec3 albedo, vec3 view_dir, real eps, mask steps,
                          real travelled, mask surface, int with_shadows, march_limits limits,
                          __constant const float* lights, int light_count, mask* work, PARAMS) {
    real ambient = fgr_real(FGR_AMBIENT);
#ifdef FGR_EFFECT_AMBIENT_OCCLUSION
    /* Rays that needed many steps crept past nearby geometry: darken them (the classic
     * step-count AO; costs nothing beyond the march already done). */
    real occlusion = 1.0f - convert_real(steps) / (float)limits.max_steps;
    ambient *= occlusion * occlusion;
#endif
#ifdef FGR_EFFECT_SAMPLED_OCCLUSION
    ambient *= sampled_occlusion(p, n, PARAMS_PASS);
#endif
    vec3 colour = v3_scale(albedo, ambient);
    vec3 to_eye = v3_neg(view_dir);
    for (int i = 0; i < light_count; ++i) {
        __constant const float* light = lights + i * FGR_LIGHT_FLOATS;
        real falloff, reach;
        vec3 l = light_direction(light, p, limits.max_distance, &falloff, &reach);
        real diffuse = fmax(v3_dot(n, l), 0.0f);
        vec3 half_vector = v3_normalize(v3_add(l, to_eye));
        real specular = FGR_SPECULAR * fgr_pown(fmax(v3_dot(n, half_vector), 0.0f), FGR_SHININESS);
        real strength = light[FGR_LIGHT_INTENSITY] * falloff *
                        select(fgr_real(0.0f), fgr_real(1.0f), diffuse > 0.0f);
#if defined(FGR_EFFECT_SHADOWS) || defined(FGR_EFFECT_SOFT_SHADOWS)
        if (with_shadows) {
            vec3 start = leave_surface(p, n, travelled, limits);
            strength *= light_visibility(start, l, surface & (diffuse > 0.0f), travelled, reach,
                                         limits, work, PARAMS_PASS);
        }
#endif
        vec3 light_colour = light_vec3(light, FGR_LIGHT_COLOUR);
        vec3 lit = v3(albedo.x * diffuse + specular, albedo.y * diffuse + specular,
                      albedo.z * diffuse + specular);
        colour = v3_add(colour, v3_scale(v3_mul(lit, light_colour), strength));
    }
    return colour;
}

#ifdef FGR_EFFECT_REFLECTIONS
#ifndef FGR_SCENE_HAS_REFLECTIVITY
/* Reflectivity at normal incidence for scenes that do not set it per material. */
inline real scene_reflectivity(vec3 p, PARAMS) {
    (void)p;
    (void)fgr_params;
    return fgr_real(0.15f);
}
#endif

/* Mirror reflections, up to the built-in parameter reflection_bounces deep: each bounce marches
 * the reflected ray and shades what it meets (without shadow rays, which a reflection rarely
 * shows), weighted by the surface's reflectivity raised towards 1 at grazing angles (Schlick's
 * Fresnel approximation) times the weights of the bounces before it. Lanes in `surface` only. */
inline vec3 add_reflection(vec3 colour, vec3 p, vec3 n, vec3 dir, real eps, real travelled,
                           mask surface, march_limits limits, __constant const float* lights,
                           int light_count, mask* work, PARAMS) {
    real throughput = fgr_real(1.0f); /* how much of this path's light reaches the eye */
    vec3 result = colour;
    vec3 mirror_colour = colour; /* colour of the surface the current bounce leaves */
    for (int bounce = 0; bounce < param_reflection_bounces; ++bounce) {
        if (!fgr_any(surface)) break;
        real cos_in = fmax(-v3_dot(dir, n), 0.0f);
        vec3 reflected = v3_normalize(v3_mad(dir, n, 2.0f * cos_in));
        real r0 = scene_reflectivity(p, PARAMS_PASS);
        real grazing = 1.0f - cos_in;
        real fresnel = r0 + (1.0f - r0) * grazing * grazing * grazing * grazing * grazing;
        surface &= r0 > 0.0f;
        vec3 start = leave_surface(p, n, travelled, limits);
        march_result next =
            march_rays_after(start, reflected, surface, travelled, limits, PARAMS_PASS);
        fgr_count_work(work, next.steps);
        vec3 seen = background(reflected);
        vec3 q = v3_mad(start, reflected, next.t);
        real q_eps = fmax((travelled + next.t) * limits.footprint * 0.5f, FGR_MIN_LENGTH);
        vec3 q_normal = n;
        if (fgr_any(next.hit)) {
            q_normal = surface_normal(next, q, q_eps, PARAMS_PASS);
            vec3 q_colour = shade_surface(
                q, q_normal, surface_albedo(next, q, PARAMS_PASS), reflected, q_eps, next.steps,
                travelled + next.t, next.hit, 0, limits, lights, light_count, work, PARAMS_PASS);
            seen = v3_select(seen, q_colour, next.hit);
        }
        /* This surface shows (1 - F) of its own colour and F of what it reflects. */
        real weight = select(fgr_real(0.0f), throughput * fresnel, surface);
        result = v3_add(result, v3_scale(v3_sub(seen, mirror_colour), weight));
        throughput *= select(fgr_real(0.0f), fresnel, surface);
        surface &= next.hit;
        mirror_colour = seen;
        p = q;
        n = q_normal;
        dir = reflected;
        eps = q_eps;
        travelled += next.t;
    }
    return result;
}
#endif

#ifdef FGR_EFFECT_REFRACTION
#ifndef FGR_SCENE_HAS_TRANSMISSION
/* How much light passes into the surface, for scenes that do not set it per material: the
 * built-in parameter `transmission`. */
inline real scene_transmission(vec3 p, PARAMS) {
    (void)p;
    return fgr_real(param_transmission);
}
#endif

/* Inner reflections a ray refracted into a solid follows before it is given up as trapped. */
#define FGR_INNER_BOUNCES 4

/* Crossing a solid along dir from `start` (just inside its surface): marches -DE until the far
 * surface is within the hit footprint of the whole path (`travelled` before start). Lanes that
 * reach it are set in *reached; the others ran out of steps or distance inside. Returns the
 * length crossed. */
inline real cross_solid(vec3 start, vec3 dir, mask active, real travelled, march_limits limits,
                        mask* reached, mask* work, PARAMS) {
    real t = fgr_real(0.0f);
    mask crossing = active;
    *reached = (mask)(0);
    for (int step = 0; step < limits.max_steps; ++step) {
        if (!fgr_any(crossing)) break;
        real dist = -scene_de(v3_mad(start, dir, t), PARAMS_PASS);
        fgr_count_if(*work, crossing);
        const real footprint = (t + travelled) * limits.footprint;
        mask arrived = crossing & (dist < footprint);
        *reached |= arrived;
        crossing &= !arrived;
        /* At least a footprint per step (a length, like the hit test), so grazing crossings end. */
        t = select(t, t + fmax(dist * limits.step_factor, footprint), crossing);
        crossing &= t <= limits.max_distance;
    }
    return t;
}

/* Transparency: light enters the surface (index of refraction `ior`; below 1 the solid is the
 * thinner medium, like a bubble), crosses the solid, which absorbs exp(-absorption * length)
 * tinted by its colour (Beer-Lambert), and leaves it bending back, showing what lies behind (shaded
 * without shadow rays). Where it meets the far surface beyond the critical angle it is totally
 * reflected and goes on inside, up to FGR_INNER_BOUNCES times. The result is blended over the
 * surface colour by the material's transmission times (1 - Fresnel reflectance). Lanes where no
 * light can pass keep the surface colour: total internal reflection at the entry (ior < 1),
 * rays that run out of steps inside, and rays still trapped after the last inner bounce. */
inline vec3 add_refraction(vec3 colour, vec3 p, vec3 n, vec3 dir, real eps, real travelled,
                           mask surface, march_limits limits, __constant const float* lights,
                           int light_count, mask* work, PARAMS) {
    real transmission = select(fgr_real(0.0f), scene_transmission(p, PARAMS_PASS), surface);
    /* Entry: Snell's law with eta = 1 / ior; k < 0 is total reflection, nothing enters. */
    const real cos_in = fmax(-v3_dot(dir, n), 0.0f);
    const real eta_in = fgr_real(1.0f / param_ior);
    const real k_in = 1.0f - eta_in * eta_in * (1.0f - cos_in * cos_in);
    mask inside = (transmission > 0.0f) & (k_in >= 0.0f);
    if (!fgr_any(inside)) return colour;
    vec3 albedo = scene_colour(p, PARAMS_PASS);
    vec3 d = v3_normalize(
        v3_add(v3_scale(dir, eta_in), v3_scale(n, eta_in * cos_in - sqrt(fmax(k_in, 0.0f)))));
    /* The hit lies up to a footprint outside the surface; start two more inside, so the crossing
     * does not take the surface it enters for the one it leaves. */
    vec3 start = v3_mad(p, n, -surface_offset(p, travelled, 3.0f, limits));
    real path = fgr_real(0.0f); /* length travelled inside, for absorption */
    mask leaves = (mask)(0);
    vec3 exit_point = p, exit_normal = n, out_dir = dir;
    for (int bounce = 0; bounce <= FGR_INNER_BOUNCES; ++bounce) {
        if (!fgr_any(inside)) break;
        mask reached;
        const real t =
            cross_solid(start, d, inside, travelled + path, limits, &reached, work, PARAMS_PASS);
        path = select(path, path + t, inside);
        inside &= reached; /* lanes lost inside stop here and keep the surface colour */
        const vec3 q = v3_mad(start, d, t);
        const real q_eps = fmax((travelled + path) * limits.footprint * 0.5f, FGR_MIN_LENGTH);
        const vec3 q_normal = estimate_normal(q, q_eps, PARAMS_PASS);
        /* Exit: from the solid (ior) into the outside (1). */
        const real cos_out = fmax(v3_dot(d, q_normal), 0.0f);
        const real k_out = 1.0f - param_ior * param_ior * (1.0f - cos_out * cos_out);
        const mask exits = inside & (k_out >= 0.0f);
        const vec3 refracted =
            v3_normalize(v3_add(v3_scale(d, fgr_real(param_ior)),
                                v3_scale(q_normal, sqrt(fmax(k_out, 0.0f)) - param_ior * cos_out)));
        exit_point = v3_select(exit_point, q, exits);
        exit_normal = v3_select(exit_normal, q_normal, exits);
        out_dir = v3_select(out_dir, refracted, exits);
        leaves |= exits;
        /* Total internal reflection: mirror off the inner surface and cross again. */
        inside &= !exits;
        const vec3 reflected = v3_normalize(v3_mad(d, q_normal, -2.0f * cos_out));
        d = v3_select(d, reflected, inside);
        start = v3_select(
            start, v3_mad(q, q_normal, -surface_offset(q, travelled + path, 3.0f, limits)), inside);
    }
    if (!fgr_any(leaves)) return colour;
    vec3 behind_start = leave_surface(exit_point, exit_normal, travelled + path, limits);
    march_result behind =
        march_rays_after(behind_start, out_dir, leaves, travelled + path, limits, PARAMS_PASS);
    fgr_count_work(work, behind.steps);
    vec3 seen = background(out_dir);
    if (fgr_any(behind.hit)) {
        vec3 q = v3_mad(behind_start, out_dir, behind.t);
        real q_eps = fmax((travelled + path + behind.t) * limits.footprint * 0.5f, FGR_MIN_LENGTH);
        vec3 q_normal = surface_normal(behind, q, q_eps, PARAMS_PASS);
        vec3 q_colour = shade_surface(q, q_normal, surface_albedo(behind, q, PARAMS_PASS), out_dir,
                                      q_eps, behind.steps, travelled + path + behind.t, behind.hit,
                                      0, limits, lights, light_count, work, PARAMS_PASS);
        seen = v3_select(seen, q_colour, behind.hit);
    }
    /* Beer-Lambert: each colour channel decays at a rate that grows as the albedo darkens. */
    real absorbed_path = path * param_absorption;
    vec3 absorbed = v3(seen.x * exp(-absorbed_path * (1.0f - albedo.x)),
                       seen.y * exp(-absorbed_path * (1.0f - albedo.y)),
                       seen.z * exp(-absorbed_path * (1.0f - albedo.z)));
    /* Schlick's Fresnel approximation, with the cosine on the thinner side of the interface. */
    real r0 = (param_ior - 1.0f) / (param_ior + 1.0f);
    r0 *= r0;
    const real cos_thin = param_ior >= 1.0f ? cos_in : sqrt(fmax(k_in, 0.0f));
    real grazing = 1.0f - cos_thin;
    real fresnel = r0 + (1.0f - r0) * grazing * grazing * grazing * grazing * grazing;
    real weight = select(fgr_real(0.0f), transmission * (1.0f - fresnel), leaves);
    return v3(mix(colour.x, absorbed.x, weight), mix(colour.y, absorbed.y, weight),
              mix(colour.z, absorbed.z, weight));
}
#endif
