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
