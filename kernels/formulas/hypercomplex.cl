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

/* The bicomplex numbers (Corrado Segre, 1892; the 3D slices of their Mandelbrot set are Dominic
 * Rochon's Tetrabrot, 2000): z1 + z2 j with z1 = x + i y, z2 = z + i w and i j = j i, j^2 = -1,
 * so (z1 + z2 j)^2 = (z1^2 - z2^2) + 2 z1 z2 j. Unlike the quaternions' the product commutes but
 * is not conformal (it has zero divisors), so no scalar running derivative bounds the distance:
 * the bicomplex formulas' scenes are inside tests for the brute-force mode, and dr here is only a
 * growth measure. */
inline void bicomplex_square(vec3* z, real* w) {
    const vec3 p = *z;
    const real q = *w;
    *z = v3(p.x * p.x - p.y * p.y - p.z * p.z + q * q, 2.0f * (p.x * p.y - p.z * q),
            2.0f * (p.x * p.z - p.y * q));
    *w = 2.0f * (p.x * q + p.y * p.z);
}

/* Tetrabrot: the bicomplex Mandelbrot set z^2 + c, on the slice w = 0 (Rochon 2000). */
inline void formula_tetrabrot(vec3* z, real* w, real* dr, const vec3 c) {
    *dr = 2.0f * quaternion_length(*z, *w) * *dr + 1.0f;
    bicomplex_square(z, w);
    *z = v3_add(*z, c);
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
