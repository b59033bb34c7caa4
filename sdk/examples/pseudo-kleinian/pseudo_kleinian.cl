// SPDX-License-Identifier: Apache-2.0
/* Knighty's pseudo-Kleinian: a box fold and an inversion in a sphere, repeated, approximate the
 * limit set of a Kleinian group; the distance is to a thin surface around the orbit's end, divided
 * by how much the inversions magnified space. */
#define FGR_KERNEL_API 2
#define FGR_SCENE_HAS_COLOUR

/* Knighty's "thingy": the surface |rxy z| = thickness, its distance roughly (|rxy z| - t) / |z|. */
inline real thingy(vec3 z, float thickness) {
    const real rxy = sqrt(z.x * z.x + z.y * z.y);
    return 0.5f * (fabs(rxy * z.z) - thickness) / sqrt(v3_length2(z) + thickness + 1e-20f);
}

FGR_ORBIT(param_iterations, FGR_NO_BAILOUT)
FGR_ITERATE
z = fold_box_axes(z, param_box);
z = fold_sphere(z, &dr, 1e-6f, param_size);
z = v3_add(z, param_offset);
FGR_DISTANCE(thingy(z, param_thickness) / dr)
