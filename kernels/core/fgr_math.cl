// SPDX-License-Identifier: Apache-2.0
/* fgr kernel library: powers, sines and parities that are right in every lane.
 *
 * A vector built-in can be wrong where the scalar one is right. Debian's PoCL AVX-512 library
 * computes double8/double16 pow and pown (and fmod, frexp) with a lane mask of the wrong width, so
 * a lane that is 0, denormal, Inf or NaN corrupts another lane of the packet; its float16 sin,
 * cos and sincos go wrong in a lane near 0 when another lane is Inf. The library calls these
 * helpers instead, and the host's math self-test (host/device/math_check.cpp) checks them and the
 * plain built-ins the library uses at the width and precision of each render, narrowing the
 * packet where one fails. For finite inputs, float lanes compute what the plain built-ins
 * compute, except fgr_pown, which multiplies. Scenes should use them too. */

/* One step of binary exponentiation with exponent bits e: multiply in the base for a set low bit,
 * shift, square the base while bits remain. */
#define FGR_BINARY_POWER_STEP(e, multiply, square) \
    if ((e) > 0) {                                 \
        if ((e)&1) multiply;                       \
        (e) >>= 1;                                 \
        if ((e) > 0) square;                       \
    }

/* A kernel built with parameters compiled in (FGR_SPECIALISED) often has constant exponents, yet
 * PoCL keeps the loop below even then: there the first five steps are written out, for the
 * compiler to fold (the same multiplications in the same order, so the same bits), and the power
 * helpers are inlined into packet code. Measured slower in the kernel that reads parameters from
 * the buffer, so that one keeps the plain loop. */
#if defined(FGR_SPECIALISED) && FGR_WIDTH > 1
#define FGR_POWER_FUNCTION inline __attribute__((always_inline))
#define FGR_POWER_STEPS_AHEAD(e, multiply, square) \
    FGR_BINARY_POWER_STEP(e, multiply, square)     \
    FGR_BINARY_POWER_STEP(e, multiply, square)     \
    FGR_BINARY_POWER_STEP(e, multiply, square)     \
    FGR_BINARY_POWER_STEP(e, multiply, square)     \
    FGR_BINARY_POWER_STEP(e, multiply, square)
#else
#define FGR_POWER_FUNCTION inline
#define FGR_POWER_STEPS_AHEAD(e, multiply, square)
#endif

/* Binary exponentiation: for each bit of e from the lowest, `multiply` folds the base into the
 * result where the bit is set and `square` squares the base while bits remain; the first steps
 * written out where that pays. fgr_pown, complex_powi and rho_complex_powi share it, each with
 * its own multiplication. */
#define FGR_BINARY_POWER(e, multiply, square)      \
    FGR_POWER_STEPS_AHEAD(e, multiply, square)     \
    while ((e) > 0) {                              \
        FGR_BINARY_POWER_STEP(e, multiply, square) \
    }

/* x^n for an integer n (the same for every lane): binary exponentiation, exact to a few
 * roundings (n = 7 is four multiplications), in float too: PoCL's float16 pown costs more than
 * the rest of a Mandelbulb iteration together (the canonical view rendered in 2.2x the time). */
FGR_POWER_FUNCTION real fgr_pown(real x, int n) {
    int e = abs(n);
    real result = fgr_real(1.0f);
    real base = x;
    FGR_BINARY_POWER(e, result *= base, base *= base)
    return n < 0 ? 1.0f / result : result;
}

/* x^y for x >= 0 (NaN for negative x, as pow gives for a non-integer y). Double: exp(y log x),
 * whose relative error is about |y log x| ulps: under 50 for the powers fractals use; 0^0 = 1 as
 * pow has it. */
inline real fgr_pow(real x, real y) {
#ifdef FGR_DOUBLE
    return select(exp(y * log(x)), fgr_real(1.0f), y == 0.0f);
#else
    return pow(x, y);
#endif
}

#ifdef FGR_DOUBLE
/* sin and cos with Inf lanes kept away from the built-in; they still give NaN there. */
inline real fgr_sin(real x) {
    const mask infinite = isinf(x);
    return select(sin(select(x, fgr_real(0.0f), infinite)), fgr_real(NAN), infinite);
}
inline real fgr_cos(real x) {
    const mask infinite = isinf(x);
    return select(cos(select(x, fgr_real(0.0f), infinite)), fgr_real(NAN), infinite);
}
#else
/* Float lanes compute sin and cos here, as Cephes' sinf and cosf do (Moshier): x less the
 * nearest even multiple j of pi/4, subtracted in three parts of pi/4 (Cody and Waite) so the
 * remainder keeps its precision, then the minimax polynomial for sin or cos on [-pi/4, pi/4]
 * that octant j asks for; within 2 ulps of libm for |x| < 8192 (the math self-test holds every
 * width to 4). Beyond that the reduction loses bits (about |x| * 6e-8 absolute); see the end
 * for |x| past 1e9, Inf and NaN. PoCL's float16 built-ins are right, but a call to one anywhere
 * in a DE, even on a branch never taken, made the benchmark scene's frames 25% slower. */
inline real fgr_sin_cos_float(real x, int want_cos) {
    const real ax = fabs(x);
    const mask octant_of = convert_mask(ax * 1.27323954473516f); /* 4 / pi, truncated */
    const mask even = octant_of + (octant_of & 1); /* the remainder lies in [-pi/4, pi/4] */
    const real j = convert_real(even);
    const real r =
        ((ax - j * 0.78515625f) - j * 2.4187564849853515625e-4f) - j * 3.77489497744594108e-8f;
    const real z = r * r;
    const real sin_r =
        ((-1.9515295891e-4f * z + 8.3321608736e-3f) * z - 1.6666654611e-1f) * z * r + r;
    const real cos_r =
        ((2.443315711809948e-5f * z - 1.388731625493765e-3f) * z + 4.166664568298827e-2f) * z * z -
        0.5f * z + 1.0f;
    /* By octant 0, 2, 4, 6, sin(ax) is sin_r, cos_r, -sin_r, -cos_r; cos(ax) two octants on. */
    const mask turn = (even + (want_cos ? 2 : 0)) & 7;
    const real value = select(sin_r, cos_r, (turn == 2) | (turn == 6));
    real of_ax = select(value, -value, turn >= 4);
    if (!want_cos) of_ax = select(of_ax, -of_ax, signbit(x)); /* odd; sin(-0) is -0 */
    /* Past 1e9 float's spacing exceeds 64 and an angle means nothing: a finite answer (sin 0,
     * cos 1) keeps DEs finite at the stability checks' far points. Inf and NaN give NaN. */
    const real far_value = fgr_real(want_cos ? 1.0f : 0.0f);
    return select(select(of_ax, far_value, !(ax < 1e9f)), fgr_real(NAN), isinf(x) | isnan(x));
}
inline real fgr_sin(real x) { return fgr_sin_cos_float(x, 0); }
inline real fgr_cos(real x) { return fgr_sin_cos_float(x, 1); }
#endif

/* 1 for odd integers, 0 for even ones (any sign), exactly: a checkerboard without fmod. */
inline real fgr_parity(real n) { return n - 2.0f * floor(0.5f * n); }
