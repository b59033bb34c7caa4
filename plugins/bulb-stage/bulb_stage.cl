// SPDX-License-Identifier: Apache-2.0
/* Bulb stage: a polished Mandelbulb standing on a tiled floor, made for the path tracer (its
 * default mode): the floor catches the fractal's soft shadow and its reflected light, and the
 * metal shows the sky or studio around it. In the shaded mode the same scene is lit by its sun
 * with Blinn-Phong.
 *
 * Materials: the bulb is a metal (no diffuse part, its colour as the specular reflectance F0)
 * whose roughness is a parameter; the floor is a diffuse tile with a faint plastic coat. */

inline real stage_bulb(vec3 p, PARAMS) {
    orbit_trap unused;
    return mandelbulb_de(p, param_power, 2.0f, param_iterations, 0, 0, &unused);
}

inline real stage_floor(vec3 p, PARAMS) { return p.z - param_floor_height; }

/* Which lanes' points belong to the floor (nearer to it than to the bulb). */
inline mask on_floor(vec3 p, PARAMS) {
    return stage_floor(p, PARAMS_PASS) < stage_bulb(p, PARAMS_PASS);
}

real scene_de(vec3 p, PARAMS) {
    return fmin(stage_bulb(p, PARAMS_PASS), stage_floor(p, PARAMS_PASS));
}

/* Two points' DEs with the bulb's orbits in one loop (mandelbulb_de_pair): the same values. */
#define FGR_SCENE_HAS_DE_PAIR
inline void scene_de_pair(vec3 a, vec3 b, real* da, real* db, PARAMS) {
    real bulb_a, bulb_b;
    mandelbulb_de_pair(a, b, param_power, 2.0f, param_iterations, 0, &bulb_a, &bulb_b);
    *da = fmin(bulb_a, stage_floor(a, PARAMS_PASS));
    *db = fmin(bulb_b, stage_floor(b, PARAMS_PASS));
}

/* Tiles of side `tile`, every other one a little darker. */
inline vec3 floor_colour(vec3 p, PARAMS) {
    const real checker = fgr_parity(floor(p.x / param_tile) + floor(p.y / param_tile));
    return v3_scale(param_floor_colour, 1.0f - 0.3f * checker);
}

#define FGR_SCENE_HAS_COLOUR
vec3 scene_colour(vec3 p, PARAMS) {
    return v3_select(param_bulb_colour, floor_colour(p, PARAMS_PASS), on_floor(p, PARAMS_PASS));
}

#define FGR_SCENE_HAS_MATERIAL
material scene_material(vec3 p, PARAMS) {
    const mask floor_lanes = on_floor(p, PARAMS_PASS);
    material m;
    m.albedo = v3_select(v3_splat(0.0f, 0.0f, 0.0f), floor_colour(p, PARAMS_PASS), floor_lanes);
    m.specular = v3_select(param_bulb_colour, v3_splat(0.04f, 0.04f, 0.04f), floor_lanes);
    m.roughness = select(fgr_real(param_bulb_roughness), fgr_real(0.6f), floor_lanes);
    m.emission = v3_splat(0.0f, 0.0f, 0.0f);
    return m;
}
