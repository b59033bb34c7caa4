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
    FGR_POWER_STEPS_AHEAD(remaining, result = complex_mul(result, base),
                          base = complex_mul(base, base))
    while (remaining > 0) {
        if (remaining & 1) result = complex_mul(result, base);
        remaining >>= 1;
        if (remaining > 0) base = complex_mul(base, base);
    }
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

/* One Mandelbulb iteration for the lanes still inside the bailout: z -> z^power + p and the
 * running derivative, with integer_power choosing the trigonometry-free form. */
#define FGR_BULB_ITERATE(integer_power)                                           \
    do {                                                                          \
        real r_pow;                                                               \
        vec3 z_n;                                                                 \
        if (integer_power) {                                                      \
            r_pow = fgr_pown(r, (int)power - 1);                                  \
            z_n = bulb_power_integer(z, r, r_pow * r, (int)power, latitude_form); \
        } else {                                                                  \
            r_pow = fgr_pow(r, fgr_real(power - 1.0f));                           \
            z_n = bulb_power_real(z, r, r_pow * r, power, latitude_form);         \
        }                                                                         \
        dr = select(dr, power * r_pow * dr + 1.0f, active);                       \
        z = v3_select(z, v3_add(z_n, p), active);                                 \
        r = v3_length(z);                                                         \
        if (record) *trap = trap_update(*trap, z, active);                        \
    } while (0)

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
            FGR_BULB_ITERATE(1);
        }
    } else {
        for (int i = 0; i < iterations; ++i) {
            const mask active = r <= bailout;
            if (!fgr_any(active)) break;
            FGR_BULB_ITERATE(0);
        }
    }
    /* r = 0 never escapes (the origin is inside): distance 0, never log(0) * 0 = NaN. */
    return select(0.5f * log(r) * r / dr, fgr_real(0.0f), r <= 0.0f);
}
