/* @SCENE_NAME@ (@SCENE_ID@): the distance estimator, the colour and the material.
 *
 * fgr evaluates many rays at once, so `real` is a float or a vector of floats and `vec3` holds
 * one of them per axis; write the maths once with the v3_* helpers and it runs on CPUs (16 rays
 * per work-item) and GPUs (one). The kernel library (sd_* primitives, op_* combinators, fold_*
 * folds, orbit traps and palettes) is available here; see fgr's SDK guide. A fractal that
 * iterates a step (KIFS, Mandelbox, Kleinian) is shortest as an orbit scene: FGR_ORBIT,
 * FGR_ITERATE, FGR_DISTANCE ("Orbit scenes: the short way" in the guide). */

/* The kernel library version this source is written for: fgr shows it that version's names.
 * Parameters read as the uniform values they are: param_radius is a float, param_tint a float3
 * (param_tint.x is a float); v3_uniform(param_tint) is the same colour in every lane, a vec3. */
#define FGR_KERNEL_API 4

/* A lower bound on the distance from p to the surface: the ball of radius param_radius, pushed
 * in and out by sine bumps. op_displace_sine divides by the bumps' steepest slope, so the result
 * stays a bound and rays never step through the surface. */
real scene_de(vec3 p, PARAMS) {
    real ball = sd_sphere(p, param_radius);
    return op_displace_sine(ball, p, param_bumps, param_frequency);
}

/* No distance estimator for your formula? Replace scene_de with an inside test, true in the lanes
 * where p is in the set, and fgr renders it by brute force (--mode brute; the colour below still
 * applies). Put `#define FGR_SCENE_INSIDE_ONLY` on a line of its own, outside this comment, then
 *     mask scene_inside(vec3 p, PARAMS) { return v3_length(p) < param_radius; }
 * See "Scenes without a distance estimator" in fgr's SDK guide. */

/* Albedo in linear RGB: the tint on the bumps' tops, fading to white in the hollows. */
#define FGR_SCENE_HAS_COLOUR
vec3 scene_colour(vec3 p, PARAMS) {
    real wave = sin(param_frequency * p.x) * sin(param_frequency * p.y) *
                sin(param_frequency * p.z);
    real t = clamp(0.5f + 1.5f * wave, 0.0f, 1.0f);
    vec3 white = v3_splat(0.9f, 0.9f, 0.88f);
    return v3_add(v3_scale(white, 1.0f - t), v3_scale(v3_uniform(param_tint), t));
}

/* The material the path tracer (`fgr render --mode path`) shades with: the same colour as a
 * satin plastic (a diffuse base under a faint glossy coat). Without this function the path
 * tracer uses diffuse_material(scene_colour(p)); the fields are explained in fgr's SDK guide. */
#define FGR_SCENE_HAS_MATERIAL
material scene_material(vec3 p, PARAMS) {
    material m = diffuse_material(scene_colour(p, PARAMS_PASS));
    m.specular = v3_splat(0.04f, 0.04f, 0.04f);
    m.roughness = fgr_real(0.4f);
    return m;
}
