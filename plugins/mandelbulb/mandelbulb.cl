// SPDX-License-Identifier: Apache-2.0
/* Mandelbulb scene: the power-n Mandelbulb of kernels/fractals/fgr_fractals.cl (mandelbulb_de,
 * where the formulas are spelled out) with this scene's parameters, coloured by its orbit. */

/* A whole-number power compiled in as a constant lets the compiler unroll the integer power's
 * multiplications (fgr_pown, complex_powi) instead of looping over its bits. */
#define FGR_SPECIALISABLE power

inline real bulb_iterate(vec3 p, PARAMS, int record, orbit_trap* trap) {
    return mandelbulb_de(p, param_power, param_bailout, param_iterations, param_variant == 1,
                         record, trap);
}

#define FGR_SCENE_HAS_COLOUR
FGR_TRAP_COLOURED_SCENE(bulb_iterate)
