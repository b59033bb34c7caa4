// SPDX-License-Identifier: Apache-2.0
/* fgr kernel library: fractal formulas shared by scenes.
 *
 * Mandelbulb: the iteration z -> z^n + c with z^n taken in spherical coordinates
 * (r, theta, phi) -> (r^n, n theta, n phi), and the analytic distance estimate
 * DE = 0.5 * log(r) * r / dr from the running derivative dr <- n r^(n-1) dr + 1.
 *
 * Two conventions for the polar angle:
 *   colatitude: theta = atan2(sqrt(x^2 + y^2), z), z^n = r^n (sin t cos p, sin t sin p, cos t)
 *   latitude:   theta = asin(z / r),              z^n = r^n (cos t cos p, cos t sin p, sin t)
 * The latitude form is Mandelbulber2's "Mandelbulb".
 *
 * For integer n the angle multiplications are done without trigonometry: with the unit complex
 * numbers e^(i phi) = (x + iy) / rho and e^(i theta) = (z + i rho) / r (colatitude) or
 * (rho + iz) / r (latitude), n phi and n theta are their n-th powers. Same map, a fraction of the
 * cost, and no atan2 branch cuts. */

typedef struct complex_packet {
    real re, im;
} complex_packet;

inline complex_packet complex_mul(complex_packet a, complex_packet b) {
    complex_packet c;
    c.re = a.re * b.re - a.im * b.im;
    c.im = a.re * b.im + a.im * b.re;
    return c;
}

/* a^n for integer n >= 1, by binary exponentiation (3 squarings for n = 8). */
FGR_POWER_FUNCTION complex_packet complex_powi(complex_packet a, int n) {
    complex_packet result = a;
    complex_packet base = a;
    int remaining = n - 1;
    FGR_BINARY_POWER(remaining, result = complex_mul(result, base), base = complex_mul(base, base))
    return result;
}

inline complex_packet unit_complex(real re, real im, real inv_len, real fallback_re) {
    complex_packet c;
    /* On the axis (length 0) the angle is atan2(0, 0) = 0: the unit number 1 + 0i. */
    c.re = select(re * inv_len, fallback_re, inv_len <= 0.0f);
    c.im = im * inv_len;
    return c;
}

inline real safe_inverse(real len) { return select(1.0f / len, fgr_real(0.0f), len <= 0.0f); }

/* z^n for integer n: r^n times the unit direction at angles (n theta, n phi). */
FGR_POWER_FUNCTION vec3 bulb_power_integer(vec3 z, real r, real r_n, int n, int latitude_form) {
    real rho = sqrt(z.x * z.x + z.y * z.y);
    complex_packet azimuth = complex_powi(unit_complex(z.x, z.y, safe_inverse(rho), 1.0f), n);
    real inv_r = safe_inverse(r);
    real horizontal, vertical; /* sin and cos of n theta for colatitude, cos and sin for latitude */
    if (latitude_form) {
        complex_packet polar = complex_powi(unit_complex(rho, z.z, inv_r, 1.0f), n);
        horizontal = polar.re;
        vertical = polar.im;
    } else {
        complex_packet polar = complex_powi(unit_complex(z.z, rho, inv_r, 1.0f), n);
        horizontal = polar.im;
        vertical = polar.re;
    }
    return v3_scale(v3(horizontal * azimuth.re, horizontal * azimuth.im, vertical), r_n);
}

/* a + i rho b with rho = |(x, y)| known only through rho^2. The square of z + i rho is
 * (z^2 - rho^2) + i rho (2 z), of this form, and products keep it:
 * (a + i rho b)(c + i rho d) = (ac - rho^2 bd) + i rho (ad + bc). So the even powers of the polar
 * base need no square root until the end. */
typedef struct rho_complex {
    real a, b;
} rho_complex;

inline rho_complex rho_complex_mul(rho_complex u, rho_complex v, real rho2) {
    rho_complex w;
    w.a = u.a * v.a - rho2 * (u.b * v.b);
    w.b = u.a * v.b + u.b * v.a;
    return w;
}

/* c^n for integer n >= 1, by binary exponentiation. */
FGR_POWER_FUNCTION rho_complex rho_complex_powi(rho_complex c, int n, real rho2) {
    rho_complex result = c;
    rho_complex base = c;
    int remaining = n - 1;
    FGR_BINARY_POWER(remaining, result = rho_complex_mul(result, base, rho2),
                     base = rho_complex_mul(base, base, rho2))
    return result;
}

/* z^n for integer n, as bulb_power_integer(z, |z|, |z|^n, n, latitude_form) gives it but without
 * r, with rho = |(x, y)|. The polar factor r^n e^(i n theta) is the n-th power of
 * z + i rho (colatitude) or rho + i z (latitude) itself, and the azimuth e^(i n phi) the n-th
 * power of (x + iy) / rho. For even n both are powers of squares that need only rho^2:
 * e^(2 i phi) = (x^2 - y^2 + 2ixy) / rho^2, one division, and the polar square in rho_complex
 * form, whose one factor rho is taken at the end, beside the chain. So an iteration's chain from
 * z to the next z holds a division but no square root. Odd n take rho and 1 / rho. */
FGR_POWER_FUNCTION vec3 bulb_integer_power(vec3 z, int n, int latitude_form) {
    const real x2 = z.x * z.x, y2 = z.y * z.y;
    const real rho2 = x2 + y2;
    /* Below 1e-30 the azimuth is taken as on the axis (atan2(0, 0) = 0): what that moves is at
     * most n |z|^(n-1) rho < 1e-14 |z|^(n-1). */
    const mask on_axis = rho2 < 1e-30f;
    real horizontal, vertical; /* r^n sin, cos of n theta (colatitude), cos, sin (latitude) */
    complex_packet azimuth;
    if ((n & 1) == 0) {
        const real inv_rho2 = select(1.0f / rho2, fgr_real(0.0f), on_axis);
        azimuth = complex_powi(unit_complex(x2 - y2, 2.0f * z.x * z.y, inv_rho2, 1.0f), n / 2);
        const real z2 = z.z * z.z;
        rho_complex square;
        square.a = latitude_form ? rho2 - z2 : z2 - rho2;
        square.b = 2.0f * z.z;
        const rho_complex polar = rho_complex_powi(square, n / 2, rho2);
        const real rho = sqrt(rho2);
        horizontal = latitude_form ? polar.a : rho * polar.b;
        vertical = latitude_form ? rho * polar.b : polar.a;
    } else {
        const real inv_rho = select(rsqrt(rho2), fgr_real(0.0f), on_axis);
        const real rho = rho2 * inv_rho;
        azimuth = complex_powi(unit_complex(z.x, z.y, inv_rho, 1.0f), n);
        complex_packet base;
        base.re = latitude_form ? rho : z.z;
        base.im = latitude_form ? z.z : rho;
        const complex_packet polar = complex_powi(base, n);
        horizontal = latitude_form ? polar.re : polar.im;
        vertical = latitude_form ? polar.im : polar.re;
    }
    return v3(horizontal * azimuth.re, horizontal * azimuth.im, vertical);
}

/* z^n for any real n, with trigonometry. At r = 0 every angle is finite (atan2(0, 0) = 0) and
 * r^n = 0, so the origin maps to the origin. */
inline vec3 bulb_power_real(vec3 z, real r, real r_n, float n, int latitude_form) {
    real phi = atan2(z.y, z.x) * n;
    real theta = latitude_form ? asin(clamp(z.z * safe_inverse(r), -1.0f, 1.0f)) * n
                               : atan2(sqrt(z.x * z.x + z.y * z.y), z.z) * n;
    real cos_phi = fgr_cos(phi), sin_phi = fgr_sin(phi);
    real cos_t = fgr_cos(theta), sin_t = fgr_sin(theta);
    real horizontal = latitude_form ? cos_t : sin_t;
    real vertical = latitude_form ? sin_t : cos_t;
    return v3_scale(v3(horizontal * cos_phi, horizontal * sin_phi, vertical), r_n);
}

/* One Mandelbulb iteration of orbit (z, dr, r) from c = p, for the lanes still inside the
 * bailout: z -> z^power + p and the running derivative, with integer_power choosing the
 * trigonometry-free form. */
#define FGR_BULB_ITERATE(integer_power, z, dr, r, p, active)              \
    do {                                                                  \
        real r_pow;                                                       \
        vec3 z_n;                                                         \
        if (integer_power) {                                              \
            r_pow = fgr_pown(r, (int)power - 1);                          \
            z_n = bulb_integer_power(z, (int)power, latitude_form);       \
        } else {                                                          \
            r_pow = fgr_pow(r, fgr_real(power - 1.0f));                   \
            z_n = bulb_power_real(z, r, r_pow * r, power, latitude_form); \
        }                                                                 \
        dr = select(dr, power * r_pow * dr + 1.0f, active);               \
        z = v3_select(z, v3_add(z_n, p), active);                         \
        r = v3_length(z);                                                 \
    } while (0)

/* The distance estimate from an orbit's last r and dr. r = 0 never escapes (the origin is
 * inside): distance 0, never log(0) * 0 = NaN. */
inline real bulb_distance(real r, real dr) {
    return select(0.5f * log(r) * r / dr, fgr_real(0.0f), r <= 0.0f);
}

/* The Mandelbulb's distance estimate at p: iterates z -> z^power + p at most `iterations` times
 * or until |z| > bailout, and returns 0.5 log(r) r / dr. When `record` is set it also fills *trap
 * with the orbit, for colouring. Integer and other powers iterate in loops of their own: with
 * the built-in pow, atan2 and asin of the general form inside the integer powers' loop, even on
 * a branch never taken, PoCL's code for it ran about 10% slower. */
inline real mandelbulb_de(vec3 p, float power, float bailout, int iterations, int latitude_form,
                          int record, orbit_trap* trap) {
    vec3 z = p;
    real dr = fgr_real(1.0f);
    real r = v3_length(z);
    if (power == floor(power)) {
        for (int i = 0; i < iterations; ++i) {
            const mask active = r <= bailout;
            if (!fgr_any(active)) break;
            FGR_BULB_ITERATE(1, z, dr, r, p, active);
            if (record) *trap = trap_update(*trap, z, active);
        }
    } else {
        for (int i = 0; i < iterations; ++i) {
            const mask active = r <= bailout;
            if (!fgr_any(active)) break;
            FGR_BULB_ITERATE(0, z, dr, r, p, active);
            if (record) *trap = trap_update(*trap, z, active);
        }
    }
    return bulb_distance(r, dr);
}

/* Both orbits while both have lanes inside the bailout, one iteration of each per pass, then
 * the one left on its own: two independent chains in one loop, which the processor overlaps
 * (an iteration waits on the latency of its square roots, division and squarings, not on the
 * arithmetic units). Each lane takes exactly the steps mandelbulb_de takes it. */
#define FGR_BULB_PAIR_LOOPS(integer_power)                                 \
    do {                                                                   \
        int i = 0;                                                         \
        for (; i < iterations; ++i) {                                      \
            const mask active_a = ra <= bailout, active_b = rb <= bailout; \
            if (!fgr_any(active_a) || !fgr_any(active_b)) break;           \
            FGR_BULB_ITERATE(integer_power, za, dra, ra, a, active_a);     \
            FGR_BULB_ITERATE(integer_power, zb, drb, rb, b, active_b);     \
        }                                                                  \
        for (int j = i; j < iterations; ++j) {                             \
            const mask active_a = ra <= bailout;                           \
            if (!fgr_any(active_a)) break;                                 \
            FGR_BULB_ITERATE(integer_power, za, dra, ra, a, active_a);     \
        }                                                                  \
        for (int j = i; j < iterations; ++j) {                             \
            const mask active_b = rb <= bailout;                           \
            if (!fgr_any(active_b)) break;                                 \
            FGR_BULB_ITERATE(integer_power, zb, drb, rb, b, active_b);     \
        }                                                                  \
    } while (0)

/* mandelbulb_de at two points at once (without the orbit trap), the same bits. */
inline void mandelbulb_de_pair(vec3 a, vec3 b, float power, float bailout, int iterations,
                               int latitude_form, real* da, real* db) {
    vec3 za = a, zb = b;
    real dra = fgr_real(1.0f), drb = fgr_real(1.0f);
    real ra = v3_length(za), rb = v3_length(zb);
    if (power == floor(power)) {
        FGR_BULB_PAIR_LOOPS(1);
    } else {
        FGR_BULB_PAIR_LOOPS(0);
    }
    *da = bulb_distance(ra, dra);
    *db = bulb_distance(rb, drb);
}
