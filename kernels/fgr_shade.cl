/* fgr kernel library: lighting. Blinn-Phong with the scene's lights, in linear RGB; the host
 * encodes to sRGB afterwards. Lights arrive as FGR_LIGHT_FLOATS floats each:
 * type, vector.xyz, colour.rgb, intensity (see host/src/renderer.cpp). */

#define FGR_LIGHT_FLOATS 8
#define FGR_LIGHT_POINT 1
#define FGR_AMBIENT 0.06f
#define FGR_SPECULAR 0.35f
#define FGR_SHININESS 32.0f

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

/* Direction towards light `i` from p, and the light's irradiance scale there (1/d^2 for points). */
inline vec3 light_direction(__constant const float* light, vec3 p, real* falloff) {
    vec3 v = v3_splat(light[1], light[2], light[3]);
    if ((int)light[0] == FGR_LIGHT_POINT) {
        vec3 to_light = v3_sub(v, p);
        real dist2 = fmax(v3_length2(to_light), 1e-8f);
        *falloff = 1.0f / dist2;
        return v3_scale(to_light, rsqrt(dist2));
    }
    *falloff = fgr_real(1.0f);
    return v; /* the host normalised directional vectors */
}

#ifdef FGR_EFFECT_SHADOWS
/* 1 where the light is visible from p, 0 where the surface blocks it: a march towards the light
 * that counts any hit before max_distance as an occluder. */
inline real light_visibility(vec3 p, vec3 to_light, mask lit, march_limits limits, PARAMS) {
    march_result shadow = march_rays(p, to_light, lit, limits, PARAMS_PASS);
    return select(fgr_real(1.0f), fgr_real(0.0f), shadow.hit);
}
#endif

/* Linear colour of surface point p with normal n seen along view_dir. `steps` feeds the cheap
 * step-count ambient occlusion when the scene asks for it. */
inline vec3 shade_surface(vec3 p, vec3 n, vec3 view_dir, real eps, mask steps,
                          march_limits limits, __constant const float* lights, int light_count,
                          PARAMS) {
    vec3 albedo = scene_colour(p, PARAMS_PASS);
    real ambient = fgr_real(FGR_AMBIENT);
#ifdef FGR_EFFECT_AMBIENT_OCCLUSION
    /* Rays that needed many steps crept past nearby geometry: darken them (the classic
     * step-count AO; costs nothing beyond the march already done). */
    real occlusion = 1.0f - convert_real(steps) / (float)limits.max_steps;
    ambient *= occlusion * occlusion;
#endif
    vec3 colour = v3_scale(albedo, ambient);
    vec3 to_eye = v3_neg(view_dir);
    for (int i = 0; i < light_count; ++i) {
        __constant const float* light = lights + i * FGR_LIGHT_FLOATS;
        real falloff;
        vec3 l = light_direction(light, p, &falloff);
        real diffuse = fmax(v3_dot(n, l), 0.0f);
        vec3 half_vector = v3_normalize(v3_add(l, to_eye));
        real specular = FGR_SPECULAR * pow(fmax(v3_dot(n, half_vector), 0.0f), FGR_SHININESS);
        real strength = light[7] * falloff * select(fgr_real(0.0f), fgr_real(1.0f), diffuse > 0.0f);
#ifdef FGR_EFFECT_SHADOWS
        vec3 start = v3_mad(p, n, 2.0f * eps);
        strength *= light_visibility(start, l, diffuse > 0.0f, limits, PARAMS_PASS);
#endif
        vec3 light_colour = v3_splat(light[4], light[5], light[6]);
        vec3 lit = v3(albedo.x * diffuse + specular, albedo.y * diffuse + specular,
                 albedo.z * diffuse + specular);
        colour = v3_add(colour, v3_scale(v3_mul(lit, light_colour), strength));
    }
    return colour;
}
