// fgr list: every scene found, with its parameters, cameras, camera paths and effects; fgr list
// SCENE: that scene, each parameter with its description.
#include <fmt/format.h>
#include <fmt/ranges.h>

#include <string>

#include "commands.hpp"
#include "device/kernel_assembly.hpp"
#include "scene/formulas/formulas.hpp"
#include "scene/ifs/ifs.hpp"
#include "scene/render_mode.hpp"
#include "scene/scene_argument.hpp"
#include "scene/text_scene.hpp"

namespace fgr {
namespace {

std::string range_text(const ParamInfo& param) {
    if (param.type == ParamType::Bool) return "true|false";
    // Only the choices the scene offers (ABI 1.4 colour_modes).
    if (!param.choices.empty()) return offered_choices_text(param);
    return fmt::format("[{}, {}]", param.min_value, param.max_value);
}

std::string value_text(const ParamInfo& param) {
    return param_text(param, param.default_value.data());
}

// A built-in's default the scene gave (ABI 1.4) says so.
std::string default_text(const ParamInfo& param) {
    return param.scene_default ? value_text(param) + " (scene's)" : value_text(param);
}

// Parameters are listed one line each; `described` puts each one's description under it.
void print_scene(const Scene& scene, bool described) {
    fmt::print("{}  {} - {}\n", scene.id, scene.name, scene.description);
    if (scene.ifs) {
        // An IFS file, or a plugin that handed over maps (ABI 1.3).
        fmt::print(
            "  {}: {} ({} maps; bounding sphere centre {:.4g} {:.4g} {:.4g}, radius "
            "{:.4g})\n",
            is_ifs_file_name(scene.plugin_file) ? "IFS file" : "IFS plugin",
            scene.plugin_file.string(), scene.ifs->maps.size(), scene.ifs->bounds.centre.x,
            scene.ifs->bounds.centre.y, scene.ifs->bounds.centre.z, scene.ifs->bounds.radius);
    } else if (is_formula_file_name(scene.plugin_file)) {
        fmt::print("  formula file: {}\n", scene.plugin_file.string());
    } else if (is_text_scene_file_name(scene.plugin_file)) {
        fmt::print("  text scene: {}\n", scene.plugin_file.string());
    } else {
        fmt::print("  plugin: {}\n", scene.plugin_file.string());
    }
    if (!scene.tags.empty()) fmt::print("  tags: {}\n", fmt::join(scene.tags, ", "));
    if (scene.scale != 1.0f) {
        fmt::print(
            "  scale: {} (the default ao_radius, glow_radius, aperture, fog_density and "
            "absorption follow it)\n",
            scene.scale);
    }
    fmt::print("  parameters:\n");
    for (const auto& param : scene.params) {
        if (!param_applies(scene, param)) continue;
        fmt::print("    {:<20} {:<7} {:<30} default {:<16} {} ({})\n", param.id,
                   param_type_name(param.type), range_text(param), default_text(param), param.label,
                   param.group);
        if (described && !param.description.empty()) {
            fmt::print("        {}\n", param.description);
        }
    }
    std::string cameras;
    for (const auto& camera : scene.cameras) cameras += (cameras.empty() ? "" : ", ") + camera.name;
    fmt::print("  cameras: {} (default: {})\n", cameras, scene.cameras.front().name);
    std::string paths;
    for (const auto& path : scene.camera_paths) {
        paths += fmt::format("{}{} ({}-{} s, {} keyframes)", paths.empty() ? "" : ", ", path.name,
                             path.keyframes.front().time, path.keyframes.back().time,
                             path.keyframes.size());
    }
    fmt::print("  camera paths: {}\n", paths.empty() ? "none" : paths);
    fmt::print("  effects: {}\n", effect_names(scene.effects));
    // What renders the surface, and so which modes the scene has.
    const char* surface = scene.ifs             ? "IFS maps, traced exactly (shaded, path)"
                          : scene.inside_only() ? "inside test only, no DE (brute)"
                                                : "distance estimator (shaded, path, brute)";
    fmt::print("  surface: {}; default mode {}\n", surface, render_mode_name(scene.default_mode));
    fmt::print("  path mode environment: {}\n", scene.environment.empty()
                                                    ? "sky (fgr's default)"
                                                    : scene.environment + " (the scene's own)");
}

}  // namespace

const char* distance_name(FormulaDistance distance) {
    switch (distance) {
        case FormulaDistance::Logarithmic:
            return "logarithmic";
        case FormulaDistance::Linear:
            return "linear";
        case FormulaDistance::Own:
            return "its own";
    }
    return "";
}

// The formula library: what a formula scene's "sequence" may name (scene/formulas/formulas.hpp).
void print_formulas() {
    std::string family;
    for (const Formula& formula : formula_library()) {
        if (formula.family != family) {
            family = formula.family;
            fmt::print("{}{}:\n", family == formula_library().front().family ? "" : "\n", family);
        }
        fmt::print("  {:<22} {} - {}\n", formula.name, formula.title, formula.summary);
        fmt::print("    from: {}\n", formula.origin);
        std::string distance;
        switch (formula.estimate) {
            case FormulaEstimate::Analytic:
                distance = fmt::format("distance: {}", distance_name(formula.distance));
                break;
            case FormulaEstimate::Delta:
                distance = fmt::format("distance: {}, delta estimate only",
                                       distance_name(formula.distance));
                break;
            case FormulaEstimate::Inside:
                distance = formula.distance == FormulaDistance::Own
                               ? "distance: its own alone; in a hybrid an inside test, rendered "
                                 "by brute force"
                               : "no distance estimate: an inside test, rendered by brute force";
                break;
        }
        fmt::print("    tags: {}; {}\n", fmt::join(formula.tags, ", "), distance);
        std::string params;
        for (const FormulaParam& param : formula.params) {
            params += fmt::format("{}{} [{}, {}]", params.empty() ? "" : ", ", param.id,
                                  param.min_value, param.max_value);
        }
        fmt::print("    parameters: {}\n", params.empty() ? "none" : params);
    }
}

int command_list(const std::string& scene_id, bool formulas) {
    if (formulas) {
        print_formulas();
        return 0;
    }
    if (!scene_id.empty() && scene_argument_kind(scene_id) != SceneArgumentKind::Id) {
        print_scene(scene_from_argument(scene_id), true);
        return 0;
    }
    const Discovery found = discover();
    if (!scene_id.empty()) {
        print_scene(find_scene(found, scene_id), true);
        return 0;
    }
    if (found.scenes.empty()) {
        fmt::print("no scenes found; searched:\n");
        for (const auto& dir : plugin_search_path(executable_dir()))
            fmt::print("  {}\n", dir.string());
        return 0;
    }
    for (size_t i = 0; i < found.scenes.size(); ++i) {
        if (i > 0) fmt::print("\n");
        print_scene(found.scenes[i], false);
    }
    return 0;
}

}  // namespace fgr
