// SPDX-License-Identifier: Apache-2.0
#pragma once
// The OpenCL C kernel library, embedded in the binary. A scene's program is
//   switches + prelude files + parameter accessors + the formula families the scene calls
//   + scene source + layout headers + postlude files + the render mode's files.

#include <span>
#include <string_view>

namespace fgr {

struct KernelFile {
    const char* name;    // file name under kernels/, used in #line directives
    const char* source;  // NUL-terminated OpenCL C
};

// Types and maths a scene's source may use: packet types, vec3 maths, materials and their BSDFs,
// the SDF toolkit (primitives, combinators, transforms), IFS folds and orbit-trap colouring.
std::span<const KernelFile> kernel_prelude();
// What the host and the kernels exchange, in headers the host includes too
// (shared/fgr_layout_*.h). After the scene's source, so a scene sees none of it; before
// everything that uses it.
std::span<const KernelFile> kernel_layout();
// Marching, shading, sampling (fgr_sampler.cl: every mode's random numbers), the camera and the
// probe kernels, which call the scene's functions.
std::span<const KernelFile> kernel_postlude();

// What render mode `mode` ("shaded", "path") adds after the postlude, ending with its file
// fgr_mode_<mode>.cl and its entry point fgr_render; empty for an unknown mode.
std::span<const KernelFile> mode_files(std::string_view mode);

// What the path tracer builds on beyond the prelude, for tests that build it without a scene: the
// sample generator (fgr_sampler.cl, which a scene's program has in its postlude) and the
// environment's lookup and importance sampling (fgr_environment.cl, which the path mode adds after
// the postlude). Each needs only the prelude's types and maths; materials and their BSDFs
// (fgr_bsdf.cl) are in the prelude.
std::span<const KernelFile> path_library();

// The formula library's families (formulas/<family>.cl: bulbs, hypercomplex, boxes, kifs,
// kleinian), each a file of formula_NAME step functions, in the order a program holds them; the
// program of a scene whose source calls a formula holds its family (kernel_assembly.cpp).
std::span<const KernelFile> formula_families();
// The family's file; null for an unknown family.
const KernelFile* formula_family(std::string_view family);

// The device math self-test kernel (fgr_math_check.cl), built on its own.
const char* math_check_source();

}  // namespace fgr
