// SPDX-License-Identifier: Apache-2.0
/* fgr kernel library: the device math self-test (host/device/math_check.cpp).
 *
 * Runs the maths the kernel library calls on lanes (fgr_math.cl's helpers and the plain
 * built-ins) at the packet width and precision a render would use, so the host can compare every
 * lane with its own libm: a vector built-in can be wrong where the scalar one is right (see
 * fgr_math.cl for the ones Debian's PoCL AVX-512 library gets wrong).
 *
 * Built after fgr_types.cl and fgr_math.cl, with FGR_WIDTH (and FGR_DOUBLE) as a render's program
 * is. A case is FGR_WIDTH lanes of the inputs a (and b): case c is lanes c*W .. c*W+W-1. */

#if FGR_WIDTH == 1
#define load_lanes(i, p) convert_real((p)[i])
#define store_lanes(v, i, p) ((p)[i] = (v))
#else
#define load_lanes(i, p) FGR_PASTE(vload, FGR_WIDTH)(i, p)
#define store_lanes(v, i, p) FGR_PASTE(vstore, FGR_WIDTH)(v, i, p)
#endif
typedef FGR_LANES(float, double) lane_scalar;

/* One kernel per function, each over its own run of cases starting at first_case. (A single
 * kernel switching over all of them took minutes to build at 16 double lanes, where each alone
 * takes a fraction of a second.) One work-item per group keeps PoCL from compiling a work-item
 * loop around each. Kernel names: keep in step with host/device/math_check.cpp; arguments in the
 * order of FGR_MATH_CHECK_ARG_* (shared/fgr_layout_arguments.h). */
#define FGR_CHECK_KERNEL(name, expression)                                                       \
    __kernel __attribute__((reqd_work_group_size(1, 1, 1))) void fgr_check_##name(               \
        __global const lane_scalar* a, __global const lane_scalar* b, __global lane_scalar* out, \
        int first_case) {                                                                        \
        const int c = first_case + (int)get_global_id(0);                                        \
        const real x = load_lanes(c, a);                                                         \
        const real y = load_lanes(c, b);                                                         \
        real result = expression;                                                                \
        (void)y;                                                                                 \
        FGR_CHECK_FAULT_##name;                                                                  \
        store_lanes(result, c, out);                                                             \
    }

/* A planted fault for the self-test's own test: exp's first two lanes trade places. */
#if defined(FGR_CHECK_SWAP_EXP_LANES) && FGR_WIDTH > 1
#define FGR_CHECK_FAULT_exp result.s01 = result.s10
#else
#define FGR_CHECK_FAULT_exp
#endif
#define FGR_CHECK_FAULT_fgr_pow
#define FGR_CHECK_FAULT_fgr_pown7
#define FGR_CHECK_FAULT_fgr_pown2
#define FGR_CHECK_FAULT_fgr_sin
#define FGR_CHECK_FAULT_fgr_cos
#define FGR_CHECK_FAULT_log
#define FGR_CHECK_FAULT_sqrt
#define FGR_CHECK_FAULT_rsqrt
#define FGR_CHECK_FAULT_atan2
#define FGR_CHECK_FAULT_asin
#define FGR_CHECK_FAULT_floor
#define FGR_CHECK_FAULT_fabs

FGR_CHECK_KERNEL(fgr_pow, fgr_pow(x, y))
FGR_CHECK_KERNEL(fgr_pown7, fgr_pown(x, 7))
FGR_CHECK_KERNEL(fgr_pown2, fgr_pown(x, 2))
FGR_CHECK_KERNEL(fgr_sin, fgr_sin(x))
FGR_CHECK_KERNEL(fgr_cos, fgr_cos(x))
FGR_CHECK_KERNEL(exp, exp(x))
FGR_CHECK_KERNEL(log, log(x))
FGR_CHECK_KERNEL(sqrt, sqrt(x))
FGR_CHECK_KERNEL(rsqrt, rsqrt(x))
FGR_CHECK_KERNEL(atan2, atan2(x, y))
FGR_CHECK_KERNEL(asin, asin(x))
FGR_CHECK_KERNEL(floor, floor(x))
FGR_CHECK_KERNEL(fabs, fabs(x))
