// SPDX-License-Identifier: Apache-2.0
/* fgr formula library: bulbs. Powers of triplex numbers and their relatives, iterated as
 * z <- f(z) + c from z = c. Every step here is a polynomial map of degree n, so an escaping orbit
 * grows like r^(n^k): the distance is the logarithmic estimate 0.5 log(r) r / dr, dr the running
 * derivative (Hart, Sandin and Kauffman 1989; for bulbs Daniel White and Paul Nylander 2009).
 *
 * Every formula has the shape formula_NAME(&z, &w, &dr, c, parameters...): z the orbit point, w a
 * fourth component only the hypercomplex formulas use (the others leave it alone), dr the running
 * derivative, c the point whose distance is asked. bulb_integer_power and bulb_power_real
 * (fgr_fractals.cl) give z^n. */

/* z^n of the triplex z: integer powers without trigonometry. latitude: polar angle from the
 * xy-plane (Mandelbulber's convention) instead of from +z. Returns r^(n-1) for the derivative. */
inline vec3 formula_bulb_power(vec3 z, float power, int latitude, real* r_pow) {
    const real r = v3_length(z);
    if (power == floor(power)) {
        *r_pow = fgr_pown(r, (int)power - 1);
        return bulb_integer_power(z, (int)power, latitude);
    }
    *r_pow = fgr_pow(r, fgr_real(power - 1.0f));
    return bulb_power_real(z, r, *r_pow * r, power, latitude);
}

/* Mandelbulb (Daniel White and Paul Nylander, 2009, "The Unravelling of the Real 3D
 * Mandelbulb", skytopia.com): z <- z^n + c, the power taken in spherical coordinates with the
 * polar angle from +z. */
inline void formula_mandelbulb(vec3* z, real* w, real* dr, const vec3 c, float power) {
    (void)w;
    real r_pow;
    const vec3 zn = formula_bulb_power(*z, power, 0, &r_pow);
    *dr = power * r_pow * *dr + 1.0f;
    *z = v3_add(zn, c);
}

/* Mandelbulb with the polar angle from the xy-plane (asin(z / r)): Mandelbulber 2's
 * "Mandelbulb" formula, a different surface from White and Nylander's for the same power. */
inline void formula_mandelbulb_latitude(vec3* z, real* w, real* dr, const vec3 c, float power) {
    (void)w;
    real r_pow;
    const vec3 zn = formula_bulb_power(*z, power, 1, &r_pow);
    *dr = power * r_pow * *dr + 1.0f;
    *z = v3_add(zn, c);
}

/* Juliabulb: the Mandelbulb's step with a fixed constant instead of the point (White and
 * Nylander's Julia sets of the bulb). No + 1 in the derivative: c does not move with the point. */
inline void formula_juliabulb(vec3* z, real* w, real* dr, const vec3 c, float power, vec3 julia) {
    (void)w;
    (void)c;
    real r_pow;
    const vec3 zn = formula_bulb_power(*z, power, 0, &r_pow);
    *dr = power * r_pow * *dr;
    *z = v3_add(zn, julia);
}

/* Juliabulb in the latitude form (Mandelbulber 2's convention). */
inline void formula_juliabulb_latitude(vec3* z, real* w, real* dr, const vec3 c, float power,
                                       vec3 julia) {
    (void)w;
    (void)c;
    real r_pow;
    const vec3 zn = formula_bulb_power(*z, power, 1, &r_pow);
    *dr = power * r_pow * *dr;
    *z = v3_add(zn, julia);
}

/* White-Nylander power 2 written out as the polynomial it is (Daniel White's quadratic bulb,
 * 2009): with rho = |(x, y)|, z^2 = (2 z (x^2 - y^2) / rho, 4 x y z / rho, z^2 - rho^2). The same
 * map as formula_mandelbulb at power 2, without trigonometry or angle powers (the tests hold the
 * two to each other). */
inline void formula_white_nylander(vec3* z, real* w, real* dr, const vec3 c) {
    (void)w;
    const vec3 p = *z;
    const real rho2 = p.x * p.x + p.y * p.y;
    const real rho = sqrt(rho2);
    const real inv_rho = select(1.0f / rho, fgr_real(0.0f), rho <= 0.0f);
    /* On the z axis the azimuth is 0 (as atan2(0, 0)): (2 z rho, 0, z^2 - rho^2) with rho = 0. */
    const real cos2 =
        select((p.x * p.x - p.y * p.y) * inv_rho * inv_rho, fgr_real(1.0f), rho <= 0.0f);
    const real sin2 = 2.0f * p.x * p.y * inv_rho * inv_rho;
    const real horizontal = 2.0f * p.z * rho;
    *dr = 2.0f * v3_length(p) * *dr + 1.0f;
    *z = v3_add(v3(horizontal * cos2, horizontal * sin2, p.z * p.z - rho2), c);
}

/* Mandelbar bulb: the Mandelbulb of the mirror image z -> (x, -y, z), as the tricorn (Mandelbar,
 * Crowe, Hasson, Rippon and Strain-Clark 1989) takes the complex conjugate before squaring. */
inline void formula_mandelbar_bulb(vec3* z, real* w, real* dr, const vec3 c, float power) {
    (void)w;
    real r_pow;
    const vec3 zn = formula_bulb_power(v3((*z).x, -(*z).y, (*z).z), power, 0, &r_pow);
    *dr = power * r_pow * *dr + 1.0f;
    *z = v3_add(zn, c);
}

/* Xenodreambuie's bulb (fractalforums.com, 2009; Mandelbulber 2's "Xenodreambuie"): the power
 * with both angles turned after multiplying, theta n + alpha and phi n + beta (degrees). */
inline void formula_xenodreambuie(vec3* z, real* w, real* dr, const vec3 c, float power,
                                  float alpha, float beta) {
    (void)w;
    const vec3 p = *z;
    const real r = v3_length(p);
    const real inv_r = select(1.0f / r, fgr_real(0.0f), r <= 0.0f);
    const real theta = atan2(p.y, p.x) * power + radians(alpha);
    const real phi = acos(clamp(p.z * inv_r, -1.0f, 1.0f)) * power + radians(beta);
    const real r_pow = fgr_pow(r, fgr_real(power - 1.0f));
    const real rn = r_pow * r;
    const real s = fgr_sin(phi);
    *dr = power * r_pow * *dr + 1.0f;
    *z = v3_add(v3(rn * s * fgr_cos(theta), rn * s * fgr_sin(theta), rn * fgr_cos(phi)), c);
}

/* Lambdabulb (Paul Nylander, bugman123.com "Hypercomplex", and fractalrebels,
 * fractalforums.com 2011; Mandelbulber 2's "Mandelbulb Lambda"): the logistic map
 * z <- lambda (z - z^n) of Mandelbrot's lambda form (1980) in triplex numbers, the power in the
 * latitude form and the product Nylander's trigonometry-free one: radii multiply, azimuths add,
 * and the heights combine as r1 b.z + r2 a.z over the horizontal radii r1, r2. A Julia-type set:
 * lambda is fixed and the point only starts the orbit. */
inline vec3 triplex_multiply(vec3 a, vec3 b) {
    const real ra = sqrt(a.x * a.x + a.y * a.y);
    const real rb = sqrt(b.x * b.x + b.y * b.y);
    const real k = 1.0f - a.z * b.z / fmax(ra * rb, fgr_real(1e-20f));
    return v3(k * (a.x * b.x - a.y * b.y), k * (a.x * b.y + a.y * b.x), ra * b.z + rb * a.z);
}

inline void formula_lambdabulb(vec3* z, real* w, real* dr, const vec3 c, float power, vec3 lambda) {
    (void)w;
    (void)c;
    real r_pow;
    const vec3 zn = formula_bulb_power(*z, power, 1, &r_pow);
    *dr = v3_length(lambda) * (1.0f + power * r_pow) * *dr;
    *z = triplex_multiply(v3_sub(*z, zn), lambda);
}

/* Makin's 3D Mandelbrot (fractalforums.com, 2009): (x^2 - y^2 - z^2, 2 x y, 2 x z) + c, the
 * Mandelbrot set turned about the real axis into a solid of revolution. */
inline void formula_makin(vec3* z, real* w, real* dr, const vec3 c) {
    (void)w;
    const vec3 p = *z;
    *dr = 2.0f * v3_length(p) * *dr + 1.0f;
    *z = v3_add(v3(p.x * p.x - p.y * p.y - p.z * p.z, 2.0f * p.x * p.y, 2.0f * p.x * p.z), c);
}

/* Benesi's pine tree (Matt Benesi, fractalforums.com, 2010; Mandelbulber 2's "Benesi pine
 * tree"): x <- x^2 - y^2 - z^2, and (y, z) <- 2 x / |(y, z)| (y^2 - z^2, 2 y z), plus c. */
inline void formula_benesi_pine_tree(vec3* z, real* w, real* dr, const vec3 c) {
    (void)w;
    const vec3 p = *z;
    const real yz = sqrt(p.y * p.y + p.z * p.z);
    const real t = select(2.0f * p.x / yz, fgr_real(0.0f), yz <= 0.0f);
    *dr = 2.0f * v3_length(p) * *dr + 1.0f;
    *z = v3_add(v3(p.x * p.x - yz * yz, t * (p.y * p.y - p.z * p.z), 2.0f * t * p.y * p.z), c);
}

/* Riemann sphere fractal (msltoe, fractalforums.com 2011, "Riemann fractals"; Mandelbulber 2's
 * "Riemann Sphere Msltoe"): z scaled onto the sphere of radius `scale`, projected
 * stereographically to the plane (s, t), folded there by |sin(pi s + shift)|, mapped back onto
 * the sphere and given the radius |z|^(2 (1 + s^2 + t^2)) - 1/4, then + c. The radius grows with
 * the projection's own stretch, so no running derivative bounds it: an inside test. */
inline void formula_riemann_sphere(vec3* z, real* w, real* dr, const vec3 c, float scale,
                                   float shift_s, float shift_t) {
    (void)w;
    const real r = v3_length(*z);
    const vec3 p = v3_scale(*z, scale / fmax(r, fgr_real(1e-20f)));
    /* The projection's pole (0, 0, 1) maps to infinity: keep 1 - z away from 0. */
    const real q = 1.0f / fmax(1.0f - p.z, fgr_real(1e-6f));
    real s = p.x * q, t = p.y * q;
    /* Mandelbulber caps the exponent at 36 (r^72 stays a float below r = 3.4). */
    const real exponent = fmin(1.0f + s * s + t * t, fgr_real(36.0f));
    s = fabs(fgr_sin(M_PI_F * s + shift_s));
    t = fabs(fgr_sin(M_PI_F * t + shift_t));
    const real radius = fgr_pow(r * r, exponent) - 0.25f;
    const real k = radius / (1.0f + s * s + t * t);
    *dr = 2.0f * exponent * r * *dr + 1.0f;
    *z = v3_add(v3(2.0f * s * k, 2.0f * t * k, (s * s + t * t - 1.0f) * k), c);
}
