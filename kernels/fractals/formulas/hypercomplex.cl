// SPDX-License-Identifier: Apache-2.0
/* fgr formula library: hypercomplex numbers. Four-dimensional algebras iterated from (c, 0), the
 * image their slice w = 0 (the fourth component, carried in w). Polynomial maps: the distance is
 * the logarithmic estimate with r the four-dimensional length (Hart, Sandin and Kauffman,
 * "Ray tracing deterministic 3-D fractals", SIGGRAPH 1989, for the quaternion Julia sets). */

/* q^2 of the quaternion (x, y, z, w) = (x, v): (x^2 - |v|^2, 2 x v). */
inline void quaternion_square(vec3* z, real* w) {
    const vec3 p = *z;
    const real x2 = p.x * p.x - p.y * p.y - p.z * p.z - *w * *w;
    *z = v3(x2, 2.0f * p.x * p.y, 2.0f * p.x * p.z);
    *w = 2.0f * p.x * *w;
}

/* q^3 = (x^3 - 3 x |v|^2, (3 x^2 - |v|^2) v). */
inline void quaternion_cube(vec3* z, real* w) {
    const vec3 p = *z;
    const real v2 = p.y * p.y + p.z * p.z + *w * *w;
    const real k = 3.0f * p.x * p.x - v2;
    *z = v3(p.x * (p.x * p.x - 3.0f * v2), k * p.y, k * p.z);
    *w = k * *w;
}

inline real quaternion_length(vec3 z, real w) { return sqrt(v3_length2(z) + w * w); }

/* Quaternion Mandelbrot set: q <- q^2 + c. */
inline void formula_quaternion(vec3* z, real* w, real* dr, const vec3 c) {
    *dr = 2.0f * quaternion_length(*z, *w) * *dr + 1.0f;
    quaternion_square(z, w);
    *z = v3_add(*z, c);
}

/* Quaternion Julia set (Norton 1982; Hart, Sandin and Kauffman 1989): q <- q^2 + k for a fixed
 * quaternion k = (julia, julia_w). */
inline void formula_quaternion_julia(vec3* z, real* w, real* dr, const vec3 c, vec3 julia,
                                     float julia_w) {
    (void)c;
    *dr = 2.0f * quaternion_length(*z, *w) * *dr;
    quaternion_square(z, w);
    *z = v3_add(*z, julia);
    *w += julia_w;
}

/* Cubic quaternion Mandelbrot set: q <- q^3 + c. */
inline void formula_quaternion_cubic(vec3* z, real* w, real* dr, const vec3 c) {
    const real r = quaternion_length(*z, *w);
    *dr = 3.0f * r * r * *dr + 1.0f;
    quaternion_cube(z, w);
    *z = v3_add(*z, c);
}

/* Cubic quaternion Julia set: q <- q^3 + k. */
inline void formula_quaternion_cubic_julia(vec3* z, real* w, real* dr, const vec3 c, vec3 julia,
                                           float julia_w) {
    (void)c;
    const real r = quaternion_length(*z, *w);
    *dr = 3.0f * r * r * *dr;
    quaternion_cube(z, w);
    *z = v3_add(*z, julia);
    *w += julia_w;
}

/* Quaternion power q^n + c by the polar form q = |q| (cos t + u sin t), u the unit imaginary
 * direction: q^n = |q|^n (cos nt + u sin nt). */
inline vec3 quaternion_power(vec3 p, real* w, float power, real* r_pow) {
    const real r = quaternion_length(p, *w);
    const real v = sqrt(p.y * p.y + p.z * p.z + *w * *w);
    const real t = atan2(v, p.x) * power;
    *r_pow = fgr_pow(r, fgr_real(power - 1.0f));
    const real rn = *r_pow * r;
    /* along the real axis (v = 0) the direction is irrelevant: sin(nt) = 0 there */
    const real k = select(rn * fgr_sin(t) / v, fgr_real(0.0f), v <= 0.0f);
    *w = k * *w;
    return v3(rn * fgr_cos(t), k * p.y, k * p.z);
}

inline void formula_quaternion_power(vec3* z, real* w, real* dr, const vec3 c, float power) {
    real r_pow;
    *z = v3_add(quaternion_power(*z, w, power, &r_pow), c);
    *dr = power * r_pow * *dr + 1.0f;
}

/* Quaternion power Julia set: q^n + k. */
inline void formula_quaternion_power_julia(vec3* z, real* w, real* dr, const vec3 c, float power,
                                           vec3 julia, float julia_w) {
    (void)c;
    real r_pow;
    *z = v3_add(quaternion_power(*z, w, power, &r_pow), julia);
    *w += julia_w;
    *dr = power * r_pow * *dr;
}

/* The orbit's estimate 0.5 r log(r) / dr is G / (2 |G'|) for the potential G = log(r) / 2^n
 * (potential_scale 2^-n after n steps). Near the set (G -> 0) it is the distance; far out it
 * grows like r log r, faster than the distance. Koebe's bound (Hubbard and Douady's for the
 * Mandelbrot set, the same for Julia sets), sinh(G) / (2 e^G |G'|), is the same near the set and
 * saturates far out: it is the estimate times (1 - e^(-2G)) / (2G). Negative where the orbit
 * ended inside the unit circle. */
inline real formula_potential_bound(real r, real dr, real potential_scale) {
    const real log_r = log(r);
    const real potential = log_r * potential_scale;
    const real estimate = 0.5f * r * log_r / dr;
    const real koebe_factor = (1.0f - exp(-2.0f * potential)) / (2.0f * potential);
    /* Inside (r < 1) and at G -> 0 the factor is 1; r = 0 or dr = 0 only occur inside. */
    const real bound = select(estimate, estimate * koebe_factor, potential > 1e-4f);
    return select(bound, fgr_real(0.0f), (r <= 0.0f) | (dr <= 0.0f));
}

/* The bicomplex numbers (Corrado Segre, 1892; the 3D slices of their Mandelbrot set are Dominic
 * Rochon's Tetrabrot, 2000): z1 + z2 j with z1 = x + i y, z2 = z + i w and i j = j i, j^2 = -1,
 * so (z1 + z2 j)^2 = (z1^2 - z2^2) + 2 z1 z2 j. The product commutes but is not conformal (it
 * has zero divisors): no scalar running derivative bounds the distance, and dr here is only a
 * growth measure (a hybrid with a bicomplex formula is an inside test). Alone they measure
 * their own distance, in idempotent coordinates: z1 + z2 j = u e1 + v e2 with
 * u = (x + w) + i (y - z), v = (x - w) + i (y + z) and e1, e2 = (1 +- i j) / 2, products act on u
 * and v apart, so the set is where two complex orbits stay bounded: on a 3D slice, two cylinders
 * over complex Mandelbrot or Julia sets meeting. The distance to their intersection is at least
 * the larger of the distances to each cylinder, and a cylinder's is at least the distance of u
 * (or v) to its complex set over sqrt(2), the most u moves per unit step of the point. */
inline void bicomplex_square(vec3* z, real* w) {
    const vec3 p = *z;
    const real q = *w;
    *z = v3(p.x * p.x - p.y * p.y - p.z * p.z + q * q, 2.0f * (p.x * p.y - p.z * q),
            2.0f * (p.x * p.z - p.y * q));
    *w = 2.0f * (p.x * q + p.y * p.z);
}

/* Koebe's lower bound on the distance from u to the complex Mandelbrot set (k = u, mandelbrot
 * set) or the Julia set of k, from the orbit u <- u^2 + k and its derivative by the start,
 * u' <- 2 u u' (+ 1 for the Mandelbrot set, where k moves with the start), stopping past
 * `bailout`. */
inline real complex_set_distance(complex_packet u, complex_packet k, int mandelbrot, int iterations,
                                 float bailout) {
    complex_packet du = {fgr_real(1.0f), fgr_real(0.0f)};
    real potential_scale = fgr_real(1.0f);
    real r2 = u.re * u.re + u.im * u.im;
    const float bailout2 = bailout * bailout;
    for (int i = 0; i < iterations; ++i) {
        const mask active = r2 <= bailout2;
        if (!fgr_any(active)) break;
        const complex_packet u_du = complex_mul(u, du);
        const complex_packet u2 = complex_mul(u, u);
        du.re = select(du.re, 2.0f * u_du.re + (mandelbrot ? 1.0f : 0.0f), active);
        du.im = select(du.im, 2.0f * u_du.im, active);
        u.re = select(u.re, u2.re + k.re, active);
        u.im = select(u.im, u2.im + k.im, active);
        potential_scale = select(potential_scale, 0.5f * potential_scale, active);
        r2 = u.re * u.re + u.im * u.im;
    }
    return formula_potential_bound(sqrt(r2), sqrt(du.re * du.re + du.im * du.im), potential_scale);
}

/* The bicomplex point (x, y, z, w)'s idempotent parts: u = (x + w) + i (y - z) and
 * v = (x - w) + i (y + z). */
inline complex_packet idempotent_u(vec3 p, real w) {
    const complex_packet u = {p.x + w, p.y - p.z};
    return u;
}

inline complex_packet idempotent_v(vec3 p, real w) {
    const complex_packet v = {p.x - w, p.y + p.z};
    return v;
}

/* Tetrabrot: the bicomplex Mandelbrot set z^2 + c, on the slice w = 0 (Rochon 2000). */
inline void formula_tetrabrot(vec3* z, real* w, real* dr, const vec3 c) {
    *dr = 2.0f * quaternion_length(*z, *w) * *dr + 1.0f;
    bicomplex_square(z, w);
    *z = v3_add(*z, c);
}

inline real formula_tetrabrot_distance(vec3 z, real w, real dr, vec3 c, int iterations,
                                       float bailout) {
    (void)z;
    (void)w;
    (void)dr;
    const complex_packet u = idempotent_u(c, fgr_real(0.0f)), v = idempotent_v(c, fgr_real(0.0f));
    const real du = complex_set_distance(u, u, 1, iterations, bailout);
    const real dv = complex_set_distance(v, v, 1, iterations, bailout);
    /* Where both orbits stay bounded the point is in the set: 0, not the estimates' negative
     * values (orbits ending inside the unit circle). */
    return fmax(fmax(du, dv), fgr_real(0.0f)) * M_SQRT1_2_F;
}

/* Bicomplex Julia set: z^2 + k for a fixed bicomplex k. */
inline void formula_bicomplex_julia(vec3* z, real* w, real* dr, const vec3 c, vec3 julia,
                                    float julia_w) {
    (void)c;
    *dr = 2.0f * quaternion_length(*z, *w) * *dr;
    bicomplex_square(z, w);
    *z = v3_add(*z, julia);
    *w += julia_w;
}

inline real formula_bicomplex_julia_distance(vec3 z, real w, real dr, vec3 c, vec3 julia,
                                             float julia_w, int iterations, float bailout) {
    (void)z;
    (void)w;
    (void)dr;
    const real julia_w_packet = fgr_real(julia_w);
    const real du =
        complex_set_distance(idempotent_u(c, fgr_real(0.0f)), idempotent_u(julia, julia_w_packet),
                             0, iterations, bailout);
    const real dv =
        complex_set_distance(idempotent_v(c, fgr_real(0.0f)), idempotent_v(julia, julia_w_packet),
                             0, iterations, bailout);
    /* Where both orbits stay bounded the point is in the set: 0, not the estimates' negative
     * values (orbits ending inside the unit circle). */
    return fmax(fmax(du, dv), fgr_real(0.0f)) * M_SQRT1_2_F;
}
