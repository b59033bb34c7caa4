// SPDX-License-Identifier: Apache-2.0
/* Mandelbulb scene: the power-n Mandelbulb of kernels/fractals/fgr_fractals.cl (mandelbulb_de,
 * where the formulas are spelled out) with this scene's parameters, coloured by its orbit. */

/* A whole-number power compiled in as a constant lets the compiler drop the fractional form and
 * the branch to it, and turn the integer power's steps (fgr_pown, complex_powi) into
 * straight-line multiplications in the same order, so the image stays the same. */
#define FGR_SPECIALISABLE power

inline real bulb_iterate(vec3 p, PARAMS, int record, orbit_trap* trap) {
    return mandelbulb_de(p, param_power, param_bailout, param_iterations, param_variant == 1,
                         record, trap);
}

#define FGR_SCENE_HAS_COLOUR
FGR_TRAP_COLOURED_SCENE(bulb_iterate)

/* Two points' DEs in one loop (mandelbulb_de_pair), for the library's paired evaluations. */
#define FGR_SCENE_HAS_DE_PAIR
inline void scene_de_pair(vec3 a, vec3 b, real* da, real* db, PARAMS) {
    mandelbulb_de_pair(a, b, param_power, param_bailout, param_iterations, param_variant == 1, da,
                       db);
}
