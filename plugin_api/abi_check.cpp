// Compiles plugin.h as C++; the build fails if the header stops being valid C++.
#include "fgr/plugin.h"

static_assert(sizeof(fgr_struct_header) == 8, "header is two uint32_t");
static_assert(FGR_ABI_MINOR(FGR_ABI_VERSION) == FGR_ABI_VERSION_MINOR, "version packing");
