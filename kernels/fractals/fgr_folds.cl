// SPDX-License-Identifier: Apache-2.0
/* fgr kernel library: space folds for IFS and Mandelbox-type fractals.
 *
 * A fold maps space onto a fundamental region, so one copy of the geometry stands for many. Folds
 * that are reflections (plane, box, Sierpinski, Menger, abs) are isometries: they preserve
 * distances, so a DE evaluated after them needs no correction. The sphere fold scales space and
 * reports its scale through `dr`, which the caller divides the distance by. */

/* Reflects p across the plane through the origin with unit normal n, for points on its negative
 * side (dot(p, n) < 0). */
inline vec3 fold_plane(vec3 p, vec3 n) {
    real side = fmin(v3_dot(p, n), 0.0f);
    return v3_mad(p, n, -2.0f * side);
}

/* Reflects each coordinate into the positive octant: p -> |p|. */
inline vec3 fold_abs(vec3 p) { return v3_abs(p); }

/* Box fold (Mandelbox): each coordinate beyond +-limit is reflected back about the limit. */
inline vec3 fold_box(vec3 p, float limit) {
    return v3(clamp(p.x, -limit, limit) * 2.0f - p.x, clamp(p.y, -limit, limit) * 2.0f - p.y,
              clamp(p.z, -limit, limit) * 2.0f - p.z);
}

/* Sphere fold (Mandelbox): inside min_radius scale by fixed^2/min^2, between min and fixed radius
 * invert in the sphere of radius fixed_radius, outside leave alone. Multiplies *dr by the local
 * scale so the caller's DE stays a bound. Radii are squared: min_radius2 <= fixed_radius2. */
inline vec3 fold_sphere(vec3 p, real* dr, float min_radius2, float fixed_radius2) {
    real r2 = v3_length2(p);
    real scale = select(fgr_real(1.0f), fixed_radius2 / fmax(r2, min_radius2), r2 < fixed_radius2);
    *dr *= scale;
    return v3_scale(p, scale);
}

/* Sierpinski tetrahedron fold: reflections across the planes x = -y, x = -z, y = -z map every
 * point to the region nearest the (1, 1, 1) corner. */
inline vec3 fold_sierpinski(vec3 p) {
    mask m = p.x + p.y < 0.0f;
    vec3 q = v3_select(p, v3(-p.y, -p.x, p.z), m);
    m = q.x + q.z < 0.0f;
    q = v3_select(q, v3(-q.z, q.y, -q.x), m);
    m = q.y + q.z < 0.0f;
    return v3_select(q, v3(q.x, -q.z, -q.y), m);
}

/* Menger fold: |p| with the coordinates sorted so x >= y >= z (reflections across x = y, x = z
 * and y = z), the symmetry of the cube. */
inline vec3 fold_menger(vec3 p) {
    vec3 a = v3_abs(p);
    mask m = a.x < a.y;
    a = v3_select(a, v3(a.y, a.x, a.z), m);
    m = a.x < a.z;
    a = v3_select(a, v3(a.z, a.y, a.x), m);
    m = a.y < a.z;
    return v3_select(a, v3(a.x, a.z, a.y), m);
}

#if FGR_KERNEL_API >= 2
/* Per-axis box fold (Mandelbox "ABox", Knighty's pseudo-Kleinian): coordinate i beyond +-limit.i
 * is reflected back about it. `limit` is a vec3: v3_uniform(param_<id>) from a vec3 parameter
 * (kernel API 4; API 2 and 3 pass the parameter itself). An isometry. */
inline vec3 fold_box_axes(vec3 p, vec3 limit) {
    return v3(clamp(p.x, -limit.x, limit.x) * 2.0f - p.x,
              clamp(p.y, -limit.y, limit.y) * 2.0f - p.y,
              clamp(p.z, -limit.z, limit.z) * 2.0f - p.z);
}

/* Icosahedral fold: maps p into one fundamental region of the icosahedron's symmetry group (H3,
 * the 120 reflections and rotations of the icosahedron and of its dual, the dodecahedron). The
 * region is bounded by the planes x = 0, y = 0 and the plane with unit normal
 * n = (-1/2, -cos(pi/5), sin(pi/10)); reflecting across them in turn five times reaches it from
 * anywhere (after Knighty's polyhedra folds). Its corners point at the symmetric shapes' features:
 * icosahedron_vertex() (a 5-fold axis, a dodecahedron face centre), dodecahedron_vertex() (a 3-fold
 * axis, an icosahedron face centre) and (0, 0, 1) (an edge midpoint of both). An isometry. */
#define FGR_ICOSAHEDRAL_MIRROR_X -0.5f
#define FGR_ICOSAHEDRAL_MIRROR_Y -0.80901699f
#define FGR_ICOSAHEDRAL_MIRROR_Z 0.30901699f
inline vec3 fold_icosahedral(vec3 p) {
    const vec3 mirror =
        v3_splat(FGR_ICOSAHEDRAL_MIRROR_X, FGR_ICOSAHEDRAL_MIRROR_Y, FGR_ICOSAHEDRAL_MIRROR_Z);
    for (int i = 0; i < 5; ++i) {
        p.x = fabs(p.x);
        p.y = fabs(p.y);
        p = fold_plane(p, mirror);
    }
    return p;
}
/* The dodecahedron has the icosahedron's symmetry group: the same fold, under the name a
 * dodecahedral KIFS reads best with (scale about dodecahedron_vertex()). */
#define fold_dodecahedral fold_icosahedral

/* Unit directions of the icosahedral fold's region corners (see fold_icosahedral). */
inline vec3 icosahedron_vertex(void) { return v3_splat(0.52573111f, 0.0f, 0.85065081f); }
inline vec3 dodecahedron_vertex(void) { return v3_splat(0.0f, 0.35682209f, 0.93417236f); }

/* Sphere inversion about `centre` with `radius`:
 *     p -> centre + radius^2 (p - centre) / |p - centre|^2,
 * the map of Kleinian and Apollonian fractals. |p - centre| is read as at least min_radius, so the
 * centre goes to a finite point and nothing divides by zero. Lengths near p scale by
 * radius^2 / |p - centre|^2: *dr is multiplied by it, so a DE divided by dr stays a bound. */
inline vec3 invert_sphere(vec3 p, real* dr, vec3 centre, float radius, float min_radius) {
    const vec3 q = v3_sub(p, centre);
    const real scale = (radius * radius) / fmax(v3_length2(q), fgr_real(min_radius * min_radius));
    *dr *= scale;
    return v3_mad(centre, q, scale);
}

/* The KIFS step: z scaled by s about `centre` (z s - centre (s - 1)); centre stays where it is. */
inline vec3 scale_about(vec3 z, real s, vec3 centre) {
    return v3_sub(v3_scale(z, s), v3_scale(centre, s - 1.0f));
}
#endif
