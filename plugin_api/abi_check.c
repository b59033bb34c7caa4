/* Compiles plugin.h as C11; the build fails if the header stops being valid C. */
#include "fgr/plugin.h"

_Static_assert(sizeof(fgr_struct_header) == 8, "header is two uint32_t");
_Static_assert(FGR_ABI_MAJOR(FGR_ABI_VERSION) == FGR_ABI_VERSION_MAJOR, "version packing");
