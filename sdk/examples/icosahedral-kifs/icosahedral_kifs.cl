// SPDX-License-Identifier: Apache-2.0
/* Icosahedral kaleidoscopic IFS (after Knighty): fold space into one of the 120 mirror images
 * the icosahedron's symmetry divides it into, turn it, blow it up about the icosahedron's vertex;
 * repeat. Folds and turns are isometries and dr undoes the blow-ups, so (|z| - 1) / dr is a lower
 * bound of the distance to the level-n set. Past 30 levels (3^-30 of the whole) the blow-ups
 * would only overflow float, so the iterations stop there. */
#define FGR_KERNEL_API 2
#define FGR_SCENE_HAS_COLOUR

FGR_ORBIT(min(param_iterations, 30), FGR_NO_BAILOUT)
const rotation3 turn = rotation_about_axis(param_axis, param_angle);
FGR_ITERATE
z = fold_icosahedral(z);
z = op_rotate(z, turn);
z = scale_about(z, param_scale, icosahedron_vertex());
dr *= param_scale;
FGR_DISTANCE((v3_length(z) - 1.0f) / dr)
