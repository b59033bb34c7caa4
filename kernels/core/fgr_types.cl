// SPDX-License-Identifier: Apache-2.0
/* fgr kernel library: packet types.
 *
 * Every scene function works on a packet of FGR_WIDTH rays at once. On a CPU (PoCL) the host
 * builds with FGR_WIDTH 8 or 16, so each work-item marches a tile of pixels in SIMD lanes: PoCL
 * only vectorises across work-items when a kernel has no data-dependent loops, which a sphere
 * tracer always has. On a GPU the host builds with FGR_WIDTH 1 and the same source runs one ray per
 * work-item.
 *
 *   real   a float per lane            (float, float4, float8 or float16; double with FGR_DOUBLE)
 *   mask   a truth value per lane      (int of the same width, long with FGR_DOUBLE; true lanes
 *                                       are non-zero)
 *   vec3   three reals, x/y/z          (struct of arrays: one real per component)
 *
 * Built-in maths (sin, pow, atan2, sqrt, fmin, ...) works on `real` unchanged. Lane-wise control
 * flow uses fgr_any/fgr_all and select(): a loop runs while fgr_any(active) and freezes finished
 * lanes with select(old, new, active).
 */
/* The kernel library's API: what a scene's source codes against (`real`, `vec3`, `v3_*`, `sd_*`,
 * `fold_*`, `PARAMS`, `FGR_SCENE_HAS_*`, the scene macros). A scene says which version it was
 * written for with `#define FGR_KERNEL_API 2` on a line of its own; the host reads that line and
 * defines the same value before the library, so the library shows the scene exactly the names and
 * signatures of that version. A scene that says nothing was written for version 1 (before versions
 * were counted), and keeps compiling as it did. Version 2 added: helpers taking a direction, axis
 * or size as `vec3` (what a vec3 parameter gives: rotation_about_axis, rotate_about), the folds
 * fold_box_axes, fold_icosahedral/fold_dodecahedral, invert_sphere, scale_about, and the
 * iterate-function scenes (FGR_ITERATION ... FGR_END_ITERATION, FGR_ITERATED_SCENE). Version 3
 * added op_union_culled (a union that skips an object no lane can need). Version 4 reads
 * parameters as the uniform values they are: a vec3 or colour parameter is a `float3` (so
 * `const float h = param_offset.z;` compiles at every packet width and precision, as a float
 * parameter always was a `float`), and v3_uniform(u) puts a float3 in every lane of a vec3 for the
 * vec3 helpers; before version 4 a vec3 parameter reads as a vec3, whose components are `real`
 * lanes. Names are only ever added in a new version; a change to an existing one keeps the old
 * form for older versions. */
#define FGR_KERNEL_API_LATEST 4
#ifndef FGR_KERNEL_API
#define FGR_KERNEL_API 1
#endif

#ifndef FGR_WIDTH
#define FGR_WIDTH 1
#endif

#if defined(__clang__) && FGR_WIDTH == 16
/* clang notes that float16 arguments change the x86 calling convention without AVX-512; that is
 * internal to the program and harmless, and would bury a scene's real errors in the build log. */
#pragma clang diagnostic ignored "-Wpsabi"
#endif

#ifdef FGR_DOUBLE
/* Double precision (`--precision double`, or auto for deep zooms): the same code on double lanes.
 * select() needs masks as wide as the lanes, so masks are longs; planes stay float in memory. */
#pragma OPENCL EXTENSION cl_khr_fp64 : enable
#define FGR_LANES(f, d) d
#else
#define FGR_LANES(f, d) f
#endif

/* Lane types are the scalar name with the width pasted on (float16, long16, convert_uint16, ...);
 * one ray per work-item pastes nothing and gets the scalars. */
#if FGR_WIDTH == 1
#define FGR_LANE_SUFFIX
#define fgr_any(m) ((m) != 0)
#define fgr_all(m) ((m) != 0)
#elif FGR_WIDTH == 4 || FGR_WIDTH == 8 || FGR_WIDTH == 16
#define FGR_LANE_SUFFIX FGR_WIDTH
/* Whether some lane's (every lane's) top bit is set, as any() and all() say. PoCL lowers the
 * built-in any() to a test and branch per pair of lanes (about 45 instructions at 16 lanes, once
 * per DE iteration); the top bits shifted down and or-ed together by halves lower to a shift, a
 * few ors and one test. Overloaded for int and long lanes, as the built-in is, so a mask of
 * either (a double build compares ints too) keeps working. */
#define FGR_ANY_OF(scalar, unsigned_scalar, top_bit)                                         \
    inline int __attribute__((overloadable)) fgr_any_lanes(FGR_PASTE(scalar, FGR_WIDTH) m) { \
        const FGR_PASTE(unsigned_scalar, FGR_WIDTH) top =                                    \
            FGR_PASTE(FGR_PASTE(as_, unsigned_scalar), FGR_WIDTH)(m) >> top_bit;             \
        FGR_ANY_FOLD_TO_4(unsigned_scalar, top, four);                                       \
        const FGR_PASTE(unsigned_scalar, 2) two = four.lo | four.hi;                         \
        return (two.x | two.y) != 0;                                                         \
    }
#if FGR_WIDTH == 16
#define FGR_ANY_FOLD_TO_4(unsigned_scalar, top, four)                \
    const FGR_PASTE(unsigned_scalar, 8) eight = (top).lo | (top).hi; \
    const FGR_PASTE(unsigned_scalar, 4) four = eight.lo | eight.hi
#elif FGR_WIDTH == 8
#define FGR_ANY_FOLD_TO_4(unsigned_scalar, top, four) \
    const FGR_PASTE(unsigned_scalar, 4) four = (top).lo | (top).hi
#else
#define FGR_ANY_FOLD_TO_4(unsigned_scalar, top, four) \
    const FGR_PASTE(unsigned_scalar, 4) four = (top)
#endif
#define fgr_any(m) fgr_any_lanes(m)
#define fgr_all(m) (!fgr_any_lanes(~(m)))
#else
#error "FGR_WIDTH must be 1, 4, 8 or 16"
#endif
#define FGR_PASTE_(a, b) a##b
#define FGR_PASTE(a, b) FGR_PASTE_(a, b)
#define FGR_LANE_TYPE(scalar) FGR_PASTE(scalar, FGR_LANE_SUFFIX)
#if FGR_WIDTH > 1
FGR_ANY_OF(int, uint, 31)
FGR_ANY_OF(long, ulong, 63)
#endif

typedef FGR_LANE_TYPE(FGR_LANES(float, double)) real;
typedef FGR_LANE_TYPE(FGR_LANES(int, long)) mask;
typedef FGR_LANE_TYPE(FGR_LANES(uint, ulong)) ulanes;
#define convert_ulanes FGR_LANE_TYPE(FGR_LANES(convert_uint, convert_ulong))
#define convert_real FGR_LANE_TYPE(FGR_LANES(convert_float, convert_double))
#define convert_mask FGR_LANE_TYPE(FGR_LANES(convert_int, convert_long))
#define convert_float_lanes FGR_LANE_TYPE(convert_float)

/* What the precision in use can resolve near coordinates of order 1 (a few ulps there): the
 * smallest normal stencil (a length), and how far secondary rays start off a surface at the
 * least, relative to the point's coordinates (fgr_shade.cl's rounding_floor). In float these are
 * ~2 and ~16 ulps; double resolves a deep zoom's 1e-9-unit pixels, so its floors sit ~1e7 times
 * lower. */
#define FGR_MIN_LENGTH FGR_LANES(1e-7f, 1e-14)
#define FGR_SURFACE_OFFSET FGR_LANES(1e-6f, 1e-13)

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

/* The parameter buffer a scene reads (through the generated param_<id> accessors). Parameters
 * are uniform, the same in every lane: a float parameter reads as a `float`, an int or enum as an
 * `int`, a bool as an `int` 0/1, and (kernel API 4) a vec3 or colour as a `float3`. The buffer
 * holds floats, so a double build converts them where they meet `real` lanes. */
#define PARAMS __constant const float* fgr_params
#define PARAMS_PASS fgr_params
