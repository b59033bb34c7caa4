// SPDX-License-Identifier: Apache-2.0
#pragma once
// Building OpenCL programs once per (source, switches, device): in memory for the process, and as
// device binaries on disk across runs, so a second `fgr render` skips the compiler. The disk
// entries live in a cache directory shared with the math self-test's verdicts
// (cache_directory.hpp). Where the driver keeps compiled programs itself (PoCL), fgr stores no
// binary of its own unless told to (StoredPrograms).

#include <cstdint>
#include <filesystem>
#include <map>
#include <stdexcept>
#include <string>

#include "device/cache_directory.hpp"
#include "device/kernel_assembly.hpp"
#include "device/opencl_device.hpp"

namespace fgr {

// The program did not compile. what() is a one-line summary that names the first error's file and
// line, ending with the hint when there is one; build_log() the compiler's output, whose file:line
// references name the scene's own source thanks to #line directives; hint() what to change when
// the log shows a known mistake (build_error_hint), else "".
class KernelBuildError : public std::runtime_error {
public:
    KernelBuildError(const std::string& summary, std::string log, std::string hint = "")
        : std::runtime_error(hint.empty() ? summary : summary + ": " + hint),
          log_(std::move(log)),
          hint_(std::move(hint)) {}
    const std::string& build_log() const { return log_; }
    const std::string& hint() const { return hint_; }

private:
    std::string log_;
    std::string hint_;
};

// The build log with PoCL's "error: FILE:LINE:COL: message" lines turned into the
// "FILE:LINE:COL: error: message" form that compilers print and IDEs and build tools parse.
std::string conventional_build_log(const std::string& log);

// "FILE:LINE:COL: message" of the log's first error, or "" when it names none: what a one-line
// report of a failed build can say.
std::string first_build_error(const std::string& log);

// Which compiled programs go to the disk cache. PoCL keeps every program it compiles in a cache of
// its own, keyed like fgr's by source, options and device (POCL_CACHE_DIR, else ~/.cache/pocl),
// and handing out a program's binary makes it compile every kernel in it once more, for
// work-groups of any size, which fgr never launches. On a 2-core CPU that is about 40% of a cold
// build's time to a ready kernel (1.1 s of 2.5 s for the Mandelbulb), against 37 ms more for each
// later run to build from PoCL's cache than to load fgr's binary (docs/user-guide/plugins.md). So
// by default fgr stores binaries only for drivers that keep none: GPU drivers, and PoCL with
// POCL_KERNEL_CACHE=0. $FGR_CACHE_PROGRAMS=always stores them for every driver (a container whose
// FGR_CACHE_DIR is kept between runs and whose PoCL cache is not).
enum class StoredPrograms { WhereTheDriverKeepsNone, Always };
constexpr const char* kStoredProgramsVariable = "FGR_CACHE_PROGRAMS";

// $FGR_CACHE_PROGRAMS: "always", else (unset, empty or "auto") WhereTheDriverKeepsNone; any other
// value is reported once as a warning and ignored.
StoredPrograms stored_programs_setting();

// Whether the device's driver keeps the programs it compiles across runs: PoCL, unless
// POCL_KERNEL_CACHE=0 turns its cache off.
bool driver_keeps_programs(const DeviceInfo& info);

struct BuildReport {
    double build_ms = 0.0;
    enum class Origin { Memory, Disk, Compiled } origin = Origin::Compiled;
};

class ProgramCache {
public:
    // An empty directory keeps the cache in memory only. On disk, entries are kept under
    // `size_limit` bytes by evicting the least recently used (cache_directory.hpp), and binaries
    // are stored as `stored` says.
    explicit ProgramCache(std::filesystem::path directory,
                          std::uintmax_t size_limit = cache_size_limit(),
                          StoredPrograms stored = stored_programs_setting());

    // $FGR_CACHE_DIR, else $XDG_CACHE_HOME/fgr/kernels, else ~/.cache/fgr/kernels, else none.
    static std::filesystem::path default_directory();

    cl::Program build(const ComputeDevice& device, const AssembledProgram& program,
                      BuildReport* report = nullptr);

    // 64-bit FNV-1a over everything that makes a binary valid: source, options and device.
    static std::string cache_key(const ComputeDevice& device, const AssembledProgram& program);

    const std::filesystem::path& directory() const { return directory_; }
    std::uintmax_t size_limit() const { return size_limit_; }
    // Whether a program compiled for `device` has its binary stored on disk.
    bool stores_binaries(const DeviceInfo& device) const;

private:
    // The entry `file` of the program `key` names, built; none when there is no entry, or when it
    // is unusable (not a regular file, damaged, refused by the driver): then it is removed with a
    // warning, and the caller compiles the program again.
    cl::Program load_binary(const ComputeDevice& device, const AssembledProgram& program,
                            const std::string& key, const std::filesystem::path& file);
    void store_binary(const cl::Program& program, const std::string& key,
                      const std::filesystem::path& file);

    std::filesystem::path directory_;
    std::uintmax_t size_limit_;
    StoredPrograms stored_;
    std::map<std::string, cl::Program> programs_;
};

}  // namespace fgr
