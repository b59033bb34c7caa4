// SPDX-License-Identifier: Apache-2.0
#include "kernel_test_program.hpp"

#include <fmt/format.h>

#include "device/kernel_assembly.hpp"
#include "fgr/kernel_library.hpp"

namespace fgr::test {

std::string library_test_source(std::string_view test_source) {
    std::string source;
    const auto append = [&source](std::string_view name, std::string_view text) {
        source += fmt::format("#line 1 \"{}\"\n", name);
        source += text;
        source += '\n';
    };
    // No scene: the library's scene-facing helpers need no scene_de until the postlude.
    for (const KernelFile& file : kernel_prelude()) append(file.name, file.source);
    for (const KernelFile& file : kernel_layout()) append(file.name, file.source);
    for (const KernelFile& file : path_library()) append(file.name, file.source);
    append("<test kernel>", test_source);
    return source;
}

cl::Program build_library_test_program(const ComputeDevice& device, ProgramCache& cache,
                                       std::string_view test_source, int packet_width,
                                       bool double_precision) {
    KernelSwitches switches;
    switches.packet_width = packet_width;
    switches.double_precision = double_precision;
    AssembledProgram program;
    program.source = library_test_source(test_source);
    program.options = switch_options(switches);
    return cache.build(device, program);
}

}  // namespace fgr::test
