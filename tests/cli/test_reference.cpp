// SPDX-License-Identifier: Apache-2.0
// What is generated from the command line's definitions (cli/reference.hpp): `fgr --version`, the
// bash and zsh completion scripts driven as a shell would, the man page through groff's warnings,
// and the markdown reference against the commands and options the App tree has.

#include <fgr/plugin.h>
#include <fmt/format.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "child_process.hpp"
#include "cli/commands.hpp"
#include "cli/reference.hpp"
#include "scene/kernel_api.hpp"
#include "test_files.hpp"
#include "util/version.hpp"

namespace fgr::reference_test {
namespace fs = std::filesystem;
using test::kFgrExe;
using test::RunResult;

std::vector<std::string> lines_of(const std::string& text) {
    std::vector<std::string> lines;
    std::istringstream stream(text);
    std::string line;
    while (std::getline(stream, line)) lines.push_back(line);
    return lines;
}

bool has_line(const std::vector<std::string>& lines, const std::string& wanted) {
    return std::find(lines.begin(), lines.end(), wanted) != lines.end();
}

std::vector<std::string> sorted(std::vector<std::string> items) {
    std::sort(items.begin(), items.end());
    return items;
}

std::string listed(const std::vector<std::string>& items) {
    std::string text;
    for (const std::string& item : items) text += (text.empty() ? "" : " ") + item;
    return "[" + text + "]";
}

// The first program of that name on PATH, or nothing.
fs::path on_path(const std::string& program) {
    const char* path = std::getenv("PATH");
    std::istringstream directories(path ? path : "");
    std::string directory;
    while (std::getline(directories, directory, ':')) {
        const fs::path candidate = fs::path(directory) / program;
        if (!directory.empty() && access(candidate.c_str(), X_OK) == 0) return candidate;
    }
    return {};
}

RunResult fgr_in(const fs::path& directory, const std::vector<std::string>& args) {
    return test::run_fgr(args, directory);
}

class ReferenceTest : public ::testing::Test {
protected:
    void SetUp() override {
        ASSERT_TRUE(fs::exists(kFgrExe)) << kFgrExe << " does not exist; build the fgr target";
    }
    // `fgr ARGS` that must succeed; its standard output.
    std::string output_of(const std::vector<std::string>& args) {
        const RunResult result = fgr_in(dir_.path(), args);
        EXPECT_TRUE(result.exited && result.exit_code == 0)
            << test::describe("fgr", args) << ": " << result;
        return result.out;
    }
    // `fgr ARGS` written to a file in the temporary directory.
    fs::path written(const std::vector<std::string>& args, const std::string& name) {
        const fs::path file = dir_.path() / name;
        test::write_text(file, output_of(args));
        return file;
    }
    test::TempDir dir_{"fgr_reference_test"};
};

// --- fgr --version -------------------------------------------------------------------------------

TEST_F(ReferenceTest, VersionNamesTheVersionCommitInterfacesAndOpenClPlatforms) {
    for (const char* flag : {"--version", "-V"}) {
        const RunResult result = fgr_in(dir_.path(), {flag});
        ASSERT_TRUE(result.exited && result.exit_code == 0) << flag << ": " << result;
        const std::vector<std::string> lines = lines_of(result.out);
        ASSERT_GE(lines.size(), 3u) << result.out;
        EXPECT_EQ(lines[0], fmt::format("fgr {} (commit {})", fgr_version(), fgr_commit()));
        EXPECT_EQ(lines[1], fmt::format("scene ABI {}.{}, kernel API {}", FGR_ABI_VERSION_MAJOR,
                                        FGR_ABI_VERSION_MINOR, kKernelApiLatest));
        for (std::size_t i = 2; i < lines.size(); ++i) {
            EXPECT_EQ(lines[i].rfind("OpenCL: ", 0), 0u) << lines[i];
        }
        EXPECT_TRUE(result.err.empty()) << result.err;
    }
    EXPECT_FALSE(fgr_version().empty());
    EXPECT_FALSE(fgr_commit().empty());
}

TEST_F(ReferenceTest, VersionWithoutAnOpenClPlatformSaysSoAndSucceeds) {
    // The ICD loader reads its drivers from OCL_ICD_VENDORS instead of /etc/OpenCL/vendors.
    test::ChildOptions options;
    options.working_dir = dir_.path();
    options.environment["OCL_ICD_VENDORS"] = dir_.path().string();
    const RunResult result = test::run_child(kFgrExe, {"--version"}, options);
    ASSERT_TRUE(result.exited && result.exit_code == 0) << result;
    EXPECT_TRUE(has_line(lines_of(result.out),
                         "OpenCL: no platform found (install an OpenCL "
                         "driver, e.g. pocl-opencl-icd)"))
        << result.out;
}

// --- bash ----------------------------------------------------------------------------------------

class BashCompletionTest : public ReferenceTest {
protected:
    void SetUp() override {
        ReferenceTest::SetUp();
        if (on_path("bash").empty()) GTEST_SKIP() << "no bash";
        script_ = written({"completion", "bash"}, "fgr.bash");
    }
    // What the script offers for the words typed, the last one being completed, as bash calls
    // the completion function (the first word is the built fgr, which lists the scene ids).
    std::vector<std::string> complete(const std::vector<std::string>& words) {
        std::vector<std::string> args = {
            "-c",
            "source \"$1\" || exit 3; shift; COMP_WORDS=(\"$@\"); "
            "COMP_CWORD=$((${#COMP_WORDS[@]} - 1)); COMP_LINE=\"${COMP_WORDS[*]}\"; "
            "COMP_POINT=${#COMP_LINE}; _fgr || exit 4; printf '%s\\n' \"${COMPREPLY[@]}\"",
            "bash", script_.string(), kFgrExe.string()};
        args.insert(args.end(), words.begin(), words.end());
        test::ChildOptions options;
        options.working_dir = dir_.path();
        options.environment["FGR_PLUGIN_PATH"] = std::nullopt;
        const RunResult result = test::run_child(on_path("bash"), args, options);
        EXPECT_TRUE(result.exited && result.exit_code == 0) << result;
        EXPECT_TRUE(result.err.empty()) << result.err;
        std::vector<std::string> offered = lines_of(result.out);
        std::erase(offered, "");
        return offered;
    }
    fs::path script_;
};

TEST_F(BashCompletionTest, CompletesCommandsOptionsChoicesAndSceneIds) {
    const auto offers = [this](const std::vector<std::string>& words, const std::string& wanted) {
        const std::vector<std::string> offered = complete(words);
        EXPECT_TRUE(has_line(offered, wanted))
            << test::describe("fgr", words) << " offers " << listed(offered) << ", not " << wanted;
    };
    const auto offers_exactly = [this](const std::vector<std::string>& words,
                                       const std::vector<std::string>& wanted) {
        EXPECT_EQ(sorted(complete(words)), sorted(wanted)) << test::describe("fgr", words);
    };
    offers_exactly({"ren"}, {"render"});
    offers({""}, "completion");
    EXPECT_FALSE(has_line(complete({""}), "__reference"));
    offers({"render", "mandel"}, "mandelbulb");
    offers_exactly({"render", "--wid"}, {"--width"});
    offers({"render", "--mode", ""}, "path");
    offers_exactly({"render", "--mode", "br"}, {"brute"});
    offers_exactly({"render", "--mode", "=", "pa"}, {"path"});
    // A number or a name completes to nothing (not to the files here: fgr.bash); past an
    // option's value comes the scene again.
    offers_exactly({"render", "--width", ""}, {});
    offers_exactly({"render", "--camera", ""}, {});
    offers_exactly({"new-scene", ""}, {});
    offers({"render", "-o", ""}, "fgr.bash");
    offers({"render", "--width", "64", "mandel"}, "mandelbulb");
    // Subcommands of subcommands, and their own options.
    offers_exactly({"cache", ""}, {"size", "clear"});
    offers({"bench", "accuracy", "--rep"}, "--repeats");
    offers_exactly({"completion", ""}, {"bash", "zsh"});
}

TEST_F(BashCompletionTest, SceneArgumentsCompleteSceneFilesAndDirectories) {
    for (const char* name : {"a.cl", "b.txt", "c.fgrview.json", "d.ifs.json", "e.so"}) {
        test::write_text(dir_.path() / name, "");
    }
    fs::create_directory(dir_.path() / "scenes");
    EXPECT_EQ(sorted(complete({"render", "./"})),
              sorted({"./a.cl", "./c.fgrview.json", "./d.ifs.json", "./e.so", "./scenes"}));
    EXPECT_EQ(sorted(complete({"render", "--kernel-source", "./"})),
              sorted({"./a.cl", "./scenes"}));
}

// --- zsh -----------------------------------------------------------------------------------------

TEST_F(ReferenceTest, ZshCompletionScriptIsValidZsh) {
    const fs::path zsh = on_path("zsh");
    // zsh is a test package (build.sh): a check that quietly skipped would never run in CI.
    ASSERT_FALSE(zsh.empty()) << "zsh not found: it is one of the test packages build.sh installs";
    const fs::path script = written({"completion", "zsh"}, "_fgr");
    const RunResult result = test::run_child(zsh, {"-n", script.string()}, {});
    EXPECT_TRUE(result.exited && result.exit_code == 0 && result.err.empty()) << result;
    // Loaded as a completion function, it defines every command's function.
    const std::string text = test::read_file(script);
    EXPECT_NE(text.find("#compdef fgr"), std::string::npos);
    EXPECT_NE(text.find("_fgr_cmd_render()"), std::string::npos);
    EXPECT_NE(text.find("_fgr_cmd_bench_accuracy()"), std::string::npos);
}

// --- The man page --------------------------------------------------------------------------------

// groff's warnings (all of them: -ww) about a man page, or nothing when groff is missing.
// groff and zsh are test packages (build.sh): the checks that need them fail without them rather
// than skip, so they cannot quietly stop running in CI.
std::string groff_warnings(const fs::path& page) {
    const fs::path groff = on_path("groff");
    EXPECT_FALSE(groff.empty()) << "groff not found: groff-base is one of the test packages";
    if (groff.empty()) return "no groff";
    const RunResult result = test::run_child(groff, {"-man", "-ww", "-z", page.string()}, {});
    EXPECT_TRUE(result.exited && result.exit_code == 0) << result;
    return result.err;
}

TEST_F(ReferenceTest, ManPageHasItsSectionsAndRendersWithoutWarnings) {
    const fs::path page = written({"__reference", "man"}, "fgr.1");
    const std::string text = test::read_file(page);
    for (const char* section : {"NAME", "SYNOPSIS", "DESCRIPTION", "OPTIONS", "COMMANDS", "FILES",
                                "ENVIRONMENT", "\"EXIT STATUS\"", "\"SEE ALSO\""}) {
        const std::string heading = std::string(".SH ") + section + "\n";
        EXPECT_NE(text.find(heading), std::string::npos) << heading;
    }
    EXPECT_NE(text.find(".SS \"fgr render"), std::string::npos);
    EXPECT_NE(text.find("\\fB\\-\\-width\\fR"), std::string::npos);
    EXPECT_NE(text.find("FGR_PLUGIN_PATH"), std::string::npos);
    EXPECT_EQ(groff_warnings(page), "");
}

// Text that roff and the shells read as syntax stays text: dashes, a leading dot or quote,
// backslashes, brackets, colons and quotes in descriptions, and characters past ASCII.
TEST(ReferenceEscaping, AwkwardDescriptionsStayText) {
    CLI::App app{"fgr: a test of awkward text"};
    CLI::App* command =
        app.add_subcommand("odd-one", ".starts with a dot, has a - dash and a \\ backslash");
    std::string value;
    command
        ->add_option("--quote", value, "'quoted' [bracketed] a:b \"double\" `code` 90\u00B0 $HOME")
        ->check(CLI::IsMember({"a", "b"}));
    command->add_option("scene", value, "'leading quote");
    app.add_subcommand("hidden", "never shown")->group("");
    const CliCommand top = describe_cli(app);

    const std::string page = cli_man_page(top);
    EXPECT_NE(page.find("\n\\&.starts with a dot, has a \\- dash and a \\e backslash\n"),
              std::string::npos)
        << page;
    EXPECT_NE(page.find("90\\[u00B0]"), std::string::npos);
    EXPECT_EQ(page.find("never shown"), std::string::npos);
    test::TempDir dir("fgr_reference_escaping");
    test::write_text(dir.path() / "odd.1", page);
    EXPECT_EQ(groff_warnings(dir.path() / "odd.1"), "") << page;

    const std::string markdown = cli_reference_markdown(top);
    EXPECT_NE(markdown.find("## fgr odd-one"), std::string::npos);
    EXPECT_EQ(markdown.find("never shown"), std::string::npos);

    for (const auto& [shell, script] : {std::pair{"bash", bash_completion_script(top)},
                                        std::pair{"zsh", zsh_completion_script(top)}}) {
        const fs::path program = on_path(shell);
        ASSERT_FALSE(program.empty()) << shell << " not found: it is one of the test packages";
        const fs::path file = dir.path() / fmt::format("completion.{}", shell);
        test::write_text(file, script);
        const RunResult result = test::run_child(program, {"-n", file.string()}, {});
        EXPECT_TRUE(result.exited && result.exit_code == 0 && result.err.empty())
            << shell << ": " << result << "\n"
            << script;
        EXPECT_EQ(script.find("never shown"), std::string::npos);
        EXPECT_EQ(script.find("hidden"), std::string::npos);
    }
}

// --- The markdown reference ----------------------------------------------------------------------

// The section of the reference about one command: from its heading to the next command's.
std::string section_of(const std::string& markdown, const std::string& command) {
    const std::string heading = "\n## " + command + "\n";
    const std::size_t start = markdown.find(heading);
    if (start == std::string::npos) return "";
    const std::size_t end = markdown.find("\n## ", start + heading.size());
    return markdown.substr(start, end == std::string::npos ? std::string::npos : end - start);
}

// The commands `fgr --help` lists: CLI11's own listing of the App tree's visible subcommands,
// one a line under its heading, indented by a few spaces (deeper lines continue a description).
std::vector<std::string> commands_in_help(const std::string& help) {
    std::vector<std::string> commands;
    bool in_section = false;
    for (const std::string& line : lines_of(help)) {
        const std::size_t indent = line.find_first_not_of(' ');
        if (line == "Subcommands:" || line == "SUBCOMMANDS:" || line == "Commands:" ||
            line == "COMMANDS:") {
            in_section = true;
        } else if (in_section && indent == std::string::npos) {
            in_section = false;
        } else if (in_section && indent > 0 && indent <= 4) {
            commands.push_back(line.substr(indent, line.find(' ', indent) - indent));
        } else if (indent == 0) {
            in_section = false;
        }
    }
    return commands;
}

TEST_F(ReferenceTest, MarkdownReferenceListsEveryCommandAndEveryRenderOption) {
    const std::string markdown = output_of({"__reference", "markdown"});
    const std::vector<std::string> commands = commands_in_help(output_of({"--help"}));
    ASSERT_GE(commands.size(), 10u) << "the commands of `fgr --help`: " << output_of({"--help"});
    for (const std::string& command : commands) {
        EXPECT_FALSE(section_of(markdown, "fgr " + command).empty()) << command;
    }
    EXPECT_TRUE(section_of(markdown, "fgr __reference").empty());
    EXPECT_FALSE(section_of(markdown, "fgr bench accuracy").empty());

    // `fgr render`'s options as add_render_command defines them, each in the render section,
    // with its default when it records one.
    CLI::App app;
    RenderOptions options;
    add_render_command(app, options);
    const CLI::App* render = app.get_subcommand("render");
    const std::string section = section_of(markdown, "fgr render");
    std::size_t checked = 0;
    for (const CLI::Option* option : render->get_options()) {
        if (option->get_group().empty() || option == render->get_help_ptr()) continue;
        const std::string name = option->get_lnames().empty() ? option->get_name(true, false)
                                                              : "--" + option->get_lnames().front();
        const std::size_t entry = section.find("- `" + name + "`");
        const std::size_t later = section.find("`" + name + "`");
        EXPECT_TRUE(entry != std::string::npos || later != std::string::npos) << name;
        if (!option->get_default_str().empty()) {
            const std::size_t line_start = std::min(entry, later);
            const std::string line =
                section.substr(line_start, section.find('\n', line_start) - line_start);
            EXPECT_NE(line.find("default: " + option->get_default_str()), std::string::npos)
                << line;
        }
        ++checked;
    }
    EXPECT_GE(checked, 30u);
    EXPECT_NE(section.find("one of: shaded, path, brute"), std::string::npos) << section;
}

// The build wrote what it generates from the fgr it built (the fgr_generated_docs target).
TEST_F(ReferenceTest, TheBuildTreeHoldsTheGeneratedFiles) {
    const fs::path build = kFgrExe.parent_path().parent_path();
    for (const char* file : {"share/man/man1/fgr.1", "share/man/man1/fgr.1.gz",
                             "share/bash-completion/completions/fgr",
                             "share/zsh/vendor-completions/_fgr", "docs/cli-reference.md"}) {
        EXPECT_TRUE(fs::is_regular_file(build / file)) << build / file;
    }
    EXPECT_EQ(test::read_file(build / "share/man/man1/fgr.1"), output_of({"__reference", "man"}));
}

}  // namespace fgr::reference_test
