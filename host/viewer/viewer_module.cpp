// SPDX-License-Identifier: Apache-2.0
// The entry point of libfgr_viewer.so, the viewer as the module `fgr view` loads (viewer.hpp).
#include "viewer/viewer.hpp"

extern "C" __attribute__((visibility("default"))) const fgr::viewer::ViewerModule*
fgr_viewer_module() {
    static const fgr::viewer::ViewerModule module{fgr::viewer::kViewerModuleVersion,
                                                  fgr::viewer::run_viewer};
    return &module;
}
