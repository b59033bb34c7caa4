// SPDX-License-Identifier: Apache-2.0
/* fgr: what the host and the kernels exchange, written once for both (kernels/shared/).
 *
 * These headers are the common subset of C++20 and OpenCL C 1.2: #defines, and structs whose
 * fields are 32-bit integers, floats and float4s, which lay out alike on both sides (OpenCL C
 * aligns each field to its size, a float4 to 16 bytes, and a struct to its largest field, as
 * the host's compilers do with cl_int, cl_uint, cl_float and cl_float4). The host includes them
 * from the targets that fill what kernels read or read what they write, and static_asserts every
 * size and offset (host/device/kernel_layout.hpp); the kernel library embeds them and pastes
 * them into every program after the scene's source, before the library code that uses them
 * (kernel_layout() in kernels/kernel_library.cpp), so a scene sees no name it did not see
 * before.
 *
 * A program has no #include, so a header includes the others only for the host and relies on
 * the pasting order on the device; and each has a classic include guard, since `#pragma once`
 * in a pasted program would be "in the main file".
 *
 * On the host the structs live in namespace fgr::layout; the macros, being macros, do not. */
#ifndef FGR_LAYOUT_TYPES_H
#define FGR_LAYOUT_TYPES_H

#ifndef __OPENCL_C_VERSION__
#include <CL/cl_platform.h>
#endif

#ifdef __cplusplus
namespace fgr::layout {
#endif

/* A field's type names the same bits on both sides. */
#ifdef __OPENCL_C_VERSION__
typedef int fgr_layout_int;
typedef uint fgr_layout_uint;
typedef float fgr_layout_float;
typedef float4 fgr_layout_float4;
#else
typedef cl_int fgr_layout_int;
typedef cl_uint fgr_layout_uint;
typedef cl_float fgr_layout_float;
typedef cl_float4 fgr_layout_float4;
#endif

#ifdef __cplusplus
}  // namespace fgr::layout
#endif

#endif /* FGR_LAYOUT_TYPES_H */
