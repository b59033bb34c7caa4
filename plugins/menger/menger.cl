// SPDX-License-Identifier: Apache-2.0
/* Menger sponge as a kaleidoscopic IFS (Knighty's KIFS, as in Syntopia's Fragmentarium).
 *
 * Each iteration folds space into the cube's fundamental region x >= y >= z >= 0 (fold_menger),
 * optionally twists it, and blows the sub-cube there up to full size:
 *
 *     z <- R fold_menger(z) * scale - offset * (scale - 1)
 *
 * In that region two of the 20 sub-cubes remain: the corner cube at (1, 1, 1) and the edge cube
 * at (1, 1, 0) in the middle layer, which the step picks by pulling z.z back when it is below
 * -offset.z * (scale - 1) / 2. The step is the formula library's (formula_menger_step in
 * kernels/fractals/formulas/kifs.cl, which the menger formula scales by `scale`).
 *
 * After n iterations the point is measured against the cube [-1, 1]^3 and the distance scaled
 * back by scale^-n. Reflections, rotations, uniform scaling and the pull-back are all isometries
 * of the region the next fold sees (it takes |z| first, and the box at the end is symmetric), so
 * the estimate is a true lower bound on the distance to the surface it draws, for every
 * parameter value. With scale 3, offset (1, 1, 1) and no twist it is the level-n Menger sponge,
 * 20^n cubes of size 3^-n, and the estimate matches the exact distance to them outside.
 *
 * The loop keeps w = z * scale^-i instead of z: the same map (folds and rotations commute with
 * scaling), but w stays in p's units while z would overflow float for far points or high
 * iteration counts. */

/* The formula library (kernels/fractals/formulas/) is kernel API 2. */
#define FGR_KERNEL_API 2

/* Orbit traps see the first few levels only: deeper ones vary faster than a pixel and would turn
 * the colour into speckle. */
#define MENGER_TRAP_LEVELS 4

/* Runs the KIFS for p; returns the DE and, when `record` is set, fills *trap with the orbit. */
inline real menger_iterate(vec3 p, PARAMS, int record, orbit_trap* trap) {
    const float scale = param_scale;
    const vec3 offset = param_offset;
    /* The twist turns about the cube's diagonal, through the corner cube being blown up. */
    const rotation3 twist =
        rotation_about_axis(v3_splat(0.57735027f, 0.57735027f, 0.57735027f), param_twist);
    vec3 w = p;        /* the orbit point z_i times scale^-i */
    float size = 1.0f; /* scale^-i: the half-size of one level-i cube */
    for (int i = 0; i < param_iterations; ++i) {
        size /= scale;
        w = formula_menger_step(w, twist, offset, (scale - 1.0f) * size);
        if (record && i < MENGER_TRAP_LEVELS) {
            *trap = trap_update(*trap, v3_scale(w, 1.0f / size), FGR_TRUE);
        }
    }
    return sd_box(w, v3_splat(size, size, size));
}

#define FGR_SCENE_HAS_COLOUR
FGR_TRAP_COLOURED_SCENE(menger_iterate)
