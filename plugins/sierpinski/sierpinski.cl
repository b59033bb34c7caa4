// SPDX-License-Identifier: Apache-2.0
/* Sierpinski tetrahedron as a kaleidoscopic IFS (Knighty's KIFS, as in Syntopia's Fragmentarium).
 *
 * Each iteration folds space into the quarter nearest the corner (1, 1, 1) of the tetrahedron
 * with corners (1,1,1), (-1,-1,1), (1,-1,-1), (-1,1,-1), optionally twists it, and blows that
 * corner's copy up to full size:
 *
 *     z <- R fold_sierpinski(z) * scale - offset * (scale - 1)
 *
 * After n iterations the point is measured against the base tetrahedron and the distance scaled
 * back by scale^-n. Every step is a reflection, a rotation or a uniform scaling, so the estimate
 * is 1-Lipschitz in p: a true lower bound on the distance to the surface it draws, for every
 * scale, offset and twist. With scale >= 2, offset (1, 1, 1) and no twist that surface is the
 * level-n Sierpinski tetrahedron: 4^n tetrahedra of size 2^-n.
 *
 * The loop keeps w = z * scale^-i instead of z. It is the same map (folds and rotations commute
 * with scaling), but w stays in p's units: z itself would grow like scale^n, which overflows
 * float for far points or high iteration counts, where w merely stops changing. The step is the
 * formula library's (formula_sierpinski_step in kernels/fractals/formulas/kifs.cl, which the
 * sierpinski formula scales by `scale`). */

/* The formula library (kernels/fractals/formulas/) is kernel API 2. */
#define FGR_KERNEL_API 2

#define SIERPINSKI_INV_SQRT3 0.57735027f
/* Orbit traps see the first few levels only: deeper ones vary faster than a pixel and would turn
 * the colour into speckle. */
#define SIERPINSKI_TRAP_LEVELS 4

/* World to fractal coordinates: a rotation taking world +z to the diagonal (1, 1, 1), so the
 * tetrahedron stands on a face with its apex up the z axis at (0, 0, sqrt(3)). */
inline vec3 tetrahedron_frame(vec3 p) {
    const float3 across = (float3)(0.70710678f, -0.70710678f, 0.0f);       /* world x */
    const float3 depth = (float3)(0.40824829f, 0.40824829f, -0.81649658f); /* world y */
    const float up = SIERPINSKI_INV_SQRT3;                                 /* world z */
    return v3(across.x * p.x + depth.x * p.y + up * p.z, across.y * p.x + depth.y * p.y + up * p.z,
              depth.z * p.y + up * p.z);
}

/* Runs the KIFS for p; returns the DE and, when `record` is set, fills *trap with the orbit. */
inline real sierpinski_iterate(vec3 p, PARAMS, int record, orbit_trap* trap) {
    const float scale = param_scale;
    const vec3 offset = param_offset;
    /* The twist turns about the diagonal (world z), through the corner being blown up. */
    const rotation3 twist = rotation_about_axis(
        v3_splat(SIERPINSKI_INV_SQRT3, SIERPINSKI_INV_SQRT3, SIERPINSKI_INV_SQRT3), param_twist);
    vec3 w = tetrahedron_frame(p); /* the orbit point z_i times scale^-i */
    float size = 1.0f;             /* scale^-i: the size of one level-i tetrahedron */
    for (int i = 0; i < param_iterations; ++i) {
        size /= scale;
        w = formula_sierpinski_step(w, twist, offset, (scale - 1.0f) * size);
        if (record && i < SIERPINSKI_TRAP_LEVELS) {
            *trap = trap_update(*trap, v3_scale(w, 1.0f / size), FGR_TRUE);
        }
    }
    return sd_tetrahedron(w, size);
}

#define FGR_SCENE_HAS_COLOUR
FGR_TRAP_COLOURED_SCENE(sierpinski_iterate)
