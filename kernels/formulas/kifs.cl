/* fgr formula library: kaleidoscopic IFS (Knighty, "Kaleidoscopic (escape time) IFS",
 * fractalforums.com 2010). A fold into the symmetry group's fundamental region (an isometry), an
 * optional rotation, and a scale about a vertex: z <- s R fold(z) - offset (s - 1). No + c: the
 * attractor is the same for every point; dr counts the scale. Alone, each measures the distance
 * to its level-n shapes, the base solid at the orbit's end divided by dr
 * (formula_NAME_distance: exact for the folds are isometries); in a hybrid, r / dr. */

/* Menger sponge (Knighty's Menger KIFS): the cube's fold (|z| sorted x >= y >= z), scale 3 about
 * (1, 1, 1), and the middle layer pulled back so the holes go through. */
inline void formula_menger(vec3* z, real* w, real* dr, const vec3 c, float scale, vec3 offset,
                           rotation3 turn) {
    (void)w;
    (void)c;
    vec3 p = op_rotate(fold_menger(*z), turn);
    p = v3_sub(v3_scale(p, fgr_real(scale)), v3_scale(offset, fgr_real(scale - 1.0f)));
    const real middle = 0.5f * offset.z * (scale - 1.0f);
    p.z = select(p.z, p.z + offset.z * (scale - 1.0f), p.z < -middle);
    *z = p;
    *dr *= scale;
}

/* Sierpinski tetrahedron: reflections across x = -y, x = -z, y = -z, scale 2 about (1, 1, 1). */
inline void formula_sierpinski(vec3* z, real* w, real* dr, const vec3 c, float scale,
                               vec3 offset, rotation3 turn) {
    (void)w;
    (void)c;
    const vec3 p = op_rotate(fold_sierpinski(*z), turn);
    *z = v3_sub(v3_scale(p, fgr_real(scale)), v3_scale(offset, fgr_real(scale - 1.0f)));
    *dr *= scale;
}

/* Octahedral KIFS: the octahedron's (the cube's) fold, scale 2 about a vertex (1, 0, 0). */
inline void formula_octahedral(vec3* z, real* w, real* dr, const vec3 c, float scale,
                               vec3 offset, rotation3 turn) {
    (void)w;
    (void)c;
    const vec3 p = op_rotate(fold_menger(*z), turn);
    *z = v3_sub(v3_scale(p, fgr_real(scale)), v3_scale(offset, fgr_real(scale - 1.0f)));
    *dr *= scale;
}

/* Icosahedral KIFS: the icosahedral fold, scale about the icosahedron's vertex (times `size`). */
inline void formula_icosahedral(vec3* z, real* w, real* dr, const vec3 c, float scale,
                                float size, rotation3 turn) {
    (void)w;
    (void)c;
    const vec3 p = op_rotate(fold_icosahedral(*z), turn);
    *z = scale_about(p, fgr_real(scale), v3_scale(icosahedron_vertex(), fgr_real(size)));
    *dr *= scale;
}

/* Dodecahedral KIFS: the same fold, scale about the dodecahedron's vertex (times `size`). */
inline void formula_dodecahedral(vec3* z, real* w, real* dr, const vec3 c, float scale,
                                 float size, rotation3 turn) {
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

inline real formula_sierpinski_distance(vec3 z, real w, real dr, vec3 c, float scale,
                                        vec3 offset) {
    (void)w;
    (void)c;
    (void)scale;
    (void)offset;
    return sd_tetrahedron(z, 1.0f) / dr;
}

inline real formula_octahedral_distance(vec3 z, real w, real dr, vec3 c, float scale,
                                        vec3 offset) {
    (void)w;
    (void)c;
    (void)scale;
    (void)offset;
    return sd_octahedron(z, 1.0f) / dr;
}

inline real formula_icosahedral_distance(vec3 z, real w, real dr, vec3 c, float scale,
                                         float size) {
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
