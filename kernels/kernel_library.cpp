// SPDX-License-Identifier: Apache-2.0
#include "fgr/kernel_library.hpp"

#include <array>
#include <string_view>

#include "fgr_bsdf_cl.h"
#include "fgr_camera_cl.h"
#include "fgr_colour_cl.h"
#include "fgr_effects_cl.h"
#include "fgr_environment_cl.h"
#include "fgr_folds_cl.h"
#include "fgr_fractals_cl.h"
#include "fgr_geometry_cl.h"
#include "fgr_ifs_cl.h"
#include "fgr_iterate_cl.h"
#include "fgr_layout_arguments_h.h"
#include "fgr_layout_camera_h.h"
#include "fgr_layout_environment_h.h"
#include "fgr_layout_lights_h.h"
#include "fgr_layout_path_h.h"
#include "fgr_layout_planes_h.h"
#include "fgr_layout_types_h.h"
#include "fgr_march_cl.h"
#include "fgr_math_check_cl.h"
#include "fgr_math_cl.h"
#include "fgr_mode_brute_cl.h"
#include "fgr_mode_path_cl.h"
#include "fgr_mode_shaded_cl.h"
#include "fgr_prepass_cl.h"
#include "fgr_probe_cl.h"
#include "fgr_sampler_cl.h"
#include "fgr_sdf_cl.h"
#include "fgr_shade_cl.h"
#include "fgr_types_cl.h"
#include "fgr_vec3_cl.h"
#include "formulas_boxes_cl.h"
#include "formulas_bulbs_cl.h"
#include "formulas_hypercomplex_cl.h"
#include "formulas_kifs_cl.h"
#include "formulas_kleinian_cl.h"

namespace fgr {

std::span<const KernelFile> kernel_prelude() {
    static constexpr std::array files{
        KernelFile{"fgr_types.cl", fgr_types_cl},
        KernelFile{"fgr_math.cl", fgr_math_cl},
        KernelFile{"fgr_vec3.cl", fgr_vec3_cl},
        KernelFile{"fgr_bsdf.cl", fgr_bsdf_cl},
        KernelFile{"fgr_sdf.cl", fgr_sdf_cl},
        KernelFile{"fgr_folds.cl", fgr_folds_cl},
        KernelFile{"fgr_colour.cl", fgr_colour_cl},
        KernelFile{"fgr_fractals.cl", fgr_fractals_cl},
        KernelFile{"fgr_iterate.cl", fgr_iterate_cl},
    };
    return files;
}

std::span<const KernelFile> formula_families() {
    static constexpr std::array files{
        KernelFile{"formulas/bulbs.cl", formulas_bulbs_cl},
        KernelFile{"formulas/hypercomplex.cl", formulas_hypercomplex_cl},
        KernelFile{"formulas/boxes.cl", formulas_boxes_cl},
        KernelFile{"formulas/kifs.cl", formulas_kifs_cl},
        KernelFile{"formulas/kleinian.cl", formulas_kleinian_cl},
    };
    return files;
}

const KernelFile* formula_family(std::string_view family) {
    for (const KernelFile& file : formula_families()) {
        const std::string_view name = file.name;
        if (name.substr(9, name.size() - 12) == family) return &file;
    }
    return nullptr;
}

std::span<const KernelFile> kernel_layout() {
    static constexpr std::array files{
        KernelFile{"shared/fgr_layout_types.h", fgr_layout_types_h},
        KernelFile{"shared/fgr_layout_camera.h", fgr_layout_camera_h},
        KernelFile{"shared/fgr_layout_environment.h", fgr_layout_environment_h},
        KernelFile{"shared/fgr_layout_path.h", fgr_layout_path_h},
        KernelFile{"shared/fgr_layout_lights.h", fgr_layout_lights_h},
        KernelFile{"shared/fgr_layout_planes.h", fgr_layout_planes_h},
        KernelFile{"shared/fgr_layout_arguments.h", fgr_layout_arguments_h},
    };
    return files;
}

std::span<const KernelFile> kernel_postlude() {
    static constexpr std::array files{
        KernelFile{"fgr_geometry.cl", fgr_geometry_cl},
        KernelFile{"fgr_march.cl", fgr_march_cl},
        KernelFile{"fgr_ifs.cl", fgr_ifs_cl},
        KernelFile{"fgr_shade.cl", fgr_shade_cl},
        KernelFile{"fgr_sampler.cl", fgr_sampler_cl},
        KernelFile{"fgr_effects.cl", fgr_effects_cl},
        KernelFile{"fgr_camera.cl", fgr_camera_cl},
        KernelFile{"fgr_prepass.cl", fgr_prepass_cl},
        KernelFile{"fgr_probe.cl", fgr_probe_cl},
    };
    return files;
}

std::span<const KernelFile> mode_files(std::string_view mode) {
    static constexpr std::array shaded{KernelFile{"fgr_mode_shaded.cl", fgr_mode_shaded_cl}};
    static constexpr std::array path{
        KernelFile{"fgr_environment.cl", fgr_environment_cl},
        KernelFile{"fgr_mode_path.cl", fgr_mode_path_cl},
    };
    static constexpr std::array brute{KernelFile{"fgr_mode_brute.cl", fgr_mode_brute_cl}};
    if (mode == "shaded") return shaded;
    if (mode == "brute") return brute;
    if (mode == "path") return path;
    return {};
}

std::span<const KernelFile> path_library() {
    static constexpr std::array files{
        KernelFile{"fgr_sampler.cl", fgr_sampler_cl},
        KernelFile{"fgr_environment.cl", fgr_environment_cl},
    };
    return files;
}

const char* math_check_source() { return fgr_math_check_cl; }

}  // namespace fgr
