// SPDX-License-Identifier: Apache-2.0
/* Mandelbox (Tom Lowe, 2010): the iteration z -> scale * sphere_fold(box_fold(z)) + p, one step
 * of which is the formula library's formula_mandelbox (kernels/fractals/formulas/boxes.cl, with the
 * scale kept at |scale| >= 1.2, below which every point is inside).
 *
 * Distance estimate: DE = |z| / dr with the running derivative
 * dr -> dr * |scale| * (sphere fold's local scale) + 1, the folds' stretch bounding how fast z
 * moves with p. Folds and derivative are continuous in p, so the DE only jumps where the number of
 * iterations before escape changes, by about (fold offsets) / bailout relative: the large default
 * bailout (10^4) keeps those jumps below the march's tolerance. */

/* The formula library (kernels/fractals/formulas/) is kernel API 2. */
#define FGR_KERNEL_API 2

/* Iterates the Mandelbox map from z = p; returns the DE and, when `record` is set, fills *trap
 * with the orbit. */
inline real mandelbox_iterate(vec3 p, PARAMS, int record, orbit_trap* trap) {
    const float bailout2 = param_bailout * param_bailout;
    vec3 z = p;
    real w = fgr_real(0.0f); /* the library's fourth component, which the Mandelbox leaves alone */
    real dr = fgr_real(1.0f);
    real r2 = v3_length2(z);
    for (int i = 0; i < param_iterations; ++i) {
        mask active = r2 <= bailout2;
        if (!fgr_any(active)) break;
        vec3 z_next = z;
        real dr_next = dr;
        formula_mandelbox(&z_next, &w, &dr_next, p, param_scale, param_folding_limit,
                          param_min_radius, param_fixed_radius);
        z = v3_select(z, z_next, active);
        dr = select(dr, dr_next, active);
        r2 = v3_length2(z);
        if (record) *trap = trap_update(*trap, z, active);
    }
    return sqrt(r2) / dr;
}

#define FGR_SCENE_HAS_COLOUR
FGR_TRAP_COLOURED_SCENE(mandelbox_iterate)
