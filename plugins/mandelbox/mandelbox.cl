/* Mandelbox (Tom Lowe, 2010): the iteration z -> scale * sphere_fold(box_fold(z)) + p.
 *
 * Distance estimate: DE = |z| / dr with the running derivative
 * dr -> dr * |scale| * (sphere fold's local scale) + 1, the folds' stretch bounding how fast z
 * moves with p. Folds and derivative are continuous in p, so the DE only jumps where the number of
 * iterations before escape changes, by about (fold offsets) / bailout relative: the large default
 * bailout (10^4) keeps those jumps below the march's tolerance. */

/* |scale| <= 1 never escapes (every point is inside): magnitudes below this are raised to it. */
#define MANDELBOX_MIN_ABS_SCALE 1.2f

inline float mandelbox_scale(float requested) {
    float magnitude = fmax(fabs(requested), MANDELBOX_MIN_ABS_SCALE);
    return requested < 0.0f ? -magnitude : magnitude;
}

/* Iterates the Mandelbox map from z = p; returns the DE and, when `record` is set, fills *trap
 * with the orbit. */
inline real mandelbox_iterate(vec3 p, PARAMS, int record, orbit_trap* trap) {
    const float scale = mandelbox_scale(param_scale);
    const float folding_limit = param_folding_limit;
    const float fixed_radius2 = param_fixed_radius * param_fixed_radius;
    /* min_radius above fixed_radius would make the sphere fold shrink space: clamp it. */
    const float min_radius2 = fmin(param_min_radius * param_min_radius, fixed_radius2);
    const float bailout2 = param_bailout * param_bailout;
    vec3 z = p;
    real dr = fgr_real(1.0f);
    real r2 = v3_length2(z);
    for (int i = 0; i < param_iterations; ++i) {
        mask active = r2 <= bailout2;
        if (!fgr_any(active)) break;
        real fold_dr = dr;
        vec3 folded = fold_sphere(fold_box(z, folding_limit), &fold_dr, min_radius2, fixed_radius2);
        z = v3_select(z, v3_mad(p, folded, fgr_real(scale)), active);
        dr = select(dr, fold_dr * fabs(scale) + 1.0f, active);
        r2 = v3_length2(z);
        if (record) *trap = trap_update(*trap, z, active);
    }
    return sqrt(r2) / dr;
}

#define FGR_SCENE_HAS_COLOUR
FGR_TRAP_COLOURED_SCENE(mandelbox_iterate)
