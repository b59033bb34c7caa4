// SPDX-License-Identifier: Apache-2.0
// run_cli: registers every command's options, parses, runs the command given and turns what it
// throws into a one-line error and an exit code.
#include "cli.hpp"

#include <fmt/format.h>
#include <spdlog/sinks/stdout_color_sinks.h>
#include <spdlog/spdlog.h>

#include <CLI/CLI.hpp>
#include <cstdio>
#include <exception>
#include <string>

#include "commands.hpp"
#include "device/opencl_device.hpp"
#include "device/program_cache.hpp"
#include "distributed/cluster.hpp"
#include "reference.hpp"
#include "usage.hpp"
#include "util/interruption.hpp"
#include "util/strings.hpp"

namespace fgr {
namespace {

// Under MPI, rank 0 speaks for the job: the other ranks log warnings only, named by rank.
void configure_logging(bool verbose, const Cluster& cluster) {
    auto logger = spdlog::stderr_color_mt("fgr");
    if (cluster.coordinator()) {
        logger->set_pattern("fgr: %^%l%$: %v");
    } else {
        logger->set_pattern(fmt::format("fgr ({}): %^%l%$: %v", cluster.name()));
    }
    spdlog::set_default_logger(logger);
    const auto level = verbose ? spdlog::level::debug : spdlog::level::info;
    spdlog::set_level(cluster.coordinator() ? level : std::max(level, spdlog::level::warn));
}

int report_error(const std::string& message, int code) {
    Cluster& cluster = Cluster::current();
    // Errors are one line: keep only the first line of messages that carry more, and show any
    // control character left in it (a file name's) escaped.
    const std::string line = printable_text(message.substr(0, message.find('\n')));
    if (!cluster.coordinator()) {
        // Rank 0 prints it, naming this rank; every rank printing the same error would bury it.
        cluster.report_failure(line);
        return code;
    }
    // Said first: when a rank died, mpirun may end this one while it dismisses the others.
    std::fprintf(stderr, "fgr: error: %s\n", line.c_str());
    std::fflush(stderr);
    // No rank is left waiting for rank 0, however it ended.
    cluster.dismiss_workers();
    return code;
}

// The commands that share one render between MPI ranks.
bool runs_across_ranks(const std::string& command) {
    return command == "render" || command == "video";
}

}  // namespace

int run_cli(int argc, char** argv) {
    const Cluster& cluster = Cluster::current();
    if (!cluster.unavailable().empty()) {
        if (cluster.coordinator())
            std::fprintf(stderr, "fgr: error: %s\n", cluster.unavailable().c_str());
        return kExitFailure;
    }
    CLI::App app{"fgr: real-time ray marching of 3D fractals"};
    configure_help(app);
    app.require_subcommand(1);
    bool verbose = false;
    app.add_flag("-v,--verbose", verbose, "debug logging");
    ListOptions list_options;
    add_list_command(app, list_options);
    bool math_check = false;
    std::string info_argument;
    CLI::App* info = app.add_subcommand(
        "info",
        "list OpenCL platforms and devices; describe a scene; or print the view an image carries");
    info->add_flag("--math-check", math_check,
                   "also run (or read the cached verdicts of) the device math self-test at every "
                   "precision and packet width");
    info->add_option("scene-or-file", info_argument,
                     "a scene (an id or a scene file): describe it, as `fgr list SCENE`; a PNG, "
                     "TIFF or EXR image fgr wrote, or a view file: print the view it carries");
    RenderOptions render_options;
    add_render_command(app, render_options);
    VideoOptions video_options;
    add_video_command(app, video_options);
    MergeOptions merge_options;
    add_merge_command(app, merge_options);
    ViewCommandOptions view_options;
    add_view_command(app, view_options);
    CheckOptions check_options;
    add_check_command(app, check_options);
    NewSceneOptions new_scene_options;
    add_new_scene_command(app, new_scene_options);
    BenchOptions bench_options;
    add_bench_command(app, bench_options);
    CacheOptions cache_options;
    add_cache_command(app, cache_options);
    EnvironmentOptions environment_options;
    add_environment_command(app, environment_options);
    ReferenceOptions reference_options;
    add_reference_commands(app, reference_options);
    group_options(app);
    if (argc < 2) {
        std::fputs(overview(app).c_str(), stdout);
        return report_error("no command given", kExitUsage);
    }
    if (const std::string first = argv[1];
        !first.empty() && first.front() != '-' && !is_command(app, first)) {
        return report_error(unknown_command_message(app, first), kExitUsage);
    }
    try {
        app.parse(argc, argv);
    } catch (const CLI::CallForHelp& help) {
        return app.exit(help);
    } catch (const CLI::CallForVersion& version) {
        return app.exit(version);
    } catch (const CLI::ValidationError& error) {
        return report_error(invalid_value_message(error), kExitUsage);
    } catch (const CLI::ExtrasError& error) {
        return report_error(unexpected_arguments_message(app, error), kExitUsage);
    } catch (const CLI::RequiredError& error) {
        return report_error(required_option_message(app, error), kExitUsage);
    } catch (const CLI::ParseError& error) {
        return report_error(error.what(), kExitUsage);
    }
    configure_logging(verbose, cluster);
    const auto run_command = [&](const std::string& command) {
        if (is_reference_command(command)) {
            return command_reference(app, reference_options, command);
        }
        if (command == "list") return command_list(list_options);
        if (command == "info" && !info_argument.empty()) {
            if (math_check)
                throw UsageError("--math-check is for the devices, not a scene or file");
            return command_info_argument(info_argument);
        }
        if (command == "info") return command_info(math_check);
        if (command == "video") return command_video(video_options);
        if (command == "merge") return command_merge(merge_options);
        if (command == "view") return command_view(view_options);
        if (command == "check") return command_check(check_options);
        if (command == "new-scene") return command_new_scene(new_scene_options);
        if (command == "bench") return command_bench(bench_options);
        if (command == "cache") return command_cache(cache_options);
        if (command == "environment") return command_environment(environment_options);
        return command_render(render_options);
    };
    try {
        const std::string command = app.get_subcommands().front()->get_name();
        if (!cluster.alone() && !runs_across_ranks(command)) {
            throw UsageError(
                fmt::format("only `fgr render` and `fgr video` run across MPI ranks: "
                            "run `fgr {}` without mpirun",
                            command));
        }
        const int code = run_command(command);
        if (cluster.coordinator()) {
            // After a signal the workers stopped too, which is no failure of theirs.
            if (const std::string failure = Cluster::current().dismiss_workers();
                !failure.empty() && !interrupted()) {
                return report_error(failure, kExitFailure);
            }
        }
        return code;
    } catch (const UsageError& error) {
        return report_error(error.what(), kExitUsage);
    } catch (const KernelBuildError& error) {
        if (cluster.coordinator()) {
            std::fputs(conventional_build_log(error.build_log()).c_str(), stderr);
        }
        return report_error(error.what(), kExitFailure);
    } catch (const cl::Error& error) {
        // what() names only the call; the code says why. A GPU driver reports a kernel that
        // faulted at the next call that waits for it, as one of these two.
        const bool kernel_fault =
            error.err() == CL_INVALID_COMMAND_QUEUE || error.err() == CL_OUT_OF_RESOURCES;
        return report_error(
            fmt::format("OpenCL call {} failed: {}{}", error.what(), cl_error_name(error.err()),
                        kernel_fault ? " (a kernel before it may have faulted)" : ""),
            kExitFailure);
    } catch (const std::exception& error) {
        return report_error(error.what(), kExitFailure);
    }
}

}  // namespace fgr
