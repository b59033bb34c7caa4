// SPDX-License-Identifier: Apache-2.0
// fgr list: every scene found, a line each (id, kind, description); fgr list SCENE (and fgr info
// SCENE): that scene in full, its parameters described, its cameras, camera paths and effects.
#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <string>
#include <vector>

#include "commands.hpp"
#include "device/kernel_assembly.hpp"
#include "scene/formulas/formulas.hpp"
#include "scene/ifs/ifs.hpp"
#include "scene/render_mode.hpp"
#include "scene/scene_argument.hpp"
#include "scene/text_scene.hpp"
#include "util/lower_case.hpp"
#include "util/strings.hpp"

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

// What makes the scene: "plugin", "text", "IFS", "IFS plugin", "formula" or "hybrid".
std::string scene_kind(const Scene& scene) {
    if (scene.ifs) return is_ifs_file_name(scene.plugin_file) ? "IFS" : "IFS plugin";
    if (is_formula_file_name(scene.plugin_file)) {
        const bool hybrid =
            std::find(scene.tags.begin(), scene.tags.end(), "hybrid") != scene.tags.end();
        return hybrid ? "hybrid" : "formula";
    }
    if (is_text_scene_file_name(scene.plugin_file)) return "text";
    return "plugin";
}

// `fgr list` keeps a scene to a line of about this many columns.
constexpr std::size_t kListWidth = 100;

// The scene's name and description, the name once when the description starts with it.
std::string about(const Scene& scene) {
    if (scene.description.empty()) return scene.name;
    if (scene.description.size() >= scene.name.size() &&
        lower_case(scene.description.substr(0, scene.name.size())) == lower_case(scene.name)) {
        return scene.description;
    }
    return scene.name + ": " + scene.description;
}

// `text` cut at a word to at most `width` characters, "..." marking the cut.
std::string shortened(const std::string& text, std::size_t width) {
    if (text.size() <= width) return text;
    const std::size_t room = width > 3 ? width - 3 : 0;
    std::size_t cut = text.rfind(' ', room);
    if (cut == std::string::npos || cut < room / 2) cut = room;
    while (cut > 0 && (text[cut - 1] == ' ' || text[cut - 1] == ',' || text[cut - 1] == ':')) --cut;
    return text.substr(0, cut) + "...";
}

// One line a scene, the columns aligned: id, kind, name and description.
void print_scene_lines(const std::vector<Scene>& scenes) {
    std::size_t id_width = 0, kind_width = 0;
    for (const Scene& scene : scenes) {
        id_width = std::max(id_width, scene.id.size());
        kind_width = std::max(kind_width, scene_kind(scene).size());
    }
    const std::size_t about_width =
        kListWidth - std::min(kListWidth / 2, id_width + kind_width + 4);
    for (const Scene& scene : scenes) {
        fmt::print("{:<{}}  {:<{}}  {}\n", scene.id, id_width, scene_kind(scene), kind_width,
                   shortened(about(scene), about_width));
    }
}

// The scene in full, each parameter with its description on the line under it.
void print_scene(const Scene& scene) {
    fmt::print("{}  {} - {}\n", scene.id, scene.name, scene.description);
    if (scene.ifs) {
        // An IFS file, or a plugin that handed over maps (ABI 1.3).
        fmt::print(
            "  {}: {} ({} maps; bounding sphere centre {:.4g} {:.4g} {:.4g}, radius "
            "{:.4g})\n",
            is_ifs_file_name(scene.plugin_file) ? "IFS file" : "IFS plugin",
            printable_path(scene.plugin_file), scene.ifs->maps.size(), scene.ifs->bounds.centre.x,
            scene.ifs->bounds.centre.y, scene.ifs->bounds.centre.z, scene.ifs->bounds.radius);
    } else if (is_formula_file_name(scene.plugin_file)) {
        fmt::print("  formula file: {}\n", printable_path(scene.plugin_file));
    } else if (is_text_scene_file_name(scene.plugin_file)) {
        fmt::print("  text scene: {}\n", printable_path(scene.plugin_file));
    } else {
        fmt::print("  plugin: {}\n", printable_path(scene.plugin_file));
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
        if (!param.description.empty()) {
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

void add_list_command(CLI::App& app, ListOptions& options) {
    CLI::App* list =
        app.add_subcommand("list", "list the scenes found, one a line, or one in full");
    list->add_option("scene", options.scene,
                     "describe this scene (an id or a scene file) in full: its parameters, each "
                     "described, cameras, camera paths and effects");
    list->add_flag("--formulas", options.formulas,
                   "list the formula library instead: what formula scene files may iterate");
    list->add_flag("--ids", options.ids, "print the scene ids alone, one a line (for scripts)");
}

int command_list_scene(const std::string& argument) {
    print_scene(scene_from_argument(argument));
    return 0;
}

int command_list(const ListOptions& options) {
    if (options.formulas) {
        print_formulas();
        return 0;
    }
    if (!options.scene.empty()) return command_list_scene(options.scene);
    const Discovery found = discover();
    if (options.ids) {
        for (const Scene& scene : found.scenes) fmt::print("{}\n", scene.id);
        return 0;
    }
    if (found.scenes.empty()) {
        fmt::print("no scenes found; searched:\n");
        for (const auto& dir : plugin_search_path(executable_dir()))
            fmt::print("  {}\n", printable_path(dir));
        return 0;
    }
    print_scene_lines(found.scenes);
    return 0;
}

}  // namespace fgr
