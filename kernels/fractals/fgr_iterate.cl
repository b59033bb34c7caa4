// SPDX-License-Identifier: Apache-2.0
/* fgr kernel library: orbit scenes (kernel API 2).
 *
 * Most fractals are "apply a step to z a number of times, then measure": Mandelbox, KIFS,
 * Kleinian, Mandelbulb. A scene written this way says only what is computed once, the step, and
 * the measure; the library owns the loop, the bailout, the per-lane bookkeeping of a packet of
 * rays (masks, select, any), the orbit trap for colouring, and scene_de and scene_colour:
 *
 *     #define FGR_KERNEL_API 2
 *     #define FGR_SCENE_HAS_COLOUR                 (colour by orbit trap: FGR_COLOUR_PARAMS)
 *
 *     FGR_ORBIT(min(param_iterations, 30), FGR_NO_BAILOUT)   (once per point; in scope: vec3 c)
 *         const rotation3 turn = rotation_about_axis(param_axis, param_angle);
 *     FGR_ITERATE                               (each step; also in scope: vec3 z, real dr, int i)
 *         z = fold_icosahedral(z);
 *         z = op_rotate(z, turn);
 *         z = scale_about(z, param_scale, icosahedron_vertex());
 *         dr *= param_scale;
 *     FGR_DISTANCE((v3_length(z) - 1.0f) / dr)
 *
 * FGR_ORBIT(iterations, bailout) starts the scene: z = c (the point whose distance is asked) and
 * dr = 1 (how much the steps so far stretched lengths: multiply it by each step's scale). What
 * follows it, up to FGR_ITERATE, runs once per point: compute there what the steps share (a
 * rotation matrix, a shift), not in the step, where it would run every iteration. The step, up to
 * FGR_DISTANCE, runs `iterations` times (i counts from 0) and stops in each lane once |z| passes
 * `bailout` (FGR_NO_BAILOUT: never); it may declare locals and call any helper, but must not
 * `return`, `break` or `continue`. FGR_DISTANCE(expression) ends the scene with the distance, an
 * expression in the final z and dr (and c), and defines scene_de; and scene_colour from the orbit
 * trap if `#define FGR_SCENE_HAS_COLOUR` came before it (declare the FGR_COLOUR_PARAMS parameters).
 * One FGR_ORBIT per scene. (FGR_DISTANCE takes one named parameter, not `...`: OpenCL C 1.2 has no
 * variadic macros, and NVIDIA's compiler refuses them; commas inside the expression's own
 * parentheses pass through.)
 *
 * Cost: the step is the loop's body, so the scene compiles to the loop one would write out by
 * hand in packet form, and costs the same (docs/performance.md, "Scene authoring cost"). A constant
 * FGR_NO_BAILOUT removes the bailout test and its masks from the loop altogether. */

#if FGR_KERNEL_API >= 2

/* No bailout: every lane runs every iteration (folding fractals: KIFS, Kleinian). */
#define FGR_NO_BAILOUT INFINITY

#define FGR_ORBIT(iterations, bailout)                                      \
    inline real fgr_scene_orbit(const vec3 c, PARAMS, const int fgr_record, \
                                orbit_trap* fgr_trap) {                     \
        const int fgr_iterations = (iterations);                            \
        const float fgr_bailout = (bailout);                                \
        const float fgr_bailout2 = fgr_bailout * fgr_bailout;               \
        vec3 z = c;                                                         \
        real dr = fgr_real(1.0f);

/* Lanes whose |z| passed the bailout keep their z and dr (an escaped orbit's distance is read
 * where it escaped). `!(r2 > bailout2)` rather than `r2 <= bailout2`: with a constant infinite
 * bailout the compiler sees an always-true mask and drops the bookkeeping. */
#define FGR_ITERATE                                              \
    for (int i = 0; i < fgr_iterations; ++i) {                   \
        const mask fgr_active = !(v3_length2(z) > fgr_bailout2); \
        if (!fgr_any(fgr_active)) break;                         \
        const vec3 fgr_z_before = z;                             \
        const real fgr_dr_before = dr;                           \
        {
#define FGR_DISTANCE(distance)                                         \
    }                                                                  \
    z = v3_select(fgr_z_before, z, fgr_active);                        \
    dr = select(fgr_dr_before, dr, fgr_active);                        \
    if (fgr_record) *fgr_trap = trap_update(*fgr_trap, z, fgr_active); \
    }                                                                  \
    return (distance);                                                 \
    }                                                                  \
    real scene_de(vec3 p, PARAMS) {                                    \
        orbit_trap unused;                                             \
        return fgr_scene_orbit(p, PARAMS_PASS, 0, &unused);            \
    }                                                                  \
    FGR_PASTE(FGR_ORBIT_COLOUR_, FGR_SCENE_HAS_COLOUR)(fgr_scene_orbit)

/* scene_colour from the orbit when the scene said `#define FGR_SCENE_HAS_COLOUR` (empty, or 1):
 * the paste above picks FGR_ORBIT_COLOUR_ or FGR_ORBIT_COLOUR_1; left undefined, the name stays
 * and picks the empty FGR_ORBIT_COLOUR_FGR_SCENE_HAS_COLOUR (the library's default colour). */
#define FGR_ORBIT_COLOUR_(orbit) FGR_TRAP_COLOUR_FUNCTION(orbit)
#define FGR_ORBIT_COLOUR_1(orbit) FGR_TRAP_COLOUR_FUNCTION(orbit)
#define FGR_ORBIT_COLOUR_FGR_SCENE_HAS_COLOUR(orbit)

#endif
