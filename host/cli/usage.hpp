// SPDX-License-Identifier: Apache-2.0
#pragma once
// What the command line says about itself: the overview `fgr` alone prints, the help's headings
// and defaults, and the one-line errors for a mistyped command or option, each offering the
// nearest name (util/suggest.hpp).

#include <CLI/CLI.hpp>
#include <string>
#include <vector>

namespace fgr {

// Names the program `fgr` in every usage line and shows each option's default in its help. Call
// before adding the commands: they inherit both.
void configure_help(CLI::App& app);
// Files every option still in CLI11's default group under its heading ("Output", "Camera",
// "Scene parameters", ...). Call after adding every command's options.
void group_options(CLI::App& app);

// The overview `fgr` prints without a command: what it is, the commands most people want with an
// example each, and where to read more.
std::string overview(const CLI::App& app);

// The commands, as typed, hidden ones left out.
std::vector<std::string> command_names(const CLI::App& app);
// Whether `name` is one of the app's commands (hidden ones included).
bool is_command(const CLI::App& app, const std::string& name);
// "unknown command 'rendr'; did you mean 'render'?" (or the commands there are).
std::string unknown_command_message(const CLI::App& app, const std::string& typed);
// CLI11's "The following arguments were not expected: ..." as fgr says it, for the command being
// parsed: "unknown option '--widht' for `fgr render`; did you mean '--width'?".
std::string unexpected_arguments_message(const CLI::App& app, const CLI::ExtrasError& error);
// CLI11 checks required options before it refuses unknown ones, so `fgr render mandelbulb --widht
// 8` would hear only that --output is required: an argument the command does not take, if any, is
// named first (as unexpected_arguments_message does), since it is likely what was meant.
std::string required_option_message(const CLI::App& app, const CLI::RequiredError& error);

// CLI11's message for a value outside an option's choices ("--mode: pth not in
// {shaded,path,brute}") with the nearest choice offered.
std::string invalid_value_message(const CLI::ValidationError& error);

}  // namespace fgr
