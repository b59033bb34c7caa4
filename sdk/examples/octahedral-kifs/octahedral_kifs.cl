// SPDX-License-Identifier: Apache-2.0
/* Octahedral kaleidoscopic IFS (after Knighty's KIFS family): six half-size octahedra at the
 * vertices of an octahedron, each made of six smaller ones, and so on; a twist per level turns it
 * into a coral of crystals.
 *
 * One iteration folds space into the octahedron's fundamental region x >= y >= z >= 0
 * (fold_menger: |p| with sorted coordinates, the 48 symmetries of the cube and octahedron),
 * optionally turns it, and scales it about the vertex `offset`:
 *
 *     z <- R fold(z) * scale - offset * (scale - 1)
 *
 * Folds and rotations are isometries and the scaling is undone at the end, so
 * sd_octahedron(z) / scale^n is a lower bound of the distance to the level-n set: no step factor
 * needed. As in the Menger scene, the loop carries w = z * scale^-i, which stays in p's units
 * instead of growing as scale^n. */

/* Orbit traps of the first levels only: finer ones would vary faster than a pixel. */
#define KIFS_TRAP_LEVELS 4

inline real kifs_iterate(vec3 p, PARAMS, int record, orbit_trap* trap) {
    const float scale = param_scale;
    const rotation3 twist = rotation_about_axis((float3)(0.0f, 0.0f, 1.0f), param_twist);
    const int twisted = param_twist != 0.0f;
    vec3 w = p;
    float size = 1.0f; /* scale^-i */
    for (int i = 0; i < param_iterations; ++i) {
        w = fold_menger(w);
        if (twisted) w = op_rotate(w, twist);
        size /= scale;
        w = v3_sub(w, v3_scale(param_offset, (scale - 1.0f) * size));
        if (record && i < KIFS_TRAP_LEVELS) {
            *trap = trap_update(*trap, v3_scale(w, 1.0f / size), FGR_TRUE);
        }
    }
    return sd_octahedron(w, size);
}

#define FGR_SCENE_HAS_COLOUR
FGR_TRAP_COLOURED_SCENE(kifs_iterate)
