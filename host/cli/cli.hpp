// SPDX-License-Identifier: Apache-2.0
#pragma once
// The `fgr` command line: list, info, render, video, view, new-scene, bench, cache. Returns the
// process exit code: 0 on success, 2 for bad command-line input, 1 for failures while running.
// Errors are one line on stderr starting with "fgr: error: ".

namespace fgr {

int run_cli(int argc, char** argv);

}  // namespace fgr
