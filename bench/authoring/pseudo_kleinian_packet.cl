// SPDX-License-Identifier: Apache-2.0
/* The SDK example sdk/examples/pseudo-kleinian written out by hand in packet form, as scenes were
 * before the iterate-function contract: the loop, the box fold and the inversion spelled out
 * per coordinate. bench/authoring_cost.sh times the example against it (`fgr bench
 * --kernel-source`); the same surface, so the same image. */
#define FGR_KERNEL_API 2

inline real kleinian_iterate(vec3 p, PARAMS, int record, orbit_trap* trap) {
    const vec3 box = param_box;
    const float size = param_size;
    const vec3 offset = param_offset;
    vec3 z = p;
    real dr = fgr_real(1.0f);
    for (int i = 0; i < param_iterations; ++i) {
        z = v3(clamp(z.x, -box.x, box.x) * 2.0f - z.x, clamp(z.y, -box.y, box.y) * 2.0f - z.y,
               clamp(z.z, -box.z, box.z) * 2.0f - z.z);
        const real r2 = v3_length2(z);
        const real k = select(fgr_real(1.0f), size / fmax(r2, 1e-6f), r2 < size);
        z = v3_mad(offset, z, k);
        dr *= k;
        if (record) *trap = trap_update(*trap, z, FGR_TRUE);
    }
    const real rxy = sqrt(z.x * z.x + z.y * z.y);
    return 0.5f * (fabs(rxy * z.z) - param_thickness) /
           sqrt(v3_length2(z) + param_thickness + 1e-20f) / dr;
}

#define FGR_SCENE_HAS_COLOUR
FGR_TRAP_COLOURED_SCENE(kleinian_iterate)
