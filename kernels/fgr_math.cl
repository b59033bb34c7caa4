/* fgr kernel library: powers, sines and parities that are right in every lane.
 *
 * A vector built-in can be wrong where the scalar one is right. Debian's PoCL AVX-512 library
 * computes double8/double16 pow and pown (and fmod, frexp) with a lane mask of the wrong width, so
 * a lane that is 0, denormal, Inf or NaN corrupts another lane of the packet; its float16 sin,
 * cos and sincos go wrong in a lane near 0 when another lane is Inf. The library calls these
 * helpers instead, and the host's math self-test (host/src/math_check.cpp) checks them and the
 * plain built-ins the library uses at the width and precision of each render, narrowing the
 * packet where one fails. For finite inputs, float lanes compute what the plain built-ins
 * compute, except fgr_pown, which multiplies. Scenes should use them too. */

/* x^n for an integer n (the same for every lane): binary exponentiation, exact to a few
 * roundings (n = 7 is four multiplications), in float too: PoCL's float16 pown costs more than
 * the rest of a Mandelbulb iteration together (the canonical view rendered in 2.2x the time). */
inline real fgr_pown(real x, int n) {
    int e = abs(n);
    real result = fgr_real(1.0f);
    real base = x;
    while (e > 0) {
        if (e & 1) result *= base;
        e >>= 1;
        if (e > 0) base *= base;
    }
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

/* sin and cos with Inf lanes kept away from the built-in; they still give NaN there. */
inline real fgr_sin(real x) {
    const mask infinite = isinf(x);
    return select(sin(select(x, fgr_real(0.0f), infinite)), fgr_real(NAN), infinite);
}
inline real fgr_cos(real x) {
    const mask infinite = isinf(x);
    return select(cos(select(x, fgr_real(0.0f), infinite)), fgr_real(NAN), infinite);
}

/* 1 for odd integers, 0 for even ones (any sign), exactly: a checkerboard without fmod. */
inline real fgr_parity(real n) { return n - 2.0f * floor(0.5f * n); }
