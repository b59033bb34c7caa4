// SPDX-License-Identifier: Apache-2.0
// The kernel cache directory: which files are entries (programs and math self-test verdicts), the
// size limit from FGR_CACHE_MAX_MB, eviction of the least recently used, clearing; and
// ProgramCache keeping its disk entries that way (a disk hit marks the entry used, a store evicts
// what the limit cannot hold).
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "child_process.hpp"
#include "device/cache_directory.hpp"
#include "device/kernel_assembly.hpp"
#include "device/opencl_device.hpp"
#include "device/program_cache.hpp"
#include "scene/scene_index.hpp"
#include "scoped_env.hpp"
#include "test_scenes.hpp"

namespace fgr {
namespace {

namespace fs = std::filesystem;
using std::chrono::hours;

constexpr const char* kProgram = "0123456789abcdef.bin";
constexpr const char* kVerdict = "math-0123456789abcdef.txt";

void write_bytes(const fs::path& file, std::size_t bytes) {
    std::ofstream(file, std::ios::binary) << std::string(bytes, 'x');
}

// Sets the file's last use `age` before now.
void age(const fs::path& file, hours age) {
    fs::last_write_time(file, fs::file_time_type::clock::now() - age);
}

std::vector<std::string> names(const fs::path& directory) {
    std::vector<std::string> found;
    for (const auto& entry : fs::directory_iterator(directory)) {
        found.push_back(entry.path().filename().string());
    }
    std::sort(found.begin(), found.end());
    return found;
}

TEST(CacheDirectory, EntriesAreProgramsVerdictsAndTheSceneIndexOnly) {
    EXPECT_TRUE(is_cache_entry_name(kProgram));
    EXPECT_TRUE(is_cache_entry_name(kVerdict));
    EXPECT_TRUE(is_cache_entry_name(kSceneIndexName));
    for (const char* name :
         {"0123456789abcdef.bin.tmp-12-0", "0123456789ABCDEF.bin", "scene-index.json.tmp-12-0",
          "scene-index.jsonx", "scenes.json", "0123456789abcde.bin", "notes.txt",
          "math-0123456789abcdef.bin", "0123456789abcdef.txt", "math-xyz.txt", ".bin"}) {
        EXPECT_FALSE(is_cache_entry_name(name)) << name;
    }
}

TEST(CacheDirectory, LimitComesFromTheEnvironmentInMebibytes) {
    EXPECT_EQ(parse_cache_limit("1"), std::uintmax_t{1} << 20);
    EXPECT_EQ(parse_cache_limit("300"), std::uintmax_t{300} << 20);
    for (const char* bad : {"", "0", "-1", "1.5", "12x", " 3", "x", "99999999999999999999999"}) {
        EXPECT_FALSE(parse_cache_limit(bad).has_value()) << bad;
    }
    test::ScopedEnv limit(kCacheLimitVariable, "7");
    EXPECT_EQ(cache_size_limit(), std::uintmax_t{7} << 20);
    limit.set("seven");
    EXPECT_EQ(cache_size_limit(), kDefaultCacheLimitBytes);
    limit.set(nullptr);
    EXPECT_EQ(cache_size_limit(), kDefaultCacheLimitBytes);
}

// PoCL keeps every program it compiles unless POCL_KERNEL_CACHE=0; a GPU driver keeps none that
// fgr could count on. $FGR_CACHE_PROGRAMS=always stores binaries for every driver.
TEST(StoredPrograms, PoclKeepsItsProgramsUnlessItsCacheIsOff) {
    DeviceInfo pocl;
    pocl.platform = "Portable Computing Language";
    pocl.version = "OpenCL 3.0 PoCL 3.1+debian  Linux, None+Asserts, RELOC, LLVM 15.0.6";
    DeviceInfo nvidia;
    nvidia.platform = "NVIDIA CUDA";
    nvidia.version = "OpenCL 3.0 CUDA";
    test::ScopedEnv pocl_cache("POCL_KERNEL_CACHE", nullptr);
    EXPECT_TRUE(driver_keeps_programs(pocl));
    EXPECT_FALSE(driver_keeps_programs(nvidia));
    pocl_cache.set("1");
    EXPECT_TRUE(driver_keeps_programs(pocl));
    pocl_cache.set("0");
    EXPECT_FALSE(driver_keeps_programs(pocl));

    test::ScopedEnv setting(kStoredProgramsVariable, nullptr);
    EXPECT_EQ(stored_programs_setting(), StoredPrograms::WhereTheDriverKeepsNone);
    for (const char* value : {"", "auto"}) {
        setting.set(value);
        EXPECT_EQ(stored_programs_setting(), StoredPrograms::WhereTheDriverKeepsNone) << value;
    }
    setting.set("always");
    EXPECT_EQ(stored_programs_setting(), StoredPrograms::Always);
    setting.set("sometimes");
    EXPECT_EQ(stored_programs_setting(), StoredPrograms::WhereTheDriverKeepsNone);
}

TEST(CacheDirectory, TrimEvictsTheLeastRecentlyUsedEntriesAndNothingElse) {
    const test::TempDir dir("fgr_cache_dir_test");
    const fs::path a = dir.path() / "aaaaaaaaaaaaaaaa.bin", b = dir.path() / "bbbbbbbbbbbbbbbb.bin",
                   c = dir.path() / "cccccccccccccccc.bin",
                   verdict = dir.path() / "math-dddddddddddddddd.txt",
                   foreign = dir.path() / "notes.txt";
    write_bytes(a, 1000);
    write_bytes(b, 1000);
    write_bytes(c, 1000);
    write_bytes(verdict, 10);
    write_bytes(foreign, 5000);
    age(verdict, hours(4));  // the oldest: a verdict is an entry like a program
    age(b, hours(3));
    age(a, hours(2));
    age(foreign, hours(9));
    EXPECT_EQ(cache_usage(dir.path()).entries, 4u);
    EXPECT_EQ(cache_usage(dir.path()).bytes, 3010u);

    age(c, hours(1));
    touch_cache_entry(b);  // used again now: of the entries only c (an hour ago) comes close
    const CacheUsage evicted = trim_cache(dir.path(), 2000);
    EXPECT_EQ(evicted.entries, 2u);
    EXPECT_EQ(evicted.bytes, 1010u);
    EXPECT_EQ(names(dir.path()), (std::vector<std::string>{"bbbbbbbbbbbbbbbb.bin",
                                                           "cccccccccccccccc.bin", "notes.txt"}));

    // The entry just written stays even when it alone is over the limit.
    trim_cache(dir.path(), 10, b);
    EXPECT_EQ(names(dir.path()), (std::vector<std::string>{"bbbbbbbbbbbbbbbb.bin", "notes.txt"}));
}

TEST(CacheDirectory, ClearRemovesEntriesAndDeadWritersTemporariesOnly) {
    const test::TempDir dir("fgr_cache_dir_test");
    write_bytes(dir.path() / kProgram, 100);
    write_bytes(dir.path() / kVerdict, 5);
    write_bytes(dir.path() / (std::string(kProgram) + ".tmp-123-0"), 7);
    write_bytes(dir.path() / "notes.txt", 3);
    write_bytes(dir.path() / "keep.bin.tmp-1-1", 3);
    const CacheUsage removed = clear_cache(dir.path());
    EXPECT_EQ(removed.entries, 3u);
    EXPECT_EQ(removed.bytes, 112u);
    EXPECT_EQ(names(dir.path()), (std::vector<std::string>{"keep.bin.tmp-1-1", "notes.txt"}));
    EXPECT_EQ(cache_usage(dir.path()).entries, 0u);
    EXPECT_EQ(clear_cache(dir.path() / "missing").entries, 0u);
}

TEST(CacheDirectory, StoreWritesTheWholeEntryAndTrimsAroundIt) {
    const test::TempDir dir("fgr_cache_dir_test");
    const fs::path old_entry = dir.path() / "sub" / "aaaaaaaaaaaaaaaa.bin";
    EXPECT_EQ(store_cache_entry(old_entry, std::string(600, 'a'), 1000), "");
    age(old_entry, hours(1));
    const fs::path entry = dir.path() / "sub" / kProgram;
    const std::string bytes("\0binary\xff\0", 9);
    EXPECT_EQ(store_cache_entry(entry, bytes, 1000), "");
    EXPECT_EQ(test::read_file(entry), bytes);
    EXPECT_EQ(store_cache_entry(entry, std::string(500, 'b'), 1000), "");  // replaces, then trims
    EXPECT_EQ(names(dir.path() / "sub"), std::vector<std::string>{kProgram});
    EXPECT_NE(store_cache_entry(dir.path() / "sub" / kProgram / "x.bin", "y", 1000), "");
}

// --- ProgramCache on disk ------------------------------------------------------------------------

class ProgramCacheDisk : public ::testing::Test {
protected:
    // A small program per radius, so each has its own key.
    AssembledProgram program(float radius) const {
        const Scene scene =
            test::inline_scene("real scene_de(vec3 p, PARAMS) { return v3_length(p) - " +
                               std::to_string(radius) + "f; }");
        return assemble_program(scene, {4, 0});
    }
    fs::path entry(const AssembledProgram& built) const {
        return dir_.path() / (ProgramCache::cache_key(device_, built) + ".bin");
    }
    // A cache that stores every program's binary, as for a driver without a cache of its own.
    ProgramCache stored_cache(std::uintmax_t limit = cache_size_limit()) const {
        return ProgramCache(dir_.path(), limit, StoredPrograms::Always);
    }

    const ComputeDevice device_ = open_device(-1);
    const test::TempDir dir_{"fgr_program_cache_test"};
};

// The tests' driver is PoCL, whose own cache keeps the programs it compiles: fgr stores a binary
// only when told to (or, on another driver, by default).
TEST_F(ProgramCacheDisk, BinariesAreStoredOnlyWhereTheDriverKeepsNoneOrWhenAsked) {
    ASSERT_TRUE(driver_keeps_programs(device_.info)) << device_.info.platform;
    const AssembledProgram a = program(0.5f);
    ProgramCache by_default(dir_.path(), cache_size_limit(),
                            StoredPrograms::WhereTheDriverKeepsNone);
    EXPECT_FALSE(by_default.stores_binaries(device_.info));
    BuildReport report;
    by_default.build(device_, a, &report);
    EXPECT_EQ(report.origin, BuildReport::Origin::Compiled);
    EXPECT_EQ(names(dir_.path()), std::vector<std::string>{}) << "a binary was stored";

    DeviceInfo gpu = device_.info;
    gpu.platform = "NVIDIA CUDA";
    gpu.version = "OpenCL 3.0 CUDA";
    EXPECT_TRUE(by_default.stores_binaries(gpu));
    EXPECT_FALSE(
        ProgramCache(fs::path(), cache_size_limit(), StoredPrograms::Always).stores_binaries(gpu))
        << "a cache without a directory stores nothing";

    stored_cache().build(device_, a, &report);
    EXPECT_EQ(report.origin, BuildReport::Origin::Compiled);
    EXPECT_TRUE(fs::exists(entry(a)));
}

TEST_F(ProgramCacheDisk, ADiskHitMarksTheEntryAsRecentlyUsed) {
    const AssembledProgram a = program(0.5f);
    stored_cache().build(device_, a);
    ASSERT_TRUE(fs::exists(entry(a)));
    age(entry(a), hours(48));
    const auto before = fs::last_write_time(entry(a));
    BuildReport report;
    stored_cache().build(device_, a, &report);
    ASSERT_EQ(report.origin, BuildReport::Origin::Disk);
    EXPECT_GT(fs::last_write_time(entry(a)), before + hours(47)) << "the hit did not mark it used";
}

TEST_F(ProgramCacheDisk, StoringEvictsTheLeastRecentlyUsedBeyondTheLimit) {
    const AssembledProgram a = program(0.5f), b = program(0.6f), c = program(0.7f);
    // Each entry's size, from a first round.
    stored_cache().build(device_, a);
    stored_cache().build(device_, b);
    stored_cache().build(device_, c);
    const std::uintmax_t size_a = fs::file_size(entry(a)), size_c = fs::file_size(entry(c));
    fs::remove(entry(c));

    // b was stored after a, but a is used again later: b is the least recently used.
    age(entry(a), hours(2));
    age(entry(b), hours(1));
    stored_cache().build(device_, a);  // a disk hit
    BuildReport report;
    // Room for a and c with a margin (a rebuilt binary may differ by a few bytes), not for b too.
    const std::uintmax_t limit = size_a + size_c + fs::file_size(entry(b)) / 2;
    stored_cache(limit).build(device_, c, &report);
    EXPECT_EQ(report.origin, BuildReport::Origin::Compiled);
    EXPECT_TRUE(fs::exists(entry(a)));
    EXPECT_FALSE(fs::exists(entry(b))) << "the least recently used entry was kept";
    EXPECT_TRUE(fs::exists(entry(c)));
    EXPECT_LE(cache_usage(dir_.path()).bytes, limit);

    // A limit smaller than one entry keeps just the newest.
    stored_cache(1).build(device_, b);
    EXPECT_EQ(names(dir_.path()), std::vector<std::string>{entry(b).filename().string()});
}

}  // namespace
}  // namespace fgr
