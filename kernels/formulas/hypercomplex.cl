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

/* The bicomplex square: (z1 + j z2)^2 = (z1^2 - z2^2) + j (2 z1 z2) with z1 = x + iy, z2 = z + iw
 * (Segre's bicomplex numbers; the "Tetrabrot" of Rochon, 2000). Products of bicomplex numbers
 * stretch lengths by up to sqrt(2) |a| |b|: the derivative carries that factor, so the estimate
 * stays a bound. */
inline void bicomplex_square(vec3* z, real* w) {
    const vec3 p = *z;
    const real a = p.x, b = p.y, e = p.z, f = *w;
    *z = v3(a * a - b * b - e * e + f * f, 2.0f * (a * b - e * f), 2.0f * (a * e - b * f));
    *w = 2.0f * (a * f + b * e);
}

/* Bicomplex Mandelbrot set (the Tetrabrot, Rochon 2000): Z <- Z^2 + c. */
inline void formula_bicomplex(vec3* z, real* w, real* dr, const vec3 c) {
    *dr = 2.0f * M_SQRT2_F * quaternion_length(*z, *w) * *dr + 1.0f;
    bicomplex_square(z, w);
    *z = v3_add(*z, c);
}

/* Bicomplex Julia set: Z <- Z^2 + k. */
inline void formula_bicomplex_julia(vec3* z, real* w, real* dr, const vec3 c, vec3 julia,
                                    float julia_w) {
    (void)c;
    *dr = 2.0f * M_SQRT2_F * quaternion_length(*z, *w) * *dr;
    bicomplex_square(z, w);
    *z = v3_add(*z, julia);
    *w += julia_w;
}

/* Z^n of the bicomplex Z = z1 + j z2 through its idempotent parts u = z1 - i z2 and
 * v = z1 + i z2, where products act part by part: Z^n = ((u^n + v^n) + j i (u^n - v^n)) / 2
 * (Rochon's multibrots, 2000). */
inline void bicomplex_power(vec3* z, real* w, int n) {
    const vec3 p = *z;
    complex_packet u, v;
    u.re = p.x + *w, u.im = p.y - p.z;  /* z1 - i z2, z2 = z + i w */
    v.re = p.x - *w, v.im = p.y + p.z;  /* z1 + i z2 */
    const complex_packet un = complex_powi(u, n), vn = complex_powi(v, n);
    /* z1 = (u + v) / 2, z2 = i (u - v) / 2 */
    *z = v3(0.5f * (un.re + vn.re), 0.5f * (un.im + vn.im), -0.5f * (un.im - vn.im));
    *w = 0.5f * (un.re - vn.re);
}

/* Bicomplex multibrot: Z <- Z^n + c (Rochon 2000), the Tetrabrot at n = 2. */
inline void formula_bicomplex_power(vec3* z, real* w, real* dr, const vec3 c, float power) {
    const int n = (int)power;
    const real r = quaternion_length(*z, *w);
    *dr = (float)n * M_SQRT2_F * fgr_pown(M_SQRT2_F * r, n - 1) * *dr + 1.0f;
    bicomplex_power(z, w, n);
    *z = v3_add(*z, c);
}

/* Quaternion power q^n + c by the polar form q = |q| (cos t + u sin t), u the unit imaginary
 * direction: q^n = |q|^n (cos nt + u sin nt). */
inline void formula_quaternion_power(vec3* z, real* w, real* dr, const vec3 c, float power) {
    const vec3 p = *z;
    const real r = quaternion_length(p, *w);
    const real v = sqrt(p.y * p.y + p.z * p.z + *w * *w);
    const real t = atan2(v, p.x) * power;
    const real r_pow = fgr_pow(r, fgr_real(power - 1.0f));
    const real rn = r_pow * r;
    /* along the real axis (v = 0) the direction is irrelevant: sin(nt) = 0 there */
    const real k = select(rn * fgr_sin(t) / v, fgr_real(0.0f), v <= 0.0f);
    *dr = power * r_pow * *dr + 1.0f;
    *z = v3_add(v3(rn * fgr_cos(t), k * p.y, k * p.z), c);
    *w = k * *w;
}
