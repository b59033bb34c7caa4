// SPDX-License-Identifier: Apache-2.0
#include "device/kernel_assembly.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "fgr/kernel_library.hpp"
#include "fgr/plugin.h"
#include "scene/kernel_api.hpp"
#include "scene/parameters.hpp"

namespace fgr {
namespace {

// A file name is quoted in #line, so quotes, backslashes and newlines in it are replaced.
std::string line_directive_name(std::string name) {
    for (char& c : name) {
        if (c == '"' || c == '\\' || c == '\n' || c == '\r') c = '_';
    }
    return name;
}

void append_file(std::string& out, const std::string& name, const char* source) {
    out += fmt::format("#line 1 \"{}\"\n", line_directive_name(name));
    out += source;
    if (!out.empty() && out.back() != '\n') out += '\n';
}

bool is_identifier_char(char c) {
    return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_';
}

// The library functions a family file defines: `inline TYPE formula_NAME(` at a line's start (its
// formulas, their distances and the steps scenes share).
std::vector<std::string> family_functions(std::string_view family_source) {
    std::vector<std::string> names;
    for (size_t at = family_source.find("inline "); at != std::string_view::npos;
         at = family_source.find("inline ", at + 1)) {
        if (at > 0 && family_source[at - 1] != '\n') continue;
        const size_t name = family_source.find("formula_", at);
        const size_t open = family_source.find('(', at);
        if (name == std::string_view::npos || open == std::string_view::npos || name > open)
            continue;
        names.emplace_back(family_source.substr(name, open - name));
    }
    return names;
}

// Whether `source` calls `function`: its name as a whole word, then "(".
bool calls(std::string_view source, const std::string& function) {
    for (size_t at = source.find(function); at != std::string_view::npos;
         at = source.find(function, at + 1)) {
        if (at > 0 && is_identifier_char(source[at - 1])) continue;
        std::string_view rest = source.substr(at + function.size());
        while (!rest.empty() && (rest.front() == ' ' || rest.front() == '\t'))
            rest.remove_prefix(1);
        if (rest.starts_with("(")) return true;
    }
    return false;
}

// The formula families whose functions `source` calls, in the library's order: a scene plugin
// iterates the library's steps as a formula scene does, and a program holds only the families
// it uses. (No family calls another's functions.)
std::vector<const KernelFile*> formula_families_called(std::string_view source) {
    static const std::vector<std::vector<std::string>> functions = [] {
        std::vector<std::vector<std::string>> all;
        for (const KernelFile& family : formula_families()) {
            all.push_back(family_functions(family.source));
        }
        return all;
    }();
    std::vector<const KernelFile*> used;
    if (source.find("formula_") == std::string_view::npos) return used;
    for (size_t i = 0; i < formula_families().size(); ++i) {
        if (std::any_of(functions[i].begin(), functions[i].end(),
                        [&](const std::string& function) { return calls(source, function); })) {
            used.push_back(&formula_families()[i]);
        }
    }
    return used;
}

// A parameter reads as the uniform value it is: the same in every lane, so `float`, `int` and (from
// kernel API 4) `float3`, whose components are plain floats at every packet width. Before API 4 a
// vec3 parameter reads as a vec3 of lanes, as scenes written then pass it to the vec3 helpers.
std::string accessor(const ParamInfo& param, int offset, int kernel_api,
                     const SpecialisedParam* constant) {
    // A whole number (specialisation_for), written exactly; the float keeps `param_x` a float.
    const std::string slot = constant ? fmt::format("{}.0f", static_cast<long>(constant->value))
                                      : fmt::format("fgr_params[{}]", offset);
    switch (param.type) {
        case ParamType::Float:
            return fmt::format("#define param_{} ({})\n", param.id, slot);
        case ParamType::Int:
            return fmt::format("#define param_{} ((int){})\n", param.id, slot);
        case ParamType::Bool:
            return fmt::format("#define param_{} ({} != 0.0f)\n", param.id, slot);
        case ParamType::Vec3:
        case ParamType::Colour:
            return fmt::format(
                "#define param_{} {}(fgr_params[{}], fgr_params[{}], fgr_params[{}]){}\n", param.id,
                kernel_api >= 4 ? "((float3)" : "v3_splat", offset, offset + 1, offset + 2,
                kernel_api >= 4 ? ")" : "");
    }
    return {};
}

}  // namespace

std::string param_accessors(const Scene& scene, int kernel_api,
                            const std::vector<SpecialisedParam>& specialised) {
    std::string out;
    const auto offsets = param_offsets(scene);
    for (size_t i = 0; i < scene.params.size(); ++i) {
        const auto constant =
            std::find_if(specialised.begin(), specialised.end(),
                         [&](const SpecialisedParam& s) { return s.id == scene.params[i].id; });
        out += accessor(scene.params[i], offsets[i], kernel_api,
                        constant == specialised.end() ? nullptr : &*constant);
    }
    return out;
}

std::vector<SpecialisedParam> specialisation_for(const Scene& scene,
                                                 const std::vector<float>& params) {
    std::vector<SpecialisedParam> specialised;
    const auto offsets = param_offsets(scene);
    for (const std::string& id : declared_specialisable(scene.source)) {
        const auto param = std::find_if(scene.params.begin(), scene.params.end(),
                                        [&](const ParamInfo& p) { return p.id == id; });
        if (param == scene.params.end() ||
            (param->type != ParamType::Int && param->type != ParamType::Float)) {
            throw std::invalid_argument(fmt::format(
                "{}: FGR_SPECIALISABLE names '{}', which is not an int or float parameter of "
                "scene '{}'",
                scene.source_name, id, scene.id));
        }
        const size_t offset = size_t(offsets[size_t(param - scene.params.begin())]);
        if (offset >= params.size()) continue;
        const float value = params[offset];
        if (std::isfinite(value) && std::floor(value) == value &&
            std::fabs(value) <= kMaxSpecialisedValue) {
            specialised.push_back({id, value});
        }
    }
    return specialised;
}

void set_specialised_values(const Scene& scene, const std::vector<SpecialisedParam>& specialised,
                            std::vector<float>& params) {
    const auto offsets = param_offsets(scene);
    for (const SpecialisedParam& constant : specialised) {
        for (size_t i = 0; i < scene.params.size(); ++i) {
            const size_t offset = size_t(offsets[i]);
            if (scene.params[i].id == constant.id && offset < params.size()) {
                params[offset] = constant.value;
            }
        }
    }
}

std::string specialisation_mismatch(const Scene& scene,
                                    const std::vector<SpecialisedParam>& specialised,
                                    const std::vector<float>& params) {
    const auto offsets = param_offsets(scene);
    for (const SpecialisedParam& constant : specialised) {
        for (size_t i = 0; i < scene.params.size(); ++i) {
            if (scene.params[i].id != constant.id) continue;
            const size_t offset = size_t(offsets[i]);
            if (offset >= params.size() || params[offset] != constant.value) {
                return fmt::format("the kernel was built with {} = {}, and the frame asks for {}",
                                   constant.id, constant.value,
                                   offset < params.size() ? params[offset] : 0.0f);
            }
        }
    }
    return "";
}

std::string build_error_hint(int kernel_api, std::string_view log) {
    // Clang's words: "initializing 'const float' with an expression of incompatible type 'real'
    // (aka 'float16')", "passing 'float3' (vector of 3 'float' values) to parameter of
    // incompatible type 'vec3'".
    for (size_t start = 0; start < log.size();) {
        const size_t end = std::min(log.find('\n', start), log.size());
        const std::string_view line = log.substr(start, end - start);
        start = end + 1;
        if (line.find("incompatible type") == std::string_view::npos) continue;
        if (kernel_api < 4 && line.find("type 'real'") != std::string_view::npos) {
            return fmt::format(
                "a `real` holds one value per lane of a packet, not a float: keep such values "
                "`real`; a vec3 parameter's components (param_<id>.z) are `real` lanes in kernel "
                "API {}, and from kernel API 4 (`#define FGR_KERNEL_API 4` on a line of its own) "
                "a vec3 parameter reads as a uniform float3 whose components are floats",
                kernel_api);
        }
        if (kernel_api >= 4 && line.find("'float3'") != std::string_view::npos &&
            line.find("'vec3'") != std::string_view::npos) {
            return "from kernel API 4 a vec3 or colour parameter is a uniform float3: where a vec3 "
                   "is wanted, pass v3_uniform(param_<id>), the same vector in every lane";
        }
    }
    return "";
}

std::string switch_options(const KernelSwitches& switches) {
    std::string options = fmt::format("-DFGR_WIDTH={}", switches.packet_width);
    for (const EffectSwitch& effect : effect_switches()) {
        if (switches.effects & effect.bit) options += fmt::format(" -D{}", effect.macro);
    }
    if (switches.stats) options += " -DFGR_STATS";
    if (switches.double_precision) options += " -DFGR_DOUBLE";
    if (switches.aovs) options += " -DFGR_AOVS";
    // Parameters compiled in: the library writes out what constants let the compiler fold.
    if (!switches.specialised.empty()) options += " -DFGR_SPECIALISED";
    // A plain literal (`z * 2.0`) is a double in OpenCL C, which a float packet refuses ("scalar
    // operand type has greater rank"), while a double build takes it: a scene could work on one
    // device and not another. In float builds literals are made single precision, so scenes
    // written the way the maths reads compile in both; double builds keep them double.
    if (!switches.double_precision) options += " -cl-single-precision-constant";
    return options;
}

bool pairs_tiles(const Scene& scene, const KernelSwitches& switches) {
    return switches.mode == RenderMode::Shaded && switches.packet_width > 1 &&
           scene.has_distance_estimator() && scene.pairs_distances() &&
           (switches.effects & FGR_EFFECT_GLOW) == 0;
}

AssembledProgram assemble_program(const Scene& scene, const KernelSwitches& switches) {
    check_supported_effects(scene, switches.effects);
    AssembledProgram program;
    program.options = switch_options(switches);
    if (pairs_tiles(scene, switches)) program.options += " -DFGR_PAIRED_TILES";
    std::string& source = program.source;
    // The library shows the scene the names of the kernel API version its source is written for.
    const int kernel_api = declared_kernel_api(scene.source);
    program.kernel_api = kernel_api;
    append_file(source, "<kernel API>",
                fmt::format("#define FGR_KERNEL_API {}\n", kernel_api).c_str());
    for (const auto& file : kernel_prelude()) append_file(source, file.name, file.source);
    append_file(source, fmt::format("<parameters of {}>", scene.id),
                param_accessors(scene, kernel_api, switches.specialised).c_str());
    const std::vector<const KernelFile*> families = formula_families_called(scene.source);
    if (!families.empty() && kernel_api < 2) {
        throw std::invalid_argument(
            fmt::format("scene '{}' calls the formula library ({}), which needs kernel API 2: put "
                        "`#define FGR_KERNEL_API 2` on a line of its own in {}",
                        scene.id, families.front()->name, scene.source_name));
    }
    for (const KernelFile* family : families) append_file(source, family->name, family->source);
    append_file(source, scene.source_name, scene.source.c_str());
    for (const auto& file : kernel_layout()) append_file(source, file.name, file.source);
    for (const auto& file : kernel_postlude()) append_file(source, file.name, file.source);
    for (const auto& file : mode_files(render_mode_name(switches.mode))) {
        append_file(source, file.name, file.source);
    }
    return program;
}

}  // namespace fgr
