// SPDX-License-Identifier: Apache-2.0
// fgr check: the numerical checks of diagnostics/scene_check.hpp on one scene, given by id or as a
// scene file, with a report a scene's author can act on; --compile only builds the kernel (what
// the SDK template's build runs, so a typo in the .cl fails `cmake --build` with its file and
// line).
#include <fmt/format.h>

#include <cstdio>
#include <optional>
#include <string>

#include "commands.hpp"
#include "device/program_cache.hpp"
#include "diagnostics/scene_check.hpp"
#include "view_options.hpp"

namespace fgr {
void add_check_command(CLI::App& app, CheckOptions& options) {
    CLI::App* check = app.add_subcommand(
        "check", "check a scene's distance estimator and views, and say what to fix");
    check
        ->add_option("scene", options.scene,
                     "scene id (see `fgr list`) or scene file: .so, .ifs.json, .formula.json, .cl; "
                     "or a view file (.fgrview.json): its scene at its parameter values")
        ->required();
    check->add_flag("--compile", options.compile_only,
                    "only compile the scene's kernel: errors name the .cl file and line");
    std::vector<std::string> names = scene_check_names();
    check->add_option("--only", options.only, "run one check")->check(CLI::IsMember(names));
    check->add_option("--set", options.assignments,
                      "check at a parameter's value, as `fgr render --set` takes it: id=value "
                      "(repeatable)");
    check->add_flag("--dev", options.dev,
                    "read the scene's .cl file from disk instead of the copy the plugin embeds");
    add_device_options(check, options.device, options.packet_width);
}

namespace {

// A view file checks its scene at the view's parameter values, under those --set gives.
CheckOptions with_view_applied(CheckOptions options) {
    if (!is_view_file_name(options.scene)) return options;
    const ViewFile view = load_view_argument(options.scene);
    options.scene = view.scene_file.empty() ? view.scene_id : view.scene_file;
    std::vector<std::string> assignments;
    for (const ViewParameter& parameter : view.parameters) {
        assignments.push_back(parameter_assignment(parameter));
    }
    assignments.insert(assignments.end(), options.assignments.begin(), options.assignments.end());
    options.assignments = std::move(assignments);
    return options;
}

}  // namespace

int command_check(const CheckOptions& typed_options) {
    const CheckOptions options = with_view_applied(typed_options);
    const Scene loaded = scene_from_argument(options.scene);
    const Scene scene = scene_as_used(loaded, options.dev);
    std::vector<float> params = default_param_values(scene);
    for (const std::string& assignment : options.assignments) {
        set_param_from_text(scene, params, assignment);  // a UsageError names the parameter
    }
    const ComputeDevice device = open_requested_device(options.device);
    ProgramCache cache(ProgramCache::default_directory());
    std::optional<SceneChecker> built;
    try {
        built.emplace(device, cache, scene, options.packet_width, params);  // compiles the kernel
    } catch (const KernelBuildError& error) {
        std::fputs(conventional_build_log(error.build_log()).c_str(), stderr);
        const std::string summary = fmt::format(
            "the kernel of scene '{}' does not compile (errors above, in {}){}", scene.id,
            scene.source_name, error.hint().empty() ? "" : ": " + error.hint());
        throw RuntimeFailure(summary);
    }
    SceneChecker& checker = *built;
    if (options.compile_only) {
        fmt::print("{}: the kernel compiles ({})\n", scene.id, scene.source_name);
        return 0;
    }
    const SceneCheckReport report = checker.run_all(options.only);
    fmt::print("{}", format_check_report(report));
    return report.passed() ? 0 : kExitFailure;
}

}  // namespace fgr
