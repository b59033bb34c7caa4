// SPDX-License-Identifier: Apache-2.0
/* Bristorbrot: the escape-time fractal of Doug Bristor's quadratic map of R^3,
 *
 *     (x, y, z) -> (x^2 - y^2 - z^2,  y (2x - k z),  z (2x + k y)) + c
 *
 * with k = 1 (the `twist` parameter varies it), as a Mandelbrot set (z0 = c = p) or a Julia set
 * (z0 = p, c fixed).
 *
 * Source: Doug Bristor, "Bristorbrot 3D", fractalforums.com (theory board), as Mandelbulber
 * implements it (BristorbrotIteration in its fractal_formulas.cpp; the reference it gives is
 * http://www.fractalforums.com/theory/bristorbrot-3d/).
 *
 * Why inside-only: with k = 0 the map squares the quaternion x + y i + z j (the w = 0 slice of
 * the quaternion Mandelbrot set), whose norm is multiplicative, |F(z)| = |z|^2, and the scalar
 * running derivative gives the usual 0.5 |z| log|z| / |z'| estimate. The cross terms -k y z and
 * +k y z break that: |F(z)| ranges from 0.58 |z|^2 to 1.49 |z|^2 over a sphere (k = 1) and the
 * Jacobian stretches some directions more than others, differently from point to point, so no
 * scalar derivative bounds the distance. Jacobian-matrix or finite-difference estimates (what
 * Mandelbulber uses for it) are heuristics with no proof that they never overestimate; the inside
 * test needs none of that.
 *
 * Inside: |z|^2 <= bailout^2 for all `iterations` steps. For k = 1, |F(z)| >= |z|^2 / sqrt(3)
 * (the minimum of |F| on the unit sphere, F being homogeneous of degree 2 and zero only at 0), so
 * every orbit beyond R = sqrt(3) (1 + sqrt(1 + 4 |c| / sqrt(3))) / 2 escapes: R < 4 for |c| <= 4,
 * so with the default bailout 4 no orbit called escaped would have stayed bounded, in both forms
 * (a Mandelbrot point with |p| > 4 is outside at once). For k = 2 the minimum drops to about 0.23
 * and a bailout of 9 is needed for that. A larger bailout still changes the set at a finite
 * iteration count: orbits on their way out are counted inside for a few steps longer. Orbits
 * stop at the bailout and |F(z)| <= 2.05 |z|^2 for k <= 2, so float never overflows: |z|^2 stays
 * below (2.05 bailout^2 + |c|)^2 ~ 7e7 at bailout 64. */

#define FGR_SCENE_INSIDE_ONLY

/* Runs the map from p for `iterations` steps; returns the lanes whose orbit stayed within the
 * bailout, and records the orbit in *trap when `record` is set. */
inline mask bristorbrot_iterate(vec3 p, PARAMS, int record, orbit_trap* trap) {
    const float k = param_twist;
    const float bailout2 = param_bailout * param_bailout;
    vec3 c = p;
    if (param_form == 1) c = param_julia_c;
    vec3 z = p;
    mask inside = v3_length2(z) <= bailout2;
    for (int i = 0; i < param_iterations; ++i) {
        if (!fgr_any(inside)) break;
        const real x = z.x * z.x - z.y * z.y - z.z * z.z + c.x;
        const real y = z.y * (2.0f * z.x - k * z.z) + c.y;
        const real w = z.z * (2.0f * z.x + k * z.y) + c.z;
        z = v3_select(z, v3(x, y, w), inside);
        if (record) *trap = trap_update(*trap, z, inside);
        inside = inside & (v3_length2(z) <= bailout2);
    }
    return inside;
}

#define FGR_SCENE_HAS_COLOUR
FGR_TRAP_COLOURED_INSIDE_SCENE(bristorbrot_iterate)
