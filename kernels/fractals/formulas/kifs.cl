// SPDX-License-Identifier: Apache-2.0
/* fgr formula library: kaleidoscopic IFS (Knighty, "Kaleidoscopic (escape time) IFS",
 * fractalforums.com 2010). A fold into the symmetry group's fundamental region (an isometry), an
 * optional rotation, and a scale about a vertex: z <- s R fold(z) - offset (s - 1). No + c: the
 * attractor is the same for every point; dr counts the scale. Alone, each measures the distance
 * to its level-n shapes, the base solid at the orbit's end divided by dr
 * (formula_NAME_distance: exact for the folds are isometries); in a hybrid, r / dr. */

/* A KIFS step before its scale: the fold, the turn, and the offset times `shift` taken off. The
 * formulas below are it times the scale, with shift (scale - 1) / scale. The menger and
 * sierpinski scenes (plugins/) iterate it on z_i scale^-i instead, with shift
 * (scale - 1) scale^-(i+1): the same map in the point's own units, which stays a float for any
 * number of steps where z_i itself overflows. */

/* Menger sponge (Knighty's Menger KIFS): the cube's fold (|z| sorted x >= y >= z), scale 3 about
 * (1, 1, 1), and the middle layer pulled back so the holes go through. */
inline vec3 formula_menger_step(vec3 p, rotation3 turn, vec3 offset, float shift) {
    p = v3_sub(op_rotate(fold_menger(p), turn), v3_scale(offset, fgr_real(shift)));
    p.z = select(p.z, p.z + offset.z * shift, p.z < -0.5f * offset.z * shift);
    return p;
}

inline void formula_menger(vec3* z, real* w, real* dr, const vec3 c, float scale, vec3 offset,
                           rotation3 turn) {
    (void)w;
    (void)c;
    *z = v3_scale(formula_menger_step(*z, turn, offset, (scale - 1.0f) / scale), fgr_real(scale));
    *dr *= scale;
}

/* Sierpinski tetrahedron: reflections across x = -y, x = -z, y = -z, scale 2 about (1, 1, 1). */
inline vec3 formula_sierpinski_step(vec3 p, rotation3 turn, vec3 offset, float shift) {
    return v3_sub(op_rotate(fold_sierpinski(p), turn), v3_scale(offset, fgr_real(shift)));
}

inline void formula_sierpinski(vec3* z, real* w, real* dr, const vec3 c, float scale, vec3 offset,
                               rotation3 turn) {
    (void)w;
    (void)c;
    *z = v3_scale(formula_sierpinski_step(*z, turn, offset, (scale - 1.0f) / scale),
                  fgr_real(scale));
    *dr *= scale;
}

/* Octahedral KIFS: the octahedron's (the cube's) fold, scale 2 about a vertex (1, 0, 0). */
inline void formula_octahedral(vec3* z, real* w, real* dr, const vec3 c, float scale, vec3 offset,
                               rotation3 turn) {
    (void)w;
    (void)c;
    const vec3 p = op_rotate(fold_menger(*z), turn);
    *z = v3_sub(v3_scale(p, fgr_real(scale)), v3_scale(offset, fgr_real(scale - 1.0f)));
    *dr *= scale;
}

/* Icosahedral KIFS: the icosahedral fold, scale about the icosahedron's vertex (times `size`). */
inline void formula_icosahedral(vec3* z, real* w, real* dr, const vec3 c, float scale, float size,
                                rotation3 turn) {
    (void)w;
    (void)c;
    const vec3 p = op_rotate(fold_icosahedral(*z), turn);
    *z = scale_about(p, fgr_real(scale), v3_scale(icosahedron_vertex(), fgr_real(size)));
    *dr *= scale;
}

/* Dodecahedral KIFS: the same fold, scale about the dodecahedron's vertex (times `size`). */
inline void formula_dodecahedral(vec3* z, real* w, real* dr, const vec3 c, float scale, float size,
                                 rotation3 turn) {
    (void)w;
    (void)c;
    const vec3 p = op_rotate(fold_dodecahedral(*z), turn);
    *z = scale_about(p, fgr_real(scale), v3_scale(dodecahedron_vertex(), fgr_real(size)));
    *dr *= scale;
}

/* Cantor dust: the octant's fold (|z|) and a scale of 3 about (1, 1, 1), so each cube keeps its
 * eight corner cubes. */
inline void formula_cantor_dust(vec3* z, real* w, real* dr, const vec3 c, float scale,
                                vec3 offset) {
    (void)w;
    (void)c;
    *z = v3_sub(v3_scale(v3_abs(*z), fgr_real(scale)), v3_scale(offset, fgr_real(scale - 1.0f)));
    *dr *= scale;
}

/* The level-n cubes, tetrahedra, octahedra and spheres the KIFS above are made of. */
inline real formula_cantor_dust_distance(vec3 z, real w, real dr, vec3 c, float scale,
                                         vec3 offset) {
    (void)w;
    (void)c;
    (void)scale;
    (void)offset;
    return sd_box(z, v3_splat(1.0f, 1.0f, 1.0f)) / dr;
}

inline real formula_menger_distance(vec3 z, real w, real dr, vec3 c, float scale, vec3 offset) {
    (void)w;
    (void)c;
    (void)scale;
    (void)offset;
    return sd_box(z, v3_splat(1.0f, 1.0f, 1.0f)) / dr;
}

inline real formula_sierpinski_distance(vec3 z, real w, real dr, vec3 c, float scale, vec3 offset) {
    (void)w;
    (void)c;
    (void)scale;
    (void)offset;
    return sd_tetrahedron(z, 1.0f) / dr;
}

inline real formula_octahedral_distance(vec3 z, real w, real dr, vec3 c, float scale, vec3 offset) {
    (void)w;
    (void)c;
    (void)scale;
    (void)offset;
    return sd_octahedron(z, 1.0f) / dr;
}

inline real formula_icosahedral_distance(vec3 z, real w, real dr, vec3 c, float scale, float size) {
    (void)w;
    (void)c;
    (void)scale;
    return (v3_length(z) - size) / dr;
}

inline real formula_dodecahedral_distance(vec3 z, real w, real dr, vec3 c, float scale,
                                          float size) {
    (void)w;
    (void)c;
    (void)scale;
    return (v3_length(z) - size) / dr;
}
