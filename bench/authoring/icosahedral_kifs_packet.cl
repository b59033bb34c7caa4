// SPDX-License-Identifier: Apache-2.0
/* The SDK example sdk/examples/icosahedral-kifs written out by hand in packet form, as scenes were
 * before the iterate-function contract: the loop, the rotation matrix built once, the fold
 * spelled out, the scale factor kept as one float for all lanes. bench/authoring_cost.sh times the
 * example against it (`fgr bench --kernel-source`); the same surface, so the same image. */
#define FGR_KERNEL_API 2

inline real kifs_iterate(vec3 p, PARAMS, int record, orbit_trap* trap) {
    const float scale = param_scale;
    const rotation3 turn = rotation_about_axis(param_axis, param_angle);
    const vec3 mirror = v3_splat(-0.5f, -0.80901699f, 0.30901699f);
    const vec3 shift = v3_scale(icosahedron_vertex(), scale - 1.0f);
    vec3 z = p;
    float dr = 1.0f;
    for (int i = 0; i < min(param_iterations, 30); ++i) {
        for (int k = 0; k < 5; ++k) {
            z.x = fabs(z.x);
            z.y = fabs(z.y);
            const real side = fmin(v3_dot(z, mirror), 0.0f);
            z = v3_mad(z, mirror, -2.0f * side);
        }
        z = op_rotate(z, turn);
        z = v3_sub(v3_scale(z, scale), shift);
        dr *= scale;
        if (record) *trap = trap_update(*trap, z, FGR_TRUE);
    }
    return (v3_length(z) - 1.0f) / dr;
}

#define FGR_SCENE_HAS_COLOUR
FGR_TRAP_COLOURED_SCENE(kifs_iterate)
