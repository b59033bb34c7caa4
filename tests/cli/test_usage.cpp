// SPDX-License-Identifier: Apache-2.0
// What the command line says about itself (cli/usage.hpp, fgr list, fgr info SCENE, the progress
// of a still): the overview without a command, a line a scene, help under headings with defaults,
// "did you mean" in the errors, and a progress line that reaches 100%. None of these build a
// kernel but the progress case, whose small shaded Mandelbulb the other CLI tests build too.

#include <gtest/gtest.h>

#include <filesystem>
#include <map>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "child_process.hpp"
#include "test_files.hpp"

namespace fgr {
namespace {

using test::RunResult;

std::vector<std::string> lines_of(const std::string& text) {
    std::vector<std::string> lines;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);) lines.push_back(line);
    return lines;
}

class Usage : public ::testing::Test {
protected:
    RunResult run(const std::vector<std::string>& args,
                  const std::map<std::string, std::optional<std::string>>& environment = {}) {
        test::ChildOptions options;
        options.working_dir = dir_.path();
        options.environment = environment;
        options.environment["FGR_PLUGIN_PATH"] = std::nullopt;
        RunResult result = test::run_child(test::kFgrExe, args, options);
        EXPECT_TRUE(result.exited) << result;
        return result;
    }

    // The one error line fgr printed, after checking that it is one line and the exit code 2.
    std::string usage_error(const std::vector<std::string>& args) {
        const RunResult result = run(args);
        EXPECT_EQ(result.exit_code, 2) << result;
        const std::vector<std::string> lines = lines_of(result.err);
        EXPECT_EQ(lines.size(), 1u) << result;
        return lines.empty() ? std::string() : lines.back();
    }

    std::filesystem::path out() const { return dir_.path() / "out.png"; }

private:
    test::TempDir dir_{"fgr_usage"};
};

// `fgr` alone: what it is, named, the commands most people want with an example each, all the
// commands and where to read more; then the usual one error line and exit 2.
TEST_F(Usage, NoCommandPrintsAnOverviewNamingTheProgram) {
    const RunResult result = run({});
    EXPECT_EQ(result.exit_code, 2) << result;
    EXPECT_EQ(result.out.rfind("fgr ", 0), 0u) << result;
    const std::string first = lines_of(result.out).front();
    EXPECT_NE(first.find(": real-time ray marching of 3D fractals"), std::string::npos) << first;
    for (const char* example : {"fgr list", "fgr render mandelbulb -o bulb.png",
                                "fgr view mandelbulb", "fgr video mandelbulb", "fgr new-scene"}) {
        EXPECT_NE(result.out.find("  " + std::string(example)), std::string::npos)
            << example << ": " << result;
    }
    EXPECT_NE(result.out.find("all commands: list, info, render, video, merge, view"),
              std::string::npos)
        << result;
    EXPECT_NE(result.out.find("`fgr COMMAND --help`"), std::string::npos) << result;
    EXPECT_EQ(result.err, "fgr: error: no command given\n") << result;
}

// `fgr list`: a line a scene, in the order and number `fgr list --ids` gives, each starting with
// the id and naming the scene's kind; none longer than a wide terminal.
TEST_F(Usage, ListIsALineAScene) {
    const RunResult ids = run({"list", "--ids"});
    const RunResult listed = run({"list"});
    ASSERT_EQ(ids.exit_code, 0) << ids;
    ASSERT_EQ(listed.exit_code, 0) << listed;
    const std::vector<std::string> id_lines = lines_of(ids.out);
    const std::vector<std::string> lines = lines_of(listed.out);
    ASSERT_GT(id_lines.size(), 40u) << ids;
    ASSERT_EQ(lines.size(), id_lines.size()) << listed;
    for (std::size_t i = 0; i < lines.size(); ++i) {
        EXPECT_EQ(lines[i].rfind(id_lines[i] + " ", 0), 0u) << lines[i];
        EXPECT_LE(lines[i].size(), 100u) << lines[i];
    }
    const auto line_of = [&](const std::string& id) {
        for (const std::string& line : lines) {
            if (line.rfind(id + " ", 0) == 0) return line;
        }
        return std::string();
    };
    EXPECT_NE(line_of("mandelbulb").find(" plugin "), std::string::npos) << listed;
    EXPECT_NE(line_of("bulb-box").find(" hybrid "), std::string::npos) << listed;
    EXPECT_NE(line_of("menger-kifs").find(" formula "), std::string::npos) << listed;
    EXPECT_NE(line_of("sierpinski-ifs").find(" IFS "), std::string::npos) << listed;
    EXPECT_EQ(listed.out.find("parameters:"), std::string::npos) << "details in the short list";
}

// `fgr info SCENE` describes the scene as `fgr list SCENE` does; `fgr info` of an unknown scene
// offers the nearest one.
TEST_F(Usage, InfoOfASceneIsItsListing) {
    const RunResult info = run({"info", "mandelbulb"});
    const RunResult listed = run({"list", "mandelbulb"});
    ASSERT_EQ(info.exit_code, 0) << info;
    EXPECT_EQ(info.out, listed.out);
    EXPECT_EQ(info.out.rfind("mandelbulb  ", 0), 0u) << info;
    EXPECT_NE(info.out.find("\n        exponent n of z -> z^n + c\n"), std::string::npos) << info;
    EXPECT_EQ(usage_error({"info", "mandlebulb"}),
              "fgr: error: unknown scene 'mandlebulb'; did you mean 'mandelbulb'?");
}

// Each mistyped name is one error line offering the nearest name; a name near nothing says where
// the names are instead of listing them.
TEST_F(Usage, MistypedNamesOfferTheNearestOne) {
    const std::string o = out().string();
    EXPECT_EQ(usage_error({"rendr"}),
              "fgr: error: unknown command 'rendr'; did you mean 'render'?");
    EXPECT_EQ(usage_error({"render", "mandlebulb", "-o", o}),
              "fgr: error: unknown scene 'mandlebulb'; did you mean 'mandelbulb'?");
    EXPECT_EQ(usage_error({"render", "zzz", "-o", o}),
              "fgr: error: unknown scene 'zzz' (`fgr list` lists the scenes)");
    EXPECT_EQ(usage_error({"render", "mandelbulb", "-o", o, "--widht", "8"}),
              "fgr: error: unknown option '--widht' for `fgr render`; did you mean '--width'?");
    // The mistyped option, not the --output it left out, is what the user needs to hear first.
    EXPECT_EQ(usage_error({"render", "mandelbulb", "--widht", "8"}),
              "fgr: error: unknown option '--widht' for `fgr render`; did you mean '--width'?");
    EXPECT_EQ(usage_error({"render", "mandelbulb"}), "fgr: error: --output is required");
    EXPECT_EQ(usage_error({"cache", "clera"}),
              "fgr: error: unknown command 'clera' for `fgr cache`; did you mean 'clear'?");
    // An option of the command above, typed after the one below.
    EXPECT_EQ(usage_error({"--verbos", "list"}),
              "fgr: error: unknown option '--verbos' for `fgr`; did you mean '--verbose'?");
    EXPECT_EQ(usage_error({"list", "--zzzz"}),
              "fgr: error: unknown option '--zzzz' for `fgr list` (`fgr list --help` lists its "
              "options)");
    EXPECT_EQ(usage_error({"bench", "accuracy", "mandelbulb", "--repaets", "2"}),
              "fgr: error: unknown option '--repaets' for `fgr bench accuracy`; did you mean "
              "'--repeats'?");
    EXPECT_EQ(usage_error({"render", "mandelbulb", "-o", o, "--mode", "pth"}),
              "fgr: error: --mode: pth not in {shaded,path,brute}; did you mean 'path'?");
    EXPECT_EQ(usage_error({"render", "menger", "-o", o, "--set", "scael=2"}),
              "fgr: error: scene 'menger' has no parameter 'scael'; did you mean 'scale'?");
    EXPECT_EQ(usage_error({"render", "menger", "-o", o, "--set", "zzz=2"}),
              "fgr: error: scene 'menger' has no parameter 'zzz' (`fgr list menger` lists its "
              "parameters)");
    EXPECT_EQ(usage_error({"render", "mandelbulb", "-o", o, "--set", "colour_mode=iteratons"}),
              "fgr: error: parameter 'colour_mode' takes point|planes|axes|iterations or a number, "
              "not 'iteratons'; did you mean 'iterations'?");
    EXPECT_EQ(usage_error({"render", "mandelbulb", "-o", o, "--colour", "iteratons"}),
              "fgr: error: parameter 'colour_mode' takes point|planes|axes|iterations or a number, "
              "not 'iteratons'; did you mean 'iterations'?");
    EXPECT_EQ(usage_error({"render", "mandelbulb", "-o", o, "--camera", "tpo"}),
              "fgr: error: scene 'mandelbulb' has no camera 'tpo'; did you mean 'top'?");
    EXPECT_FALSE(std::filesystem::exists(out()));
}

// Every command's help names fgr in its usage line, files every option under a heading (none
// left in CLI11's catch-all "Options:" but --help) and gives the defaults, those computed at run
// time in words.
TEST_F(Usage, HelpFilesEveryOptionUnderAHeadingWithItsDefault) {
    const std::vector<std::vector<std::string>> commands = {{"list"},
                                                            {"info"},
                                                            {"render"},
                                                            {"video"},
                                                            {"merge"},
                                                            {"view"},
                                                            {"check"},
                                                            {"new-scene"},
                                                            {"bench"},
                                                            {"bench", "accuracy"},
                                                            {"bench", "quality"},
                                                            {"bench", "compare"},
                                                            {"cache"},
                                                            {"cache", "size"},
                                                            {"cache", "clear"},
                                                            {"environment"}};
    for (std::vector<std::string> command : commands) {
        std::string name = "fgr";
        for (const std::string& word : command) name += " " + word;
        SCOPED_TRACE(name);
        command.push_back("--help");
        const RunResult help = run(command);
        ASSERT_EQ(help.exit_code, 0) << help;
        EXPECT_NE(help.out.find("Usage: " + name + " [OPTIONS]"), std::string::npos) << help;
        const std::size_t options = help.out.find("\nOptions:\n");
        ASSERT_NE(options, std::string::npos) << help;
        const std::size_t end = help.out.find("\n\n", options + 1);
        EXPECT_EQ(help.out.substr(options, end - options),
                  "\nOptions:\n  -h,--help                   Print this help message and exit")
            << help;
    }
    const RunResult render = run({"render", "--help"});
    for (const char* heading :
         {"Output:", "Camera:", "Scene parameters:", "Render mode and quality:",
          "Path tracing (--mode path):", "Tiles and parts:", "Device:", "Projection ("}) {
        EXPECT_NE(render.out.find("\n" + std::string(heading)), std::string::npos)
            << heading << ": " << render;
    }
    EXPECT_NE(render.out.find("image width in pixels (over 16384 a side or 16 Mpx in all: "
                              "rendered in tiles) (default: 640, or the view's with --view)"),
              std::string::npos)
        << render;
    EXPECT_NE(render.out.find("noise pattern of the path tracer (default: 0)"), std::string::npos)
        << render;
    EXPECT_NE(render.out.find("scattering events per path at most (default: 8)"), std::string::npos)
        << render;
}

// A still that runs past the delay (FGR_PROGRESS_DELAY, 0 here) shows its progress on stderr: a
// line a tenth or so when stderr is a file, with a rate and an ETA, ending at 100% with the time
// it took. A quick one (the 2 s default) shows none.
TEST_F(Usage, LongStillsShowTheirProgressToTheEnd) {
    const std::vector<std::string> args = {"render", "mandelbulb", "-o", out().string(), "--width",
                                           "16",     "--height",   "12", "--spp",        "4"};
    const RunResult shown = run(args, {{"FGR_PROGRESS_DELAY", "0"}});
    ASSERT_EQ(shown.exit_code, 0) << shown;
    std::vector<std::string> progress;
    for (const std::string& line : lines_of(shown.err)) {
        if (line.rfind("render ", 0) == 0) progress.push_back(line);
    }
    ASSERT_GE(progress.size(), 2u) << shown;
    EXPECT_EQ(progress.front().rfind("render 0% | ", 0), 0u) << shown;
    EXPECT_NE(progress[1].find("samples/s | ETA "), std::string::npos) << shown;
    EXPECT_EQ(progress.back().rfind("render 100% | ", 0), 0u) << shown;
    EXPECT_NE(progress.back().find("samples/s | took "), std::string::npos) << shown;
    const RunResult quick = run(args, {{"FGR_PROGRESS_DELAY", std::nullopt}});
    ASSERT_EQ(quick.exit_code, 0) << quick;
    EXPECT_EQ(quick.err.find("\nrender "), std::string::npos) << quick;
}

}  // namespace
}  // namespace fgr
