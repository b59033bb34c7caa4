/* fgr kernel library: packet types.
 *
 * Every scene function works on a packet of FGR_WIDTH rays at once. On a CPU (PoCL) the host
 * builds with FGR_WIDTH 8 or 16, so each work-item marches a tile of pixels in SIMD lanes: PoCL
 * only vectorises across work-items when a kernel has no data-dependent loops, which a sphere
 * tracer always has. On a GPU the host builds with FGR_WIDTH 1 and the same source runs one ray per
 * work-item.
 *
 *   real   a float per lane            (float, float4, float8 or float16)
 *   mask   a truth value per lane      (int of the same width; true lanes are non-zero)
 *   vec3   three reals, x/y/z          (struct of arrays: one real per component)
 *
 * Built-in maths (sin, pow, atan2, sqrt, fmin, ...) works on `real` unchanged. Lane-wise control
 * flow uses fgr_any/fgr_all and select(): a loop runs while fgr_any(active) and freezes finished
 * lanes with select(old, new, active).
 */
#ifndef FGR_WIDTH
#define FGR_WIDTH 1
#endif

#if defined(__clang__) && FGR_WIDTH == 16
/* clang notes that float16 arguments change the x86 calling convention without AVX-512; that is
 * internal to the program and harmless, and would bury a scene's real errors in the build log. */
#pragma clang diagnostic ignored "-Wpsabi"
#endif

#if FGR_WIDTH == 1
typedef float real;
typedef int mask;
typedef uint ulanes;
#define convert_ulanes convert_uint
#define convert_real convert_float
#define fgr_any(m) ((m) != 0)
#define fgr_all(m) ((m) != 0)
#elif FGR_WIDTH == 4
typedef float4 real;
typedef int4 mask;
typedef uint4 ulanes;
#define convert_ulanes convert_uint4
#define convert_real convert_float4
#define fgr_any(m) any(m)
#define fgr_all(m) all(m)
#elif FGR_WIDTH == 8
typedef float8 real;
typedef int8 mask;
typedef uint8 ulanes;
#define convert_ulanes convert_uint8
#define convert_real convert_float8
#define fgr_any(m) any(m)
#define fgr_all(m) all(m)
#elif FGR_WIDTH == 16
typedef float16 real;
typedef int16 mask;
typedef uint16 ulanes;
#define convert_ulanes convert_uint16
#define convert_real convert_float16
#define fgr_any(m) any(m)
#define fgr_all(m) all(m)
#else
#error "FGR_WIDTH must be 1, 4, 8 or 16"
#endif

/* A scalar broadcast to every lane. */
#define fgr_real(x) ((real)(x))

/* The all-true mask: -1 in vector lanes (select() reads the top bit), 1 for scalars. */
#if FGR_WIDTH == 1
#define FGR_TRUE 1
#else
#define FGR_TRUE ((mask)(-1))
#endif

/* Lane-wise counter increment where m holds. */
#define fgr_count_if(counter, m) ((counter) = select((counter), (counter) + 1, (m)))

/*   ulanes an unsigned int per lane        (for hashing: random numbers per pixel) */

typedef struct vec3 {
    real x, y, z;
} vec3;

/* The parameter buffer a scene reads (through the generated param_<id> accessors). */
#define PARAMS __constant const float* fgr_params
#define PARAMS_PASS fgr_params
