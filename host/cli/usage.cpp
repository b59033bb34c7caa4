// SPDX-License-Identifier: Apache-2.0
#include "cli/usage.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cstring>
#include <map>
#include <memory>
#include <optional>
#include <sstream>
#include <utility>

#include "util/suggest.hpp"
#include "util/version.hpp"

namespace fgr {
namespace {

// CLI11's own heading for options no one filed.
constexpr const char* kDefaultGroup = "Options";

// CLI11's help with each option's default at the end of its description, where it reads as a
// sentence, rather than glued to the type ("INT=640"). A description that already says what the
// default is (one computed at run time: "default: the scene's") keeps its own words.
class HelpFormatter : public CLI::Formatter {
public:
    std::string make_option_opts(const CLI::Option* option) const override {
        std::string text = CLI::Formatter::make_option_opts(option);
        const std::string glued = "=" + option->get_default_str();
        if (const std::size_t at = text.find(glued);
            !option->get_default_str().empty() && at != std::string::npos) {
            text.erase(at, glued.size());
        }
        return text;
    }

    std::string make_option_desc(const CLI::Option* option) const override {
        std::string text = CLI::Formatter::make_option_desc(option);
        const std::string value = option->get_default_str();
        const bool flag = option->get_type_size() == 0;
        if (!flag && !value.empty() && value != "[]" && text.find("default") == std::string::npos) {
            text += " (default: " + value + ")";
        }
        return text;
    }
};

// The heading of an option of `command` that nobody filed: one table, so an option has the same
// heading in every command that takes it. "command --name" entries win over "--name" ones.
std::string heading_of(const std::string& command, const std::string& name) {
    static const std::map<std::string, std::string> headings = {
        {"--output", "Output"},
        {"--width", "Output"},
        {"--height", "Output"},
        {"--bit-depth", "Output"},
        {"--aov", "Output"},
        {"--alpha", "Output"},
        {"--all", "Output"},
        {"--save-view", "Output"},
        {"--frames-format", "Output"},
        {"--fps", "Output"},
        {"--codec", "Output"},
        {"--crf", "Output"},
        {"--output-dir", "Output"},
        {"--dir", "Output"},
        {"--text", "Output"},
        {"video --frames", "Output"},
        {"merge --frames", "Output"},
        {"list --formulas", "Output"},
        {"list --ids", "Output"},
        {"--camera", "Camera"},
        {"--camera-path", "Camera"},
        {"--time", "Camera"},
        {"--view", "Camera"},
        {"--path", "Camera"},
        {"--start", "Camera"},
        {"video --duration", "Camera"},
        {"--set", "Scene parameters"},
        {"--colour", "Scene parameters"},
        {"--effects", "Scene parameters"},
        {"--kernel-source", "Scene parameters"},
        {"--dev", "Scene parameters"},
        {"--mode", "Render mode and quality"},
        {"--spp", "Render mode and quality"},
        {"--samples", "Render mode and quality"},
        {"--time-limit", "Render mode and quality"},
        {"--no-cost-limit", "Render mode and quality"},
        {"--prepass", "Render mode and quality"},
        {"--precision", "Render mode and quality"},
        {"--target-ms", "Render mode and quality"},
        {"--stats", "Render mode and quality"},
        {"--tile-size", "Tiles and parts"},
        {"--resume", "Tiles and parts"},
        {"--part", "Tiles and parts"},
        {"--tile", "Tiles and parts"},
        {"--frame-range", "Tiles and parts"},
        {"--device", "Device"},
        {"--packet-width", "Device"},
        {"--math-check", "Device"},
        {"bench --frames", "Benchmark"},
        {"bench --duration", "Benchmark"},
        {"--runs", "Benchmark"},
        {"--reference-spp", "Benchmark"},
        {"--repeats", "Benchmark"},
        {"--threshold", "Benchmark"},
        {"--baseline", "Benchmark"},
        {"--preset", "Window"},
        {"view --width", "Window"},
        {"view --height", "Window"},
        {"--fullscreen", "Window"},
        {"--replay", "Window"},
        {"--exit-after", "Window"},
        {"--compile", "Checks"},
        {"--only", "Checks"},
        {"--turbidity", "Sky"},
        {"--sun-elevation", "Sky"},
        {"--sun-azimuth", "Sky"},
    };
    if (const auto found = headings.find(command + " " + name); found != headings.end()) {
        return found->second;
    }
    const auto found = headings.find(name);
    return found == headings.end() ? std::string() : found->second;
}

void group_options_of(CLI::App& command) {
    for (CLI::Option* option : command.get_options()) {
        if (option->get_group() != kDefaultGroup || option->get_lnames().empty()) continue;
        const std::string heading = heading_of(command.get_name(), "--" + option->get_lnames()[0]);
        if (!heading.empty()) option->group(heading);
    }
    for (CLI::App* sub : command.get_subcommands([](CLI::App*) { return true; })) {
        group_options_of(*sub);
    }
}

// The command CLI11 was parsing when it stopped: the deepest one typed.
const CLI::App* command_parsed(const CLI::App& app) {
    const CLI::App* command = &app;
    for (;;) {
        const std::vector<const CLI::App*> typed =
            command->get_subcommands([](const CLI::App* sub) { return sub->parsed(); });
        if (typed.empty()) return command;
        command = typed.front();
    }
}

// "--width", "-o", "--output", ...: what `command` takes, as typed.
std::vector<std::string> option_names(const CLI::App& command) {
    std::vector<std::string> names;
    for (const CLI::Option* option : command.get_options([](const CLI::Option*) { return true; })) {
        for (const std::string& name : option->get_lnames()) names.push_back("--" + name);
        for (const std::string& name : option->get_snames()) names.push_back("-" + name);
    }
    return names;
}

std::string command_line_name(const CLI::App* command) {
    std::string name = command->get_name();
    for (const CLI::App* parent = command->get_parent(); parent != nullptr;
         parent = parent->get_parent()) {
        name = parent->get_name() + " " + name;
    }
    return name;
}

}  // namespace

void configure_help(CLI::App& app) {
    app.name("fgr");
    app.formatter(std::make_shared<HelpFormatter>());
    app.option_defaults()->always_capture_default();
}

void group_options(CLI::App& app) { group_options_of(app); }

std::vector<std::string> command_names(const CLI::App& app) {
    std::vector<std::string> names;
    for (const CLI::App* sub :
         app.get_subcommands([](const CLI::App* sub) { return !sub->get_group().empty(); })) {
        names.push_back(sub->get_name());
    }
    return names;
}

bool is_command(const CLI::App& app, const std::string& name) {
    return !app.get_subcommands([&](const CLI::App* sub) { return sub->get_name() == name; })
                .empty();
}

std::string overview(const CLI::App& app) {
    // The commands most people want, each with an example to copy.
    static const std::pair<const char*, const char*> kExamples[] = {
        {"fgr list", "the scenes, one a line; `fgr list SCENE` describes one"},
        {"fgr render mandelbulb -o bulb.png", "render a still (PNG, TIFF or EXR)"},
        {"fgr view mandelbulb", "explore a scene in a window"},
        {"fgr video mandelbulb --camera-path orbit -o orbit.mp4", "render a camera path to video"},
        {"fgr new-scene my-fractal", "start a scene of your own"},
    };
    std::string text =
        fmt::format("fgr {}: real-time ray marching of 3D fractals\n\n", fgr_version());
    std::size_t width = 0;
    for (const auto& example : kExamples) width = std::max(width, std::strlen(example.first));
    for (const auto& [example, what] : kExamples) {
        text += fmt::format("  {:<{}}  {}\n", example, width, what);
    }
    text += fmt::format("\nall commands: {}\n", fmt::join(command_names(app), ", "));
    text += "`fgr COMMAND --help` lists a command's options; `man fgr` and the docs say more\n";
    return text;
}

std::string unknown_command_message(const CLI::App& app, const std::string& typed) {
    const std::vector<std::string> names = command_names(app);
    return unknown_name_message(fmt::format("unknown command '{}'", typed), typed, names,
                                fmt::format(" (commands: {})", fmt::join(names, ", ")));
}

std::string invalid_value_message(const CLI::ValidationError& error) {
    const std::string message = error.what();
    // The form CLI::IsMember's check gives: "OPTION: VALUE not in {A,B,C}".
    const std::size_t choices = message.rfind(" not in {");
    const std::size_t value = message.find(": ");
    if (choices == std::string::npos || value == std::string::npos || value > choices ||
        message.back() != '}') {
        return message;
    }
    const std::string typed = message.substr(value + 2, choices - value - 2);
    std::vector<std::string> names;
    std::istringstream list(message.substr(choices + 9, message.size() - choices - 10));
    for (std::string name; std::getline(list, name, ',');) names.push_back(name);
    return message + did_you_mean(typed, names);
}

std::string unexpected_arguments_message(const CLI::App& app, const CLI::ExtrasError& error) {
    // CLI11 names the arguments only in its message: "...not expected: ARG ARG".
    const std::string message = error.what();
    const std::size_t colon = message.find(": ");
    std::vector<std::string> arguments;
    std::istringstream words(colon == std::string::npos ? "" : message.substr(colon + 2));
    for (std::string word; words >> word;) arguments.push_back(word);
    if (arguments.empty()) return message;
    const CLI::App* command = command_parsed(app);
    // CLI11 lists them last first.
    std::reverse(arguments.begin(), arguments.end());
    const auto option = std::find_if(arguments.begin(), arguments.end(), [](const std::string& a) {
        return a.size() > 1 && a.front() == '-';
    });
    if (option == arguments.end()) {
        const std::string name = command_line_name(command);
        const std::vector<std::string> commands = command_names(*command);
        if (!commands.empty()) {
            return unknown_name_message(
                fmt::format("unknown command '{}' for `{}`", arguments.front(), name),
                arguments.front(), commands,
                fmt::format(" (commands: {})", fmt::join(commands, ", ")));
        }
        return fmt::format("unexpected argument '{}' for `{}` (`{} --help` lists what it takes)",
                           arguments.front(), name, name);
    }
    const std::string typed = option->substr(0, option->find('='));
    // The option may be one of a command above, typed on the wrong side of the command's name
    // (`fgr --verbos list`): the nearest option of the commands typed, the innermost first.
    const CLI::App* owner = command;
    std::optional<std::string> nearest;
    std::size_t nearest_distance = 0;
    for (const CLI::App* level = command; level != nullptr; level = level->get_parent()) {
        const std::optional<std::string> found = closest_name(typed, option_names(*level));
        if (found && (!nearest || edit_distance(typed, *found) < nearest_distance)) {
            nearest = found;
            nearest_distance = edit_distance(typed, *found);
            owner = level;
        }
    }
    const std::string name = command_line_name(owner);
    const std::string unknown = fmt::format("unknown option '{}' for `{}`", typed, name);
    return nearest ? fmt::format("{}; did you mean '{}'?", unknown, *nearest)
                   : fmt::format("{} (`{} --help` lists its options)", unknown, name);
}

std::string required_option_message(const CLI::App& app, const CLI::RequiredError& error) {
    const std::vector<std::string> unexpected = command_parsed(app)->remaining();
    if (unexpected.empty()) return error.what();
    return unexpected_arguments_message(app, CLI::ExtrasError(unexpected));
}

}  // namespace fgr
