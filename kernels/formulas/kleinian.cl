/* fgr formula library: Kleinian-group limit sets, by folds and sphere inversions. Their
 * distances are to thin surfaces around the orbit's end, divided by how much the inversions
 * magnified space: each formula here names its own (formula_NAME_distance), which a scene uses
 * when the formula is its only one. */

/* Pseudo-Kleinian (Knighty, fractalforums.com 2011; the SDK guide's example): a per-axis box fold,
 * an inversion in the sphere of squared radius `size`, and an offset. */
inline void formula_pseudo_kleinian(vec3* z, real* w, real* dr, const vec3 c, vec3 box,
                                    float size, vec3 offset, float thickness) {
    (void)w;
    (void)c;
    (void)thickness;
    vec3 p = fold_box_axes(*z, box);
    p = fold_sphere(p, dr, 1e-6f, size);
    *z = v3_add(p, offset);
}

/* Knighty's "thingy": the surface |rxy z| = thickness, its distance roughly (|rxy z| - t) / |z|. */
inline real formula_pseudo_kleinian_distance(vec3 z, real w, real dr, vec3 c, vec3 box,
                                             float size, vec3 offset, float thickness) {
    (void)w;
    (void)c;
    (void)box;
    (void)size;
    (void)offset;
    const real rxy = sqrt(z.x * z.x + z.y * z.y);
    return 0.5f * (fabs(rxy * z.z) - thickness) /
           sqrt(v3_length2(z) + thickness + 1e-20f) / dr;
}

/* Apollonian gasket (after Paul Nylander's and Knighty's sphere-inversion form, 2010): space
 * folded into the unit cell [-1, 1]^3 and inverted in the sphere of squared radius `size`, over
 * and over; the packing's spheres are where the orbit lands near the plane y = 0. */
inline void formula_apollonian(vec3* z, real* w, real* dr, const vec3 c, float size) {
    (void)w;
    (void)c;
    vec3 p = *z;
    p = v3(p.x - 2.0f * floor(0.5f * p.x + 0.5f), p.y - 2.0f * floor(0.5f * p.y + 0.5f),
           p.z - 2.0f * floor(0.5f * p.z + 0.5f));
    const real k = size / fmax(v3_length2(p), fgr_real(1e-12f));
    *z = v3_scale(p, k);
    *dr *= k;
}

/* The packing fills space: cut to the cube of one cell, [-1, 1]^3, so it can be seen from
 * outside (the intersection of two bounds is a bound). */
inline real formula_apollonian_distance(vec3 z, real w, real dr, vec3 c, float size) {
    (void)w;
    (void)size;
    return fmax(0.25f * fabs(z.y) / dr, sd_box(c, v3_splat(1.0f, 1.0f, 1.0f)));
}
