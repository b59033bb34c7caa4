// SPDX-License-Identifier: Apache-2.0
/* Compiles plugin.h as C11; the build fails if the header stops being valid C. */
#include "fgr/plugin.h"

_Static_assert(sizeof(fgr_struct_header) == 8, "header is two uint32_t");
_Static_assert(FGR_ABI_MAJOR(FGR_ABI_VERSION) == FGR_ABI_VERSION_MAJOR, "version packing");

/* FGR_SCENE's source_length: an array's size, 0 (NUL-terminated) for a pointer. */
#include "fgr/scene_helpers.h"
extern const char abi_check_source[4];
extern const char* const abi_check_source_pointer;
_Static_assert(FGR_SOURCE_LENGTH(abi_check_source) == 4, "an array: its size");
_Static_assert(FGR_SOURCE_LENGTH(abi_check_source_pointer) == 0, "a pointer: NUL-terminated");
