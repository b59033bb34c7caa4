// SPDX-License-Identifier: Apache-2.0
// fgr new-scene: a scene plugin project from the SDK template, ready to build, or (--text) one text
// scene file, ready to render.
#include <fmt/format.h>

#include <filesystem>
#include <string>
#include <vector>

#include "cli/scaffold.hpp"
#include "commands.hpp"

namespace fgr {

void add_new_scene_command(CLI::App& app, NewSceneOptions& options) {
    CLI::App* command = app.add_subcommand(
        "new-scene",
        "create a scene plugin project from the SDK template, ready to build, or (--text) a text "
        "scene file, ready to render");
    command->add_option("name", options.name, "scene id, e.g. my-kifs")->required();
    command->add_option("--dir", options.directory,
                        "project directory (default: ./NAME); with --text, the folder the file "
                        "goes into (default: .)");
    command->add_flag("--text", options.text,
                      "write one text scene file, NAME.cl: the description in its first comment, "
                      "the OpenCL source after it; fgr opens it as it is, no build");
}

int command_new_scene(const NewSceneOptions& options) {
    if (options.text) {
        const std::filesystem::path file =
            scaffold_text_scene(options.name, options.directory.empty() ? "." : options.directory);
        fmt::print(
            "created text scene '{0}': {1}\n"
            "next:\n"
            "  fgr render {1} -o {0}.png\n"
            "  fgr view {1}        # reloads it whenever you save it\n",
            options.name, file.string());
        return 0;
    }
    const std::filesystem::path directory =
        std::filesystem::path(options.directory.empty() ? options.name : options.directory);
    const std::filesystem::path prefix = executable_dir().parent_path();
    const std::vector<std::filesystem::path> files =
        scaffold_scene(options.name, directory, prefix);
    fmt::print("created scene '{}' in {}:\n", options.name, directory.string());
    for (const auto& file : files) fmt::print("  {}\n", file.string());
    const std::string dir = directory.string();
    fmt::print(
        "next:\n"
        "  cmake -S {0} -B {0}/build && cmake --build {0}/build\n"
        "  cmake --build {0}/build --target install-scene   # into ~/.local/share/fgr/plugins\n"
        "  fgr render {1} -o {1}.png\n",
        dir, options.name);
    return 0;
}

}  // namespace fgr
