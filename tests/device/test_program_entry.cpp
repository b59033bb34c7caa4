// SPDX-License-Identifier: Apache-2.0
// The kernel cache's entries (device/program_entry.hpp): the header is checked before any byte
// reaches the driver, so a truncated, damaged, misplaced or odd entry (a FIFO, a directory, an
// empty or a huge file) is removed with one warning naming it and the program compiled again; a
// seeded fuzz test of the check (truncations, bit flips, header fields changed) accepts exactly
// the entries written and nothing else. Reproduce a fuzz failure with FGR_FUZZ_SEED=<case seed>
// FGR_FUZZ_CASES=1.
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "child_process.hpp"
#include "device/kernel_assembly.hpp"
#include "device/opencl_device.hpp"
#include "device/program_cache.hpp"
#include "device/program_entry.hpp"
#include "fuzz_rng.hpp"
#include "log_capture.hpp"
#include "test_files.hpp"
#include "test_scenes.hpp"

namespace fgr {
namespace {

namespace fs = std::filesystem;

constexpr const char* kKey = "0123456789abcdef";
constexpr std::size_t kLengthField = 16;  // the binary's length in the header

std::string some_binary(test::FuzzRng& rng, std::size_t bytes) {
    std::string binary(bytes, '\0');
    for (char& c : binary) c = static_cast<char>(rng.below(256));
    return binary;
}

TEST(ProgramEntry, AnEntryWrittenIsReadBackAsItsBinary) {
    const std::string binary("\0ELF\x7f binary \xff", 15);
    const std::string entry = program_entry(binary, kKey);
    EXPECT_EQ(entry.size(), kProgramEntryHeaderBytes + binary.size());
    const ProgramEntryCheck check = check_program_entry(entry, kKey);
    EXPECT_EQ(check.problem, "");
    EXPECT_EQ(check.binary, binary);
    EXPECT_THROW(program_entry(binary, "0123"), std::invalid_argument);
}

TEST(ProgramEntry, EachKindOfDamageIsNamed) {
    const std::string binary(1000, 'b');
    const std::string entry = program_entry(binary, kKey);
    const auto problem = [](const std::string& bytes, const std::string& key = kKey) {
        return check_program_entry(bytes, key).problem;
    };
    EXPECT_EQ(problem(""), "empty");
    EXPECT_EQ(problem(entry.substr(0, 40)), "40 bytes, shorter than its header");
    EXPECT_EQ(problem(entry.substr(0, 100)), "its header says 1000 bytes of binary but 44 follow");
    EXPECT_EQ(problem(entry + "x"), "its header says 1000 bytes of binary but 1001 follow");
    EXPECT_EQ(problem(binary), "not a kernel cache entry (no fgr header)");
    std::string flipped = entry;
    flipped[600] ^= 0x10;
    EXPECT_EQ(problem(flipped), "its binary does not match its hash");
    std::string version = entry;
    version[8] = 7;
    EXPECT_EQ(problem(version), "format version 7, not 1");
    std::string length = entry;
    length[kLengthField + 7] = '\x7f';  // a length no file has
    EXPECT_NE(problem(length).find("bytes of binary but 1000 follow"), std::string::npos);
    EXPECT_EQ(problem(entry, "fedcba9876543210"),
              "built from another program (fingerprint 0123456789abcdef)");
    EXPECT_EQ(problem(program_entry("", kKey)), "it holds no binary");
}

// Seeded cases: an entry of a random binary (1 to 3000 bytes), then 1 to 3 of: cut short, bits
// flipped (anywhere, or in the header), a header field rewritten (length, hash, fingerprint,
// version), bytes appended. The check must accept exactly the unchanged entries, and give their
// binary back.
TEST(FuzzKernelCacheEntry, OnlyUnchangedEntriesPass) {
    const std::uint64_t cases = test::fuzz_case_count(), base = test::fuzz_base_seed();
    std::uint64_t accepted = 0;
    for (std::uint64_t i = 0; i < cases; ++i) {
        const std::uint64_t seed = base + i;
        test::FuzzRng rng(seed);
        const std::string binary = some_binary(rng, rng.range(1, 3000));
        const std::string key = some_binary(rng, 16);  // any bytes: only equality matters
        const std::string entry = program_entry(binary, key);
        std::string mutated = entry;
        const int mutations = rng.chance(0.1) ? 0 : rng.range(1, 3);
        for (int m = 0; m < mutations; ++m) {
            switch (rng.below(6)) {
                case 0:  // cut short
                    mutated.resize(rng.below(mutated.size() + 1));
                    break;
                case 1:  // bits flipped anywhere
                    for (int flips = rng.range(1, 8); flips > 0 && !mutated.empty(); --flips) {
                        mutated[rng.below(mutated.size())] ^= static_cast<char>(1 << rng.below(8));
                    }
                    break;
                case 2:  // a bit of the header flipped
                    if (mutated.size() >= kProgramEntryHeaderBytes) {
                        mutated[rng.below(kProgramEntryHeaderBytes)] ^=
                            static_cast<char>(1 << rng.below(8));
                    }
                    break;
                case 3: {  // the length field rewritten: near the truth, or anything
                    if (mutated.size() < kProgramEntryHeaderBytes) break;
                    const std::uint64_t length =
                        rng.chance(0.5) ? binary.size() + rng.range(-3, 3) : rng.next();
                    for (int b = 0; b < 8; ++b) {
                        mutated[kLengthField + b] = static_cast<char>((length >> (8 * b)) & 0xff);
                    }
                    break;
                }
                case 4: {  // the hash, fingerprint or version rewritten
                    if (mutated.size() < kProgramEntryHeaderBytes) break;
                    const std::size_t at = rng.pick({8, 24, 40});
                    const std::string text = some_binary(rng, at == 8 ? 4 : 16);
                    mutated.replace(at, text.size(), text);
                    break;
                }
                default:  // bytes appended
                    mutated += some_binary(rng, rng.range(1, 64));
                    break;
            }
        }
        const ProgramEntryCheck check = check_program_entry(mutated, key);
        if (mutated == entry) {
            ++accepted;
            ASSERT_EQ(check.problem, "") << "case seed " << seed;
            ASSERT_EQ(check.binary.size(), binary.size()) << "case seed " << seed;
            ASSERT_EQ(check.binary, binary) << "case seed " << seed;
        } else {
            ASSERT_NE(check.problem, "") << "case seed " << seed << " passed a changed entry";
            ASSERT_EQ(check.problem.find('\n'), std::string::npos) << "case seed " << seed;
        }
    }
    if (cases >= 1000) {
        EXPECT_GT(accepted, cases / 20) << "the sound case is exercised too";
    }
}

// --- On disk, through ProgramCache ---------------------------------------------------------------

// A damaged entry of a real program: removed with one warning naming it and why, the program
// compiled again (one compile of a tiny program each, from the driver's own cache), and stored
// sound again. Before entries had a header, the first two crashed every later build of the
// program (a SIGSEGV inside PoCL; its assertion `buffer <= end_of_buffer`).
TEST(ProgramCacheEntries, ADamagedEntryIsRemovedWithAWarningAndCompiledAgain) {
    const ComputeDevice device = open_device(-1);
    const test::TempDir dir("fgr_program_entry");
    const Scene scene =
        test::inline_scene("real scene_de(vec3 p, PARAMS) { return v3_length(p) - 0.5f; }");
    const AssembledProgram program = assemble_program(scene, {4, 0});
    const std::string key = ProgramCache::cache_key(device, program);
    const fs::path entry = dir.path() / (key + ".bin");
    ProgramCache(dir.path(), cache_size_limit(), StoredPrograms::Always).build(device, program);
    const std::string sound = test::read_file(entry);
    ASSERT_EQ(check_program_entry(sound, key).problem, "");
    const std::string binary(check_program_entry(sound, key).binary);

    struct Damage {
        const char* name;
        std::function<void()> make;
        const char* reason;
    };
    const auto write = [&](const std::string& bytes) { test::write_text(entry, bytes); };
    std::string flipped = sound;
    flipped[sound.size() / 2] ^= 0x40;
    const std::vector<Damage> damages{
        {"cut to 100 bytes", [&] { write(sound.substr(0, 100)); }, "bytes of binary but 44 follow"},
        {"cut to half", [&] { write(sound.substr(0, sound.size() / 2)); }, "bytes of binary but"},
        {"a byte flipped", [&] { write(flipped); }, "does not match its hash"},
        {"empty", [&] { write(""); }, "(empty)"},
        {"another program's", [&] { write(program_entry(binary, "fedcba9876543210")); },
         "built from another program"},
        {"bytes the driver refuses", [&] { write(program_entry("not a program binary", key)); },
         "the driver refused it"},
        {"huge", [&] { fs::resize_file(entry, kMaxProgramEntryBytes + 1); }, "file too large"},
        {"a FIFO",
         [&] {
             fs::remove(entry);
             ASSERT_EQ(::mkfifo(entry.c_str(), 0600), 0);
         },
         "not a regular file"},
        {"a directory",
         [&] {
             fs::remove(entry);
             fs::create_directory(entry);
         },
         "not a regular file"},
    };
    for (const Damage& damage : damages) {
        SCOPED_TRACE(damage.name);
        write(sound);
        damage.make();
        BuildReport report;
        const test::LogCapture log;
        ProgramCache(dir.path(), cache_size_limit(), StoredPrograms::Always)
            .build(device, program, &report);
        EXPECT_EQ(report.origin, BuildReport::Origin::Compiled);
        const std::vector<std::string> lines = log.lines();
        ASSERT_EQ(lines.size(), 1u) << ::testing::PrintToString(lines);
        EXPECT_TRUE(lines[0].starts_with("warning kernel cache entry '" + entry.string() + "'"))
            << lines[0];
        EXPECT_NE(lines[0].find(damage.reason), std::string::npos) << lines[0];
        ASSERT_TRUE(fs::is_regular_file(entry)) << "the entry was not stored again";
        EXPECT_EQ(check_program_entry(test::read_file(entry), key).problem, "");
    }
    // And the sound entry is a disk hit, with nothing said.
    BuildReport report;
    const test::LogCapture log;
    ProgramCache(dir.path(), cache_size_limit(), StoredPrograms::Always)
        .build(device, program, &report);
    EXPECT_EQ(report.origin, BuildReport::Origin::Disk);
    EXPECT_TRUE(log.lines().empty()) << ::testing::PrintToString(log.lines());
}

// The reproducer as found, through fgr render: the scene's program's entry cut to 100 bytes,
// then to half its size. Before entries had a header, each such render crashed (SIGSEGV, PoCL's
// assertion) until `fgr cache clear`; now it succeeds, saying once per entry what was wrong.
TEST(ProgramCacheEntries, ARenderWithDamagedEntriesSucceedsAndSaysSo) {
    const test::TempDir dir("fgr_damaged_cache");
    const fs::path cache = dir.path() / "kernels";
    test::ChildOptions options;
    options.working_dir = dir.path();
    options.environment["FGR_CACHE_DIR"] = cache.string();
    options.environment[kStoredProgramsVariable] = "always";  // PoCL keeps its own otherwise
    options.environment["FGR_PLUGIN_PATH"] = std::nullopt;
    const std::vector<std::string> render{"render",   "mandelbulb", "--width", "16",
                                          "--height", "12",         "-o",      "out.png"};
    const test::RunResult first = test::run_child(test::kFgrExe, render, options);
    ASSERT_EQ(first.exit_code, 0) << first;
    std::vector<fs::path> programs;
    for (const fs::directory_entry& entry : fs::directory_iterator(cache)) {
        // The scene's program, not the math self-test's (math-<key>.txt keeps its verdict: a
        // second render does not build it).
        const fs::path verdict = cache / ("math-" + entry.path().stem().string() + ".txt");
        if (entry.path().extension() == ".bin" && !fs::exists(verdict)) {
            programs.push_back(entry.path());
        }
    }
    ASSERT_FALSE(programs.empty());
    for (const bool half : {false, true}) {
        SCOPED_TRACE(half ? "cut to half" : "cut to 100 bytes");
        for (const fs::path& program : programs) {
            fs::resize_file(program, half ? fs::file_size(program) / 2 : 100);
        }
        const test::RunResult again = test::run_child(test::kFgrExe, render, options);
        ASSERT_TRUE(again.exited) << again;
        EXPECT_EQ(again.exit_code, 0) << again;
        for (const fs::path& program : programs) {
            const std::string warning = "warning: kernel cache entry '" + program.string() + "'";
            const std::size_t at = again.err.find(warning);
            EXPECT_NE(at, std::string::npos) << again.err;
            EXPECT_EQ(again.err.find(warning, at + 1), std::string::npos) << again.err;
            EXPECT_GT(fs::file_size(program), 100u) << "stored again";
        }
    }
}

}  // namespace
}  // namespace fgr
