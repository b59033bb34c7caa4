/* fgr kernel library: effects applied along the primary ray (fog, glow) and the camera's sampling
 * (anti-aliasing jitter, thin-lens depth of field). Each effect exists only when its switch is
 * compiled in; sampling is always available because the sample count is a runtime choice. */

/* Where in the pixel, and where on the lens, sample `sample` of pixel (px, py) goes: sample 0 is
 * the pixel's centre through the lens centre (so one sample renders exactly the un-jittered
 * image); later samples are uniformly random, independent per pixel (fgr_sampler.cl's hashed
 * numbers). */
typedef struct camera_sample {
    real pixel_x, pixel_y; /* offset in the pixel, [0, 1) */
    real lens_x, lens_y;   /* point on the unit disc */
} camera_sample;

inline camera_sample sample_camera(real px, real py, int sample) {
    camera_sample s;
    if (sample == 0) {
        s.pixel_x = s.pixel_y = fgr_real(0.5f);
        s.lens_x = s.lens_y = fgr_real(0.0f);
        return s;
    }
    const uint_lanes h1 = sampler_mix(sampler_pixel_seed(px, py, sample));
    const uint_lanes h2 = sampler_mix(h1), h3 = sampler_mix(h2), h4 = sampler_mix(h3);
    s.pixel_x = sampler_hashed_unit(h1);
    s.pixel_y = sampler_hashed_unit(h2);
    /* Uniform on the disc: radius sqrt(u), angle 2 pi v. */
    real radius = sqrt(sampler_hashed_unit(h3));
    real angle = 6.28318531f * sampler_hashed_unit(h4);
    real cos_angle = fgr_cos(angle), sin_angle = fgr_sin(angle);
    s.lens_x = radius * cos_angle;
    s.lens_y = radius * sin_angle;
    return s;
}

#ifdef FGR_EFFECT_FOG
/* Exponential distance fog: a surface at distance t keeps exp(-density t) of its colour and takes
 * the rest from the fog; rays that miss see the sky through the fog out to max_distance, so a
 * density of 0 leaves the image untouched. */
inline vec3 apply_fog(vec3 colour, real t, mask hit, float max_distance, PARAMS) {
    real keep = exp(-param_fog_density * select(fgr_real(max_distance), t, hit));
    vec3 fog = param_fog_colour;
    return v3(mix(fog.x, colour.x, keep), mix(fog.y, colour.y, keep), mix(fog.z, colour.z, keep));
}
#endif

#ifdef FGR_EFFECT_GLOW
/* Glow around the surface: rays that miss pick up glow_colour * glow_strength, fading as
 * exp(-closest / glow_radius) with the closest their march came to the surface. */
inline vec3 apply_glow(vec3 colour, real closest, mask missed, PARAMS) {
    real amount =
        select(fgr_real(0.0f), param_glow_strength * exp(-fmax(closest, 0.0f) / param_glow_radius),
               missed);
    return v3_add(colour, v3_scale(param_glow_colour, amount));
}
#endif
