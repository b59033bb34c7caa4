// SPDX-License-Identifier: Apache-2.0
// The CLI reference, the man page, the completion scripts and `fgr --version`, generated from the
// configured CLI::App tree (reference.hpp).
#include "reference.hpp"

#include <fgr/plugin.h>
#include <fmt/format.h>
#include <fmt/ranges.h>

#include <CL/opencl.hpp>
#include <algorithm>
#include <cctype>
#include <cstdint>
#include <cstdio>
#include <initializer_list>
#include <string_view>

#include "commands.hpp"
#include "device/cache_directory.hpp"
#include "device/program_cache.hpp"
#include "scene/kernel_api.hpp"
#include "util/strings.hpp"
#include "util/version.hpp"

namespace fgr {
// A named namespace, not an anonymous one: fgr_cli's sources compile in unity batches, where the
// file-local names of every file in a batch share one translation unit.
namespace cli_reference {

// --- Reading the App tree ------------------------------------------------------------------------

bool has_name(const CliOption& option, std::string_view name) {
    return std::find(option.names.begin(), option.names.end(), name) != option.names.end();
}

// How a value completes: its choices, a scene, a file of the kinds the option reads, a
// directory, or nothing. Scene arguments are named "scene" everywhere; the options that name files
// and directories are listed here, by name (any other value, a number or a name such as --camera,
// completes to nothing rather than to files it cannot be).
void choose_completion(CliOption& option) {
    if (option.flag) return;
    const auto named = [&option](std::initializer_list<std::string_view> names) {
        return std::any_of(names.begin(), names.end(),
                           [&option](std::string_view name) { return has_name(option, name); });
    };
    if (!option.choices.empty()) {
        option.completion = ValueCompletion::Choices;
    } else if (named({"scene", "--scene"})) {
        option.completion = ValueCompletion::Scene;
    } else if (named({"--frames", "--dir", "--directory", "--output-dir"})) {
        option.completion = ValueCompletion::Directory;
    } else if (named({"file", "parts", "--output", "--replay"})) {
        option.completion = ValueCompletion::Files;
    } else if (named({"--kernel-source"})) {
        option.completion = ValueCompletion::Files;
        option.file_suffixes = {".cl"};
    } else if (named({"--view"})) {
        option.completion = ValueCompletion::Files;
        option.file_suffixes = {".fgrview.json", ".png", ".exr", ".tif", ".tiff"};
    } else if (named({"--save-view"})) {
        option.completion = ValueCompletion::Files;
        option.file_suffixes = {".fgrview.json"};
    } else if (named({"--camera-path"})) {
        option.completion = ValueCompletion::Files;
        option.file_suffixes = {".json"};
    } else if (named({"--environment"})) {
        option.completion = ValueCompletion::Files;
        option.file_suffixes = {".hdr", ".exr"};
    }
}

CliOption describe_option(const CLI::Option& source) {
    CliOption option;
    option.positional =
        source.get_positional() && source.get_snames().empty() && source.get_lnames().empty();
    if (option.positional) {
        option.names.push_back(source.get_name(true, false));
    } else {
        for (const std::string& name : source.get_snames()) option.names.push_back("-" + name);
        for (const std::string& name : source.get_lnames()) option.names.push_back("--" + name);
    }
    option.flag = source.get_items_expected_max() == 0;
    option.required = source.get_required();
    option.repeatable = source.get_items_expected_max() > 1;
    // CLI11's type name is the value's type, then what each validator says, ':' between them;
    // IsMember says "{a,b,c}".
    const std::vector<std::string> parts = split(source.get_type_name(), ':');
    option.type = option.flag ? "" : parts.front();
    for (std::size_t i = 1; i < parts.size(); ++i) {
        const std::string& part = parts[i];
        if (part.size() >= 2 && part.front() == '{' && part.back() == '}') {
            for (std::string& choice :
                 split(std::string_view(part).substr(1, part.size() - 2), ','))
                if (!choice.empty()) option.choices.push_back(std::move(choice));
        } else if (!part.empty()) {
            option.checks.push_back(part);
        }
    }
    option.default_value = source.get_default_str();
    option.description = source.get_description();
    option.group = source.get_group();
    choose_completion(option);
    return option;
}

CliCommand describe_command(const CLI::App& app, std::vector<std::string> path) {
    CliCommand command;
    command.path = std::move(path);
    command.description = app.get_description();
    command.requires_subcommand = app.get_require_subcommand_min() > 0;
    for (const CLI::Option* option : app.get_options()) {
        // Hidden options have no group; -h is every command's and documented once.
        if (option->get_group().empty() || option == app.get_help_ptr() ||
            option == app.get_help_all_ptr()) {
            continue;
        }
        command.options.push_back(describe_option(*option));
    }
    // Option groups are nameless subcommands; hidden commands have no group.
    for (const CLI::App* sub : app.get_subcommands([](const CLI::App*) { return true; })) {
        if (sub->get_name().empty() || sub->get_group().empty()) continue;
        std::vector<std::string> sub_path = command.path;
        sub_path.push_back(sub->get_name());
        command.subcommands.push_back(describe_command(*sub, std::move(sub_path)));
    }
    return command;
}

std::vector<const CliCommand*> all_commands(const CliCommand& top) {
    std::vector<const CliCommand*> commands;
    for (const CliCommand& sub : top.subcommands) {
        commands.push_back(&sub);
        for (const CliCommand* nested : all_commands(sub)) commands.push_back(nested);
    }
    return commands;
}

std::string joined(const std::vector<std::string>& parts, std::string_view separator) {
    return fmt::format("{}", fmt::join(parts, separator));
}

// "fgr render [OPTIONS] [scene]", "fgr merge [OPTIONS] parts...", "fgr cache COMMAND".
std::string usage(const CliCommand& command) {
    std::string text = command.name();
    bool has_options = false;
    for (const CliOption& option : command.options) has_options |= !option.positional;
    if (has_options) text += " [OPTIONS]";
    if (!command.subcommands.empty())
        text += command.requires_subcommand ? " COMMAND" : " [COMMAND]";
    for (const CliOption& option : command.options) {
        if (!option.positional) continue;
        const std::string name = option.names.front() + (option.repeatable ? "..." : "");
        text += option.required ? " " + name : " [" + name + "]";
    }
    return text;
}

// The groups of a command's options, in the order they first appear.
std::vector<std::string> option_groups(const CliCommand& command) {
    std::vector<std::string> groups;
    for (const CliOption& option : command.options) {
        if (option.positional) continue;
        if (std::find(groups.begin(), groups.end(), option.group) == groups.end()) {
            groups.push_back(option.group);
        }
    }
    return groups;
}

// What an option's entry says after its description: the default, the choices, the checks.
std::vector<std::string> option_facts(const CliOption& option) {
    std::vector<std::string> facts;
    if (!option.choices.empty()) facts.push_back("one of: " + joined(option.choices, ", "));
    for (const std::string& check : option.checks) facts.push_back(check);
    if (!option.default_value.empty()) facts.push_back("default: " + option.default_value);
    if (option.required && !option.positional) facts.push_back("required");
    return facts;
}

// --- Markdown ------------------------------------------------------------------------------------

// Text for markdown: characters markdown would read as markup escaped, `code spans` kept.
std::string markdown_text(std::string_view text) {
    std::string out;
    bool in_code = false;
    for (char c : text) {
        if (c == '`') in_code = !in_code;
        if (!in_code && c == '<') {
            out += "&lt;";
            continue;
        }
        if (!in_code && std::string_view("\\*_[]").find(c) != std::string_view::npos) out += '\\';
        out += c;
    }
    return out;
}

// `text` as a code span (none of the generated names has a backtick).
std::string code(std::string_view text) { return fmt::format("`{}`", text); }

std::string option_signature(const CliOption& option) {
    std::vector<std::string> names;
    for (const std::string& name : option.names) names.push_back(code(name));
    std::string text = joined(names, ", ");
    if (!option.flag && !option.positional && !option.type.empty()) {
        text += " " + code(option.type + (option.repeatable ? " ..." : ""));
    }
    return text;
}

void markdown_options(std::string& out, const CliCommand& command) {
    bool has_arguments = false;
    for (const CliOption& option : command.options) has_arguments |= option.positional;
    if (has_arguments) {
        out += "### Arguments\n\n";
        for (const CliOption& option : command.options) {
            if (!option.positional) continue;
            std::vector<std::string> facts = option_facts(option);
            facts.insert(facts.begin(), option.required ? "required" : "optional");
            if (option.repeatable) facts.insert(facts.begin() + 1, "one or more");
            out +=
                fmt::format("- {} ({}): {}", code(option.names.front()),
                            markdown_text(joined(facts, "; ")), markdown_text(option.description));
            out += "\n";
        }
        out += "\n";
    }
    for (const std::string& group : option_groups(command)) {
        out += fmt::format("### {}\n\n", markdown_text(group));
        for (const CliOption& option : command.options) {
            if (option.positional || option.group != group) continue;
            out += fmt::format("- {}: {}", option_signature(option),
                               markdown_text(option.description));
            const std::vector<std::string> facts = option_facts(option);
            if (!facts.empty()) out += fmt::format(" ({})", markdown_text(joined(facts, "; ")));
            out += "\n";
        }
        out += "\n";
    }
}

// The heading's anchor as MkDocs makes it: "fgr new-scene" becomes "fgr-new-scene".
std::string anchor(const CliCommand& command) { return joined(split(command.name(), ' '), "-"); }

// --- roff ----------------------------------------------------------------------------------------

// Text for a man page line: backslashes and hyphens escaped, non-ASCII characters as \[uXXXX],
// `code spans` in bold.
std::string roff_text(std::string_view text) {
    std::string out;
    bool in_code = false;
    for (std::size_t i = 0; i < text.size(); ++i) {
        const auto byte = static_cast<unsigned char>(text[i]);
        if (text[i] == '`') {
            out += in_code ? "\\fR" : "\\fB";
            in_code = !in_code;
        } else if (text[i] == '\\') {
            out += "\\e";
        } else if (text[i] == '-') {
            out += "\\-";
        } else if (text[i] == '\n') {
            out += ' ';
        } else if (byte < 0x80) {
            out += text[i];
        } else {
            // Decode one UTF-8 sequence; a malformed byte becomes U+FFFD.
            const int length = byte >= 0xF0 ? 4 : byte >= 0xE0 ? 3 : byte >= 0xC0 ? 2 : 1;
            uint32_t code_point = length == 1 ? 0xFFFD : byte & (0x3F >> (length - 1));
            for (int k = 1; k < length; ++k) {
                if (i + 1 >= text.size() ||
                    (static_cast<unsigned char>(text[i + 1]) & 0xC0) != 0x80) {
                    code_point = 0xFFFD;
                    break;
                }
                code_point = (code_point << 6) | (static_cast<unsigned char>(text[++i]) & 0x3F);
            }
            out += fmt::format("\\[u{:04X}]", code_point);
        }
    }
    if (in_code) out += "\\fR";
    // A line starting with a dot or a quote would be read as a request.
    if (!out.empty() && (out.front() == '.' || out.front() == '\'')) out.insert(0, "\\&");
    return out;
}

std::string roff_option_tag(const CliOption& option) {
    std::vector<std::string> names;
    for (const std::string& name : option.names) {
        names.push_back(option.positional ? "\\fI" + roff_text(name) + "\\fR"
                                          : "\\fB" + roff_text(name) + "\\fR");
    }
    std::string tag = joined(names, ", ");
    if (!option.flag && !option.positional && !option.type.empty()) {
        tag += " \\fI" + roff_text(option.type) + "\\fR" + (option.repeatable ? " ..." : "");
    }
    return tag;
}

void roff_entry(std::string& out, const std::string& tag, const std::string& text) {
    out += ".TP\n" + tag + "\n" + text + "\n";
}

void roff_options(std::string& out, const CliCommand& command) {
    for (const CliOption& option : command.options) {
        if (!option.positional) continue;
        std::string text = roff_text(option.description);
        const std::vector<std::string> facts = option_facts(option);
        if (!facts.empty()) text += " (" + roff_text(joined(facts, "; ")) + ")";
        roff_entry(out, roff_option_tag(option), text);
    }
    const std::vector<std::string> groups = option_groups(command);
    for (const std::string& group : groups) {
        // One group needs no heading of its own.
        if (groups.size() > 1) out += ".PP\n\\fI" + roff_text(group) + ":\\fR\n";
        for (const CliOption& option : command.options) {
            if (option.positional || option.group != group) continue;
            std::string text = roff_text(option.description);
            const std::vector<std::string> facts = option_facts(option);
            if (!facts.empty()) text += " (" + roff_text(joined(facts, "; ")) + ")";
            roff_entry(out, roff_option_tag(option), text);
        }
    }
}

// The top description without a leading "fgr: ", for the NAME line.
std::string summary(const CliCommand& top) {
    std::string text = top.description;
    for (std::string_view prefix : {"fgr: ", "fgr - ", "fgr "}) {
        if (text.rfind(prefix, 0) == 0) {
            text.erase(0, prefix.size());
            break;
        }
    }
    return text.empty() ? "real-time ray marching of 3D fractals" : text;
}

// --- Shell completion ----------------------------------------------------------------------------

// `text` inside single quotes, for bash and zsh.
std::string single_quoted(std::string_view text) {
    std::string out = "'";
    for (char c : text) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return out + "'";
}

// How a value completes, as the bash script's _fgr_complete reads it.
std::string bash_value_kind(const CliOption& option) {
    switch (option.completion) {
        case ValueCompletion::None:
            return "none";
        case ValueCompletion::Choices:
            return "choices:" + joined(option.choices, " ");
        case ValueCompletion::Scene:
            return "scene";
        case ValueCompletion::Files:
            return "files:" + joined(option.file_suffixes, " ");
        case ValueCompletion::Directory:
            return "directory";
    }
    return "none";
}

std::string command_key(const CliCommand& command) { return joined(command.path, " "); }

// A command's function name in the zsh script: _fgr_cmd_bench_accuracy.
std::string zsh_function(const CliCommand& command) {
    std::string name = "_fgr_cmd";
    for (const std::string& part : command.path) {
        name += '_';
        for (char c : part) name += std::isalnum(static_cast<unsigned char>(c)) ? c : '_';
    }
    return command.path.empty() ? "_fgr" : name;
}

// A description inside a zsh _arguments spec's brackets.
std::string zsh_description(std::string_view text) {
    std::string out;
    for (char c : text) {
        if (c == '\n') {
            out += ' ';
            continue;
        }
        if (c == '[' || c == ']' || c == ':' || c == '\\') out += '\\';
        out += c;
    }
    return out;
}

std::string zsh_action(const CliOption& option) {
    switch (option.completion) {
        case ValueCompletion::None:
            return " ";
        case ValueCompletion::Choices:
            return "(" + joined(option.choices, " ") + ")";
        case ValueCompletion::Scene:
            return "_fgr_scenes";
        case ValueCompletion::Directory:
            return "_files -/";
        case ValueCompletion::Files: {
            if (option.file_suffixes.empty()) return "_files";
            std::vector<std::string> suffixes;
            for (const std::string& suffix : option.file_suffixes)
                suffixes.push_back(suffix.substr(1));
            if (suffixes.size() == 1) return "_files -g \"*." + suffixes.front() + "\"";
            return "_files -g \"*.(" + joined(suffixes, "|") + ")\"";
        }
    }
    return " ";
}

// The _arguments spec of one option or argument, single-quoted for the script.
std::string zsh_spec(const CliOption& option) {
    const std::string message =
        option.positional ? option.names.front() : (option.type.empty() ? "value" : option.type);
    if (option.positional) {
        if (option.repeatable) return single_quoted("*:" + message + ":" + zsh_action(option));
        return single_quoted((option.required ? ":" : "::") + message + ":" + zsh_action(option));
    }
    std::string value;
    if (!option.flag) value = ":" + zsh_description(message) + ":" + zsh_action(option);
    const std::string description = "[" + zsh_description(option.description) + "]";
    if (option.names.size() == 1) {
        return single_quoted((option.repeatable ? "*" : "") + option.names.front() + description +
                             value);
    }
    // '(-w --width)'{-w,--width}'[image width]:INT: '
    const std::string exclusions = option.repeatable ? "*" : "(" + joined(option.names, " ") + ")";
    return single_quoted(exclusions) + "{" + joined(option.names, ",") + "}" +
           single_quoted(description + value);
}

void zsh_command_function(std::string& out, const CliCommand& command) {
    out += zsh_function(command) + "() {\n";
    std::vector<std::string> specs;
    const CliOption* first_argument = nullptr;
    for (const CliOption& option : command.options) {
        if (option.positional && !command.subcommands.empty()) {
            // With subcommands, the first word is a subcommand or this command's first argument.
            if (first_argument == nullptr) first_argument = &option;
            continue;
        }
        specs.push_back(zsh_spec(option));
    }
    specs.push_back("'(- *)'{-h,--help}'[print help and exit]'");
    if (command.path.empty()) out += "    local fgr_program=${words[1]}\n";
    if (command.subcommands.empty()) {
        out += "    _arguments -s -S \\\n";
        for (const std::string& spec : specs) out += "        " + spec + " \\\n";
        out += "        && return\n    return 1\n}\n\n";
        return;
    }
    out += "    local curcontext=\"$curcontext\" state line\n";
    out += "    _arguments -C -s -S \\\n";
    for (const std::string& spec : specs) out += "        " + spec + " \\\n";
    out += "        ': :->command' '*:: :->argument' && return\n";
    out += "    case $state in\n    command)\n        local -a commands\n        commands=(\n";
    for (const CliCommand& sub : command.subcommands) {
        out += "            " + single_quoted(sub.path.back() + ":" + sub.description) + "\n";
    }
    out += "        )\n        _describe -t commands 'command' commands\n";
    if (first_argument != nullptr) {
        if (first_argument->completion == ValueCompletion::Scene) {
            out += "        _fgr_scenes\n";
        } else if (first_argument->completion != ValueCompletion::None) {
            out += "        " + zsh_action(*first_argument) + "\n";
        }
    }
    out += "        ;;\n    argument)\n        case $words[1] in\n";
    for (const CliCommand& sub : command.subcommands) {
        out += "        " + single_quoted(sub.path.back()) + ") " + zsh_function(sub) + " ;;\n";
    }
    out += "        esac\n        ;;\n    esac\n}\n\n";
}

// --- fgr --version -------------------------------------------------------------------------------

std::string trimmed(std::string text) {
    while (!text.empty() && (text.back() == '\0' || text.back() == ' ')) text.pop_back();
    // Drivers pad their version strings with runs of spaces.
    std::string out;
    for (char c : text) {
        if (c == ' ' && !out.empty() && out.back() == ' ') continue;
        out += c;
    }
    return out;
}

// One line per OpenCL platform: its name and version and its devices' names. Enumerating opens
// no context and compiles nothing.
std::vector<std::string> opencl_platform_lines() {
    std::vector<std::string> lines;
    try {
        std::vector<cl::Platform> platforms;
        if (cl::Platform::get(&platforms) != CL_SUCCESS) return lines;
        for (const cl::Platform& platform : platforms) {
            std::vector<std::string> names;
            try {
                std::vector<cl::Device> devices;
                platform.getDevices(CL_DEVICE_TYPE_ALL, &devices);
                for (const cl::Device& device : devices) {
                    names.push_back(trimmed(device.getInfo<CL_DEVICE_NAME>()));
                }
            } catch (const cl::Error&) {
                // A platform without devices reports CL_DEVICE_NOT_FOUND.
            }
            lines.push_back(fmt::format(
                "OpenCL: {} ({}), {}", trimmed(platform.getInfo<CL_PLATFORM_NAME>()),
                trimmed(platform.getInfo<CL_PLATFORM_VERSION>()),
                names.empty()
                    ? "no devices"
                    : (names.size() == 1 ? "device " : "devices ") + joined(names, ", ")));
        }
    } catch (const cl::Error&) {
        // No ICD loader configuration reports CL_PLATFORM_NOT_FOUND_KHR: no platform.
    }
    return lines;
}

// --- What reference.hpp declares (wrapped below) -------------------------------------------------

CliCommand describe_cli(const CLI::App& app) { return describe_command(app, {}); }

std::string cli_reference_markdown(const CliCommand& top) {
    std::string out = "# Command-line reference\n\n";
    out += fmt::format(
        "<!-- Generated from fgr's command-line definitions by `fgr __reference markdown`. -->\n\n"
        "fgr {}: {}. Every command takes `-h`, `--help`, which prints its part of this page; "
        "the man page (`man fgr`) has all of it.\n\n",
        fgr_version(), markdown_text(summary(top)));
    out += fmt::format("Usage: `{}`\n\n", usage(top));
    out += "## Commands\n\n";
    for (const CliCommand* command : all_commands(top)) {
        out += fmt::format("- [{}](#{}): {}\n", code(command->name()), anchor(*command),
                           markdown_text(command->description));
    }
    out += "\n## Global options\n\n";
    out += "Given before the command.\n\n";
    CliCommand global = top;
    for (CliOption& option : global.options) option.group = "Options";
    std::string options;
    markdown_options(options, global);
    // The global options' one group needs no heading of its own.
    const std::string heading = "### Options\n\n";
    if (options.rfind(heading, 0) == 0) options.erase(0, heading.size());
    out += options;
    for (const CliCommand* command : all_commands(top)) {
        out += fmt::format("## {}\n\n{}\n\nUsage: {}\n\n", command->name(),
                           markdown_text(command->description), code(usage(*command)));
        if (!command->subcommands.empty()) {
            out += "Commands:\n\n";
            for (const CliCommand& sub : command->subcommands) {
                out += fmt::format("- [{}](#{}): {}\n", code(sub.name()), anchor(sub),
                                   markdown_text(sub.description));
            }
            out += "\n";
        }
        markdown_options(out, *command);
    }
    while (out.size() > 1 && out[out.size() - 2] == '\n') out.pop_back();
    return out;
}

std::string cli_man_page(const CliCommand& top) {
    std::string out;
    out += ".\\\" Generated from fgr's command-line definitions by `fgr __reference man`.\n";
    out += fmt::format(".TH FGR 1 \"\" \"fgr {}\" \"User Commands\"\n", roff_text(fgr_version()));
    out += ".SH NAME\nfgr \\- " + roff_text(summary(top)) + "\n";
    out += ".SH SYNOPSIS\n";
    out +=
        ".B fgr\n.RI [ options ]\n.I command\n.RI [ command\\ options ]\n"
        ".RI [ arguments ]\n.br\n.B fgr \\-\\-version\n.br\n"
        ".B fgr\n.I command\n.B \\-\\-help\n";
    out += ".SH DESCRIPTION\n";
    out += roff_text(
               "fgr renders 3D fractals on OpenCL devices: scenes are plugins, formula, IFS and "
               "text scene files found on the plugin path (see FILES). `fgr list` shows the "
               "scenes, `fgr render` renders one to an image, `fgr view` opens the interactive "
               "viewer and `fgr video` renders a camera path to a video.") +
           "\n";
    out +=
        ".SH OPTIONS\nGiven before the command; every command also takes \\fB\\-h\\fR, "
        "\\fB\\-\\-help\\fR.\n";
    CliCommand global = top;
    for (CliOption& option : global.options) option.group = "Options";
    roff_options(out, global);
    out += ".SH COMMANDS\n";
    for (const CliCommand* command : all_commands(top)) {
        out += ".SS \"" + roff_text(usage(*command)) + "\"\n";
        out += roff_text(command->description) + "\n";
        if (!command->subcommands.empty()) {
            std::vector<std::string> names;
            for (const CliCommand& sub : command->subcommands) {
                names.push_back("\\fB" + roff_text(sub.path.back()) + "\\fR");
            }
            out += ".PP\nCommands: " + joined(names, ", ") + " (below).\n";
        }
        roff_options(out, *command);
    }
    out += ".SH FILES\n";
    roff_entry(out, "\\fI" + roff_text(FGR_MAN_PLUGIN_DIR) + "\\fR",
               roff_text("The built-in scenes: plugins (.so), formula, IFS and text scene files."));
    roff_entry(out, "\\fI~/.local/share/fgr/plugins\\fR",
               roff_text("Your own scenes, searched after the built-in ones (`fgr new-scene` "
                         "makes one)."));
    roff_entry(out, "\\fI" + roff_text(FGR_MAN_KERNEL_DIR) + "\\fR",
               roff_text("The OpenCL C kernel library the scenes are compiled with."));
    roff_entry(out, "\\fI" + roff_text(FGR_MAN_SCHEMA_DIR) + "\\fR",
               roff_text("JSON Schemas of the files fgr reads and writes (view files, camera "
                         "paths, formula and IFS scenes)."));
    roff_entry(out, "\\fI$XDG_CACHE_HOME/fgr/kernels\\fR, \\fI~/.cache/fgr/kernels\\fR",
               roff_text("The kernel cache: compiled programs (for drivers that keep none of "
                         "their own: PoCL keeps its own in ~/.cache/pocl), the device math "
                         "self-test's verdicts and the scene index. `fgr cache size` and `fgr "
                         "cache clear` manage it."));
    out += ".SH ENVIRONMENT\n";
    roff_entry(out, "\\fBFGR_PLUGIN_PATH\\fR",
               roff_text("Directories (separated by colons) searched for scenes before the "
                         "built-in ones."));
    roff_entry(out, "\\fBFGR_CACHE_DIR\\fR",
               roff_text("The kernel cache directory, instead of $XDG_CACHE_HOME/fgr/kernels."));
    roff_entry(out, fmt::format("\\fB{}\\fR", roff_text(kCacheLimitVariable)),
               roff_text(fmt::format("The kernel cache's size limit in MiB (default {}); the "
                                     "least recently used entries are evicted past it.",
                                     kDefaultCacheLimitBytes >> 20)));
    roff_entry(out, fmt::format("\\fB{}\\fR", roff_text(kStoredProgramsVariable)),
               roff_text("always: store compiled programs in the kernel cache for every driver, "
                         "PoCL too (whose own cache keeps them otherwise); auto (the default): "
                         "only for drivers that keep none."));
    roff_entry(out, "\\fBFGR_MPI_RANK0_RENDERS\\fR",
               roff_text("Under mpirun, 0 keeps rank 0 to coordinating the other ranks instead of "
                         "rendering too."));
    roff_entry(out, "\\fBXDG_CACHE_HOME\\fR, \\fBHOME\\fR",
               roff_text("Where the kernel cache and your own scenes are, unless told otherwise."));
    out += ".SH \"EXIT STATUS\"\n";
    roff_entry(out, "\\fB0\\fR", "Success.");
    roff_entry(out, fmt::format("\\fB{}\\fR", kExitFailure),
               roff_text("A failure while running: a kernel that does not compile, a file that "
                         "cannot be written, no OpenCL device; `fgr check`: a check failed."));
    roff_entry(out, fmt::format("\\fB{}\\fR", kExitUsage),
               roff_text("Bad input: an unknown command or option, a value out of range, a "
                         "scene or file that cannot be read."));
    out += ".PP\n" +
           roff_text("Errors are one line on standard error, starting with \"fgr: error: \".") +
           "\n";
    out += ".SH \"SEE ALSO\"\n.BR clinfo (1),\n.BR mpirun (1),\n.BR ffmpeg (1)\n";
    return out;
}

std::string bash_completion_script(const CliCommand& top) {
    std::vector<const CliCommand*> commands = all_commands(top);
    commands.insert(commands.begin(), &top);
    std::string out = fmt::format(
        "# bash completion for fgr {}, generated by `fgr completion bash`.\n"
        "# Load it with: source <(fgr completion bash)\n\n",
        fgr_version());
    out += "# _fgr_commands COMMAND: REPLY is the subcommands of COMMAND (\"\": fgr's).\n";
    out += "_fgr_commands() {\n    case $1 in\n";
    for (const CliCommand* command : commands) {
        if (command->subcommands.empty()) continue;
        std::vector<std::string> names;
        for (const CliCommand& sub : command->subcommands) names.push_back(sub.path.back());
        out += fmt::format("    {}) REPLY={} ;;\n", single_quoted(command_key(*command)),
                           single_quoted(joined(names, " ")));
    }
    out += "    *) REPLY='' ;;\n    esac\n}\n\n";
    out += "# _fgr_options COMMAND: REPLY is the options of COMMAND.\n";
    out += "_fgr_options() {\n    case $1 in\n";
    for (const CliCommand* command : commands) {
        std::vector<std::string> names;
        for (const CliOption& option : command->options) {
            if (option.positional) continue;
            for (const std::string& name : option.names) names.push_back(name);
        }
        names.push_back("-h");
        names.push_back("--help");
        out += fmt::format("    {}) REPLY={} ;;\n", single_quoted(command_key(*command)),
                           single_quoted(joined(names, " ")));
    }
    out += "    *) REPLY='' ;;\n    esac\n}\n\n";
    out +=
        "# _fgr_value COMMAND OPTION: REPLY is how the option's value completes (none,\n"
        "# choices:..., scene, files:SUFFIX..., directory), '' for a flag or an unknown "
        "option.\n";
    out += "_fgr_value() {\n    case $1/$2 in\n";
    for (const CliCommand* command : commands) {
        for (const CliOption& option : command->options) {
            if (option.positional || option.flag) continue;
            std::vector<std::string> patterns;
            for (const std::string& name : option.names) {
                patterns.push_back(single_quoted(command_key(*command) + "/" + name));
            }
            out += fmt::format("    {}) REPLY={} ;;\n", joined(patterns, "|"),
                               single_quoted(bash_value_kind(option)));
        }
    }
    out += "    *) REPLY='' ;;\n    esac\n}\n\n";
    out += "# _fgr_argument COMMAND N: REPLY is how COMMAND's argument N (from 0) completes.\n";
    out += "_fgr_argument() {\n    REPLY=''\n    case $1 in\n";
    for (const CliCommand* command : commands) {
        std::vector<std::string> cases;
        int index = 0;
        for (const CliOption& option : command->options) {
            if (!option.positional) continue;
            // An argument that takes several values takes all the words from its place on.
            const std::string pattern = option.repeatable ? "*" : std::to_string(index);
            cases.push_back(
                fmt::format("{}) REPLY={} ;;", pattern, single_quoted(bash_value_kind(option))));
            if (option.repeatable) break;
            ++index;
        }
        if (cases.empty()) continue;
        out += fmt::format("    {}) case $2 in {} esac ;;\n", single_quoted(command_key(*command)),
                           joined(cases, " "));
    }
    out += "    esac\n}\n\n";
    out +=
        R"sh(# Adds to COMPREPLY the files under $cur ending in one of the suffixes given
# (any file when none is), and the directories.
_fgr_files() {
    local file suffix
    compopt -o filenames 2>/dev/null
    while IFS= read -r file; do
        if [[ $# -eq 0 || -d $file ]]; then
            COMPREPLY+=("$file")
            continue
        fi
        for suffix in "$@"; do
            if [[ $file == *"$suffix" ]]; then
                COMPREPLY+=("$file")
                break
            fi
        done
    done < <(compgen -f -- "$cur")
}

# Adds to COMPREPLY the values of one kind (as _fgr_value and _fgr_argument say) that start
# with $cur. Scene ids come from the fgr being completed (`fgr list --ids`).
_fgr_complete() {
    case $1 in
    choices:*)
        mapfile -t -O "${#COMPREPLY[@]}" COMPREPLY < <(compgen -W "${1#choices:}" -- "$cur")
        ;;
    scene)
        local ids
        ids=$("${COMP_WORDS[0]}" list --ids 2>/dev/null)
        mapfile -t -O "${#COMPREPLY[@]}" COMPREPLY < <(compgen -W "$ids" -- "$cur")
        _fgr_files .fgrview.json .cl .ifs.json .formula.json .so
        ;;
    files:) _fgr_files ;;
    files:*)
        local suffixes
        read -r -a suffixes <<<"${1#files:}"
        _fgr_files "${suffixes[@]}"
        ;;
    directory)
        compopt -o filenames 2>/dev/null
        mapfile -t -O "${#COMPREPLY[@]}" COMPREPLY < <(compgen -d -- "$cur")
        ;;
    esac
}

_fgr() {
    local cur=${COMP_WORDS[COMP_CWORD]} prev='' command='' arguments=0 i word REPLY
    COMPREPLY=()
    # The words before the cursor: commands, options and the values they take, arguments.
    for ((i = 1; i < COMP_CWORD; i++)); do
        word=${COMP_WORDS[i]}
        if [[ $word == -* ]]; then
            [[ $word == *=* ]] && continue
            _fgr_value "$command" "$word"
            if [[ -n $REPLY ]] && ((i + 1 < COMP_CWORD)); then
                i=$((i + 1))
                # --mode=path split at the '=' (COMP_WORDBREAKS)
                if [[ ${COMP_WORDS[i]} == = ]] && ((i + 1 < COMP_CWORD)); then
                    i=$((i + 1))
                fi
            fi
            continue
        fi
        _fgr_commands "$command"
        if ((arguments == 0)) && [[ " $REPLY " == *" $word "* ]]; then
            command=${command:+$command }$word
            continue
        fi
        arguments=$((arguments + 1))
    done
    # The value of an option: `--mode pa`, `--mode=pa` (two or three words), `--mode=`.
    if [[ $cur == = ]]; then
        cur='' prev=${COMP_WORDS[COMP_CWORD - 1]}
    elif ((COMP_CWORD >= 2)) && [[ ${COMP_WORDS[COMP_CWORD - 1]} == = ]]; then
        prev=${COMP_WORDS[COMP_CWORD - 2]}
    elif ((COMP_CWORD >= 1)); then
        prev=${COMP_WORDS[COMP_CWORD - 1]}
    fi
    if [[ $cur == --*=* ]]; then
        prev=${cur%%=*} cur=${cur#*=}
    fi
    if [[ $prev == -* ]]; then
        _fgr_value "$command" "$prev"
        if [[ -n $REPLY ]]; then
            _fgr_complete "$REPLY"
            return 0
        fi
    fi
    if [[ $cur == -* ]]; then
        _fgr_options "$command"
        mapfile -t COMPREPLY < <(compgen -W "$REPLY" -- "$cur")
        return 0
    fi
    if ((arguments == 0)); then
        _fgr_commands "$command"
        [[ -n $REPLY ]] && mapfile -t COMPREPLY < <(compgen -W "$REPLY" -- "$cur")
    fi
    _fgr_argument "$command" "$arguments"
    [[ -n $REPLY ]] && _fgr_complete "$REPLY"
    return 0
}

complete -F _fgr fgr
)sh";
    return out;
}

std::string zsh_completion_script(const CliCommand& top) {
    std::string out = fmt::format(
        "#compdef fgr\n"
        "# zsh completion for fgr {}, generated by `fgr completion zsh`.\n"
        "# Install it as _fgr in a directory of $fpath, or load it with:\n"
        "#   source <(fgr completion zsh)\n\n",
        fgr_version());
    out += R"sh(# Scene ids (from the fgr being completed: `fgr list --ids`) and scene files.
_fgr_scenes() {
    local -a ids expl
    ids=(${(f)"$(${fgr_program:-fgr} list --ids 2>/dev/null)"})
    _wanted scenes expl 'scene id' compadd -a ids
    _files -g "*.(fgrview.json|cl|ifs.json|formula.json|so)"
}

)sh";
    std::vector<const CliCommand*> commands = all_commands(top);
    for (auto it = commands.rbegin(); it != commands.rend(); ++it) {
        zsh_command_function(out, **it);
    }
    zsh_command_function(out, top);
    out += R"sh(if [[ $zsh_eval_context[-1] == loadautofunc ]]; then
    _fgr "$@"
else
    compdef _fgr fgr
fi
)sh";
    return out;
}

std::string version_text() {
    std::string text = fmt::format("fgr {} (commit {})\n", fgr_version(), fgr_commit());
    text += fmt::format("scene ABI {}.{}, kernel API {}\n", FGR_ABI_VERSION_MAJOR,
                        FGR_ABI_VERSION_MINOR, kKernelApiLatest);
    const std::vector<std::string> platforms = opencl_platform_lines();
    if (platforms.empty()) {
        text += "OpenCL: no platform found (install an OpenCL driver, e.g. pocl-opencl-icd)\n";
    }
    for (const std::string& line : platforms) text += line + "\n";
    return text;
}

void add_reference_commands(CLI::App& app, ReferenceOptions& options) {
    // CLI11 prints the text and a newline.
    app.set_version_flag(
        "-V,--version",
        [] {
            std::string text = version_text();
            if (!text.empty() && text.back() == '\n') text.pop_back();
            return text;
        },
        "print the version, the scene ABI and kernel API versions and the OpenCL platforms found, "
        "and exit");
    options.completion = app.add_subcommand(
        "completion", "print the completion script for a shell: source <(fgr completion bash)");
    options.completion->add_option("shell", options.shell, "the shell: bash or zsh")
        ->required()
        ->check(CLI::IsMember({"bash", "zsh"}));
    // Hidden (no group): what the build writes into the man page and the docs site.
    options.reference =
        app.add_subcommand("__reference", "print the CLI reference (markdown) or the man page");
    options.reference->group("");
    options.reference->add_option("format", options.format, "markdown or man")
        ->required()
        ->check(CLI::IsMember({"markdown", "man"}));
}

bool is_reference_command(const std::string& command) {
    return command == "completion" || command == "__reference";
}

}  // namespace cli_reference

std::string CliCommand::name() const {
    std::string text = "fgr";
    for (const std::string& part : path) text += " " + part;
    return text;
}

CliCommand describe_cli(const CLI::App& app) { return cli_reference::describe_cli(app); }
std::string cli_reference_markdown(const CliCommand& top) {
    return cli_reference::cli_reference_markdown(top);
}
std::string cli_man_page(const CliCommand& top) { return cli_reference::cli_man_page(top); }
std::string bash_completion_script(const CliCommand& top) {
    return cli_reference::bash_completion_script(top);
}
std::string zsh_completion_script(const CliCommand& top) {
    return cli_reference::zsh_completion_script(top);
}
std::string version_text() { return cli_reference::version_text(); }
void add_reference_commands(CLI::App& app, ReferenceOptions& options) {
    cli_reference::add_reference_commands(app, options);
}
bool is_reference_command(const std::string& command) {
    return cli_reference::is_reference_command(command);
}
int command_reference(const CLI::App& app, const ReferenceOptions& options,
                      const std::string& command) {
    const CliCommand top = fgr::describe_cli(app);
    std::string text;
    if (command == "completion") {
        text = options.shell == "zsh" ? zsh_completion_script(top) : bash_completion_script(top);
    } else {
        text = options.format == "man" ? cli_man_page(top) : cli_reference_markdown(top);
    }
    std::fwrite(text.data(), 1, text.size(), stdout);
    return 0;
}

}  // namespace fgr
