// SPDX-License-Identifier: Apache-2.0
/* Quaternion Julia set: the iteration q -> q^2 + c on quaternions q = x + y i + z j + w k, seen as
 * the 3D slice w = slice_w of the 4D set. One step is the formula library's
 * formula_quaternion_julia (kernels/fractals/formulas/hypercomplex.cl, its quaternion_square and
 * quaternion_length too, and its Koebe bound formula_potential_bound); this scene adds the slice
 * and the bounding ball.
 *
 * Distance estimate: DE = 0.5 |q| log|q| / |q'| with the running derivative q' -> 2 q q'. The
 * quaternion norm is multiplicative, so |q'| -> 2 |q| |q'| exactly and one scalar stands in for the
 * whole derivative. */

/* The formula library (kernels/fractals/formulas/) is kernel API 2. */
#define FGR_KERNEL_API 2

/* Every orbit leaving the ball of radius R = (1 + sqrt(1 + 4|c|)) / 2 escapes: beyond it
 * |q^2 + c| >= |q|^2 - |c| > |q| and the gap only grows. So the whole set lies inside it. */
inline float julia_set_radius(float c_length) {
    return 0.5f * (1.0f + sqrt(1.0f + 4.0f * c_length));
}

/* Iterates q -> q^2 + c from q = (p, slice_w); returns the DE and, when `record` is set, fills
 * *trap with the orbit's x, y, z. */
inline real julia_iterate(vec3 p, PARAMS, int record, orbit_trap* trap) {
    const float c_x = param_c_x, c_y = param_c_y, c_z = param_c_z, c_w = param_c_w;
    const vec3 julia = v3_splat(c_x, c_y, c_z);
    const float bailout = param_bailout;
    vec3 z = p;
    real w = fgr_real(param_slice_w);
    real r = quaternion_length(z, w);
    real dr = fgr_real(1.0f);
    real potential_scale = fgr_real(1.0f); /* 2^-n after n iterations */
    for (int i = 0; i < param_iterations; ++i) {
        mask active = r <= bailout;
        if (!fgr_any(active)) break;
        vec3 z_next = z;
        real w_next = w, dr_next = dr;
        formula_quaternion_julia(&z_next, &w_next, &dr_next, p, julia, c_w);
        z = v3_select(z, z_next, active);
        w = select(w, w_next, active);
        dr = select(dr, dr_next, active);
        potential_scale = select(potential_scale, 0.5f * potential_scale, active);
        r = quaternion_length(z, w);
        if (record) *trap = trap_update(*trap, z, active);
    }
    /* Far from the set the bounding ball is the better bound; both never overestimate. */
    float c_length = sqrt(c_x * c_x + c_y * c_y + c_z * c_z + c_w * c_w);
    real ball_bound = v3_length(p) - julia_set_radius(c_length);
    return fmax(formula_potential_bound(r, dr, potential_scale), ball_bound);
}

#define FGR_SCENE_HAS_COLOUR
FGR_TRAP_COLOURED_SCENE(julia_iterate)
