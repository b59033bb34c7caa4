/* Mandelbulb scene: the power-n Mandelbulb of kernels/fgr_fractals.cl (mandelbulb_de, where the
 * formulas are spelled out) with this scene's parameters, coloured by its orbit. */

real scene_de(vec3 p, PARAMS) {
    orbit_trap unused;
    return mandelbulb_de(p, param_power, param_bailout, param_iterations, param_variant == 1, 0,
                         &unused);
}

#define FGR_SCENE_HAS_COLOUR
vec3 scene_colour(vec3 p, PARAMS) {
    orbit_trap trap = trap_init();
    mandelbulb_de(p, param_power, param_bailout, param_iterations, param_variant == 1, 1, &trap);
    return trap_colour(trap, param_colour_mode, param_palette, param_base_colour);
}
