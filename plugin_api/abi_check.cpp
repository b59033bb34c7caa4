// SPDX-License-Identifier: Apache-2.0
// Compiles plugin.h as C++; the build fails if the header stops being valid C++.
#include "fgr/plugin.h"

static_assert(sizeof(fgr_struct_header) == 8, "header is two uint32_t");
static_assert(FGR_ABI_MINOR(FGR_ABI_VERSION) == FGR_ABI_VERSION_MINOR, "version packing");

// FGR_SCENE's source_length: an array's size, 0 (NUL-terminated) for a pointer.
#include "fgr/scene_helpers.h"
extern const char abi_check_source[4];
extern const char* const abi_check_source_pointer;
static_assert(FGR_SOURCE_LENGTH(abi_check_source) == 4, "an array: its size");
static_assert(FGR_SOURCE_LENGTH(abi_check_source_pointer) == 0, "a pointer: NUL-terminated");
static_assert(FGR_SOURCE_LENGTH("abc") == 4, "a string literal: its size");
