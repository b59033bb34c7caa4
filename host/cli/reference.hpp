// SPDX-License-Identifier: Apache-2.0
#pragma once
// What is generated from the command line's own definitions, so that it cannot drift from them:
// the CLI reference of the docs site (markdown), the man page fgr(1) (roff), the bash and zsh
// completion scripts, and `fgr --version`. Each walks the configured CLI::App tree: every visible
// command, its arguments and its options with their names, value types, choices, defaults,
// descriptions and help groups. A command or option in the group "" is hidden: left out of all of
// them, as CLI11 leaves it out of --help.

#include <CLI/CLI.hpp>
#include <string>
#include <vector>

namespace fgr {

// How a value is completed in a shell.
enum class ValueCompletion {
    None,       // nothing to offer: a number, a name, or no value at all (a flag)
    Choices,    // one of CliOption::choices
    Scene,      // a scene id (`fgr list --ids`) or a scene file
    Files,      // a file, ending in one of CliOption::file_suffixes (any file when there are none)
    Directory,  // a directory
};

// One argument or option of a command, as the App tree defines it.
struct CliOption {
    std::vector<std::string> names;  // "-w", "--width"; an argument: its name, e.g. "scene"
    bool positional = false;
    bool flag = false;  // takes no value
    bool required = false;
    bool repeatable = false;           // an argument that takes several values
    std::string type;                  // CLI11's type name: "INT", "FLOAT", "TEXT" ...
    std::vector<std::string> checks;   // what its validators say: "INT in [1 - 16384]", ...
    std::vector<std::string> choices;  // the values IsMember accepts, when it has such a check
    std::string default_value;         // CLI11's get_default_str(): "" when none is recorded
    std::string description;
    std::string group;  // its help heading: "Options" unless the command gives another
    ValueCompletion completion = ValueCompletion::None;
    std::vector<std::string> file_suffixes;  // with ValueCompletion::Files
};

// A command, the top one included (path empty).
struct CliCommand {
    std::vector<std::string> path;  // {"bench", "accuracy"}
    std::string description;
    std::vector<CliOption> options;       // declaration order; arguments and options, -h left out
    std::vector<CliCommand> subcommands;  // the visible ones, in declaration order
    bool requires_subcommand = false;

    std::string name() const;  // "fgr bench accuracy"
};

// The visible tree under `app`.
CliCommand describe_cli(const CLI::App& app);

// The CLI reference for the docs site: one section per command, its options under their group's
// heading, defaults and allowed values shown.
std::string cli_reference_markdown(const CliCommand& top);
// The man page fgr(1).
std::string cli_man_page(const CliCommand& top);
// `source <(fgr completion bash)`: completes commands, options, choices, scene ids and files.
std::string bash_completion_script(const CliCommand& top);
// The zsh completion function _fgr (a file in $fpath, or `source <(fgr completion zsh)`).
std::string zsh_completion_script(const CliCommand& top);

// `fgr --version`: the version and commit, the plugin ABI and kernel API versions, and the OpenCL
// platforms and devices found (enumerated, nothing compiled); says so when there is none.
std::string version_text();

// `fgr completion bash|zsh` (visible) and `fgr __reference markdown|man` (hidden), and -V,
// --version on `app`. Call after every other command is added.
struct ReferenceOptions {
    std::string shell;
    std::string format;
    CLI::App* completion = nullptr;
    CLI::App* reference = nullptr;
};
void add_reference_commands(CLI::App& app, ReferenceOptions& options);
// Runs the one of them given (`command` is a subcommand of `app`); prints the script or page.
int command_reference(const CLI::App& app, const ReferenceOptions& options,
                      const std::string& command);
// Whether `command` is one of them.
bool is_reference_command(const std::string& command);

}  // namespace fgr
