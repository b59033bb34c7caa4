// SPDX-License-Identifier: Apache-2.0
/* fgr kernel library: effects applied along the primary ray (fog, glow). Each exists only when its
 * switch is compiled in. (Where a sample's ray leaves the pixel and the lens is sampling's:
 * sample_camera in fgr_sampler.cl.) */

#ifdef FGR_EFFECT_FOG
/* Exponential distance fog: a surface at distance t keeps exp(-density t) of its colour and takes
 * the rest from the fog; rays that miss see the sky through the fog out to max_distance, so a
 * density of 0 leaves the image untouched. */
inline vec3 apply_fog(vec3 colour, real t, mask hit, float max_distance, PARAMS) {
    real keep = exp(-param_fog_density * select(fgr_real(max_distance), t, hit));
    vec3 fog = fgr_param_lanes(param_fog_colour);
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
    return v3_add(colour, v3_scale(fgr_param_lanes(param_glow_colour), amount));
}
#endif
