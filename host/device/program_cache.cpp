// SPDX-License-Identifier: Apache-2.0
#include "device/program_cache.hpp"

#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include <atomic>
#include <chrono>
#include <cstdlib>
#include <exception>
#include <regex>
#include <sstream>
#include <string_view>
#include <vector>

#include "device/program_entry.hpp"
#include "util/content_hash.hpp"
#include "util/files.hpp"
#include "util/strings.hpp"
#include "util/timing.hpp"

namespace fgr {
namespace {

// Portable options every program gets: the kernels are OpenCL C 1.2 so they run on PoCL as well
// as on GPU drivers.
constexpr const char* kBaseOptions = "-cl-std=CL1.2";

std::string full_options(const AssembledProgram& program) {
    return fmt::format("{} {}", kBaseOptions, program.options);
}

std::string build_log(const cl::Program& program, const cl::Device& device) {
    try {
        return program.getBuildInfo<CL_PROGRAM_BUILD_LOG>(device);
    } catch (const cl::Error&) {
        return "(no build log)";
    }
}

// A compiler's error line, PoCL's "error: FILE:LINE:COL: message" or the conventional
// "FILE:LINE:COL: error: message".
const std::regex& error_line() {
    static const std::regex line(R"(^(?:error: (\S+:\d+:\d+): (.*)|(\S+:\d+:\d+): error: (.*))$)");
    return line;
}

}  // namespace

std::string conventional_build_log(const std::string& log) {
    static const std::regex pocl_line(R"(^(error|warning|note): (\S+:\d+:\d+): (.*)$)");
    std::istringstream lines(log);
    std::string line, out;
    while (std::getline(lines, line)) {
        out += std::regex_replace(line, pocl_line, "$2: $1: $3") + "\n";
    }
    return out;
}

std::string first_build_error(const std::string& log) {
    std::istringstream lines(log);
    std::string line;
    while (std::getline(lines, line)) {
        if (!line.empty() && line.back() == '\r') line.pop_back();
        std::smatch match;
        if (!std::regex_match(line, match, error_line())) continue;
        const bool pocl = match[1].matched;
        std::string first =
            fmt::format("{}: {}", match[pocl ? 1 : 3].str(), match[pocl ? 2 : 4].str());
        for (char& c : first) {
            if (static_cast<unsigned char>(c) < 0x20) c = ' ';
        }
        return first;
    }
    return "";
}

StoredPrograms stored_programs_setting() {
    const char* text = std::getenv(kStoredProgramsVariable);
    if (text == nullptr || *text == '\0' || std::string_view(text) == "auto") {
        return StoredPrograms::WhereTheDriverKeepsNone;
    }
    if (std::string_view(text) == "always") return StoredPrograms::Always;
    static std::atomic<bool> warned{false};
    if (!warned.exchange(true)) {
        spdlog::warn(
            "{}='{}' is neither 'auto' nor 'always': storing programs only where the "
            "driver keeps none",
            kStoredProgramsVariable, printable_excerpt(text));
    }
    return StoredPrograms::WhereTheDriverKeepsNone;
}

bool driver_keeps_programs(const DeviceInfo& info) {
    const bool pocl = info.platform == "Portable Computing Language" ||
                      info.version.find("PoCL") != std::string::npos;
    const char* cache = std::getenv("POCL_KERNEL_CACHE");
    return pocl && !(cache && std::string_view(cache) == "0");
}

ProgramCache::ProgramCache(std::filesystem::path directory, std::uintmax_t size_limit,
                           StoredPrograms stored)
    : directory_(std::move(directory)), size_limit_(size_limit), stored_(stored) {}

bool ProgramCache::stores_binaries(const DeviceInfo& device) const {
    return !directory_.empty() &&
           (stored_ == StoredPrograms::Always || !driver_keeps_programs(device));
}

std::filesystem::path ProgramCache::default_directory() {
    if (const char* dir = std::getenv("FGR_CACHE_DIR"); dir && *dir) return dir;
    if (const char* xdg = std::getenv("XDG_CACHE_HOME"); xdg && *xdg) {
        return std::filesystem::path(xdg) / "fgr" / "kernels";
    }
    if (const char* home = std::getenv("HOME"); home && *home) {
        return std::filesystem::path(home) / ".cache" / "fgr" / "kernels";
    }
    return {};
}

std::string ProgramCache::cache_key(const ComputeDevice& device, const AssembledProgram& program) {
    const std::string options = full_options(program);
    const std::string_view parts[] = {program.source,       options,
                                      device.info.platform, device.info.name,
                                      device.info.version,  device.info.driver_version};
    ContentHash hash;
    for (std::string_view part : parts) hash.add(part);
    return hash.hex();
}

cl::Program ProgramCache::build(const ComputeDevice& device, const AssembledProgram& program,
                                BuildReport* report) {
    const auto start = std::chrono::steady_clock::now();
    BuildReport local;
    BuildReport& result = report ? *report : local;
    const std::string key = cache_key(device, program);
    if (auto found = programs_.find(key); found != programs_.end()) {
        result = {elapsed_ms(start), BuildReport::Origin::Memory};
        return found->second;
    }
    const std::filesystem::path file =
        directory_.empty() ? std::filesystem::path() : directory_ / (key + ".bin");
    cl::Program built;
    if (!file.empty()) built = load_binary(device, program, key, file);
    if (built()) {
        result.origin = BuildReport::Origin::Disk;
        touch_cache_entry(file);  // recently used: the last to be evicted
    } else {
        built = cl::Program(device.context, program.source);
        try {
            built.build({device.device}, full_options(program).c_str());
        } catch (const cl::Error&) {
            const std::string log = build_log(built, device.device);
            const std::string first = first_build_error(log);
            throw KernelBuildError(first.empty()
                                       ? "OpenCL program failed to compile"
                                       : fmt::format("OpenCL program failed to compile: {}", first),
                                   log, build_error_hint(program.kernel_api, log));
        }
        result.origin = BuildReport::Origin::Compiled;
        if (const std::string log = build_log(built, device.device); log.size() > 1) {
            spdlog::debug("OpenCL build log:\n{}", log);
        }
        if (stores_binaries(device.info)) store_binary(built, key, file);
    }
    result.build_ms = elapsed_ms(start);
    spdlog::debug("program {} ready in {:.0f} ms ({})", key, result.build_ms,
                  result.origin == BuildReport::Origin::Disk ? "disk cache" : "compiled");
    programs_.emplace(key, built);
    return built;
}

cl::Program ProgramCache::load_binary(const ComputeDevice& device, const AssembledProgram& program,
                                      const std::string& key, const std::filesystem::path& file) {
    namespace fs = std::filesystem;
    std::error_code error;
    if (!fs::exists(fs::symlink_status(file, error))) return {};  // no entry
    std::string entry;
    // Refuses what is not a regular file (a directory, a FIFO: never waited on) and huge files.
    std::string problem = read_file_bytes(file, entry, kMaxProgramEntryBytes);
    if (!problem.empty() && !fs::exists(fs::symlink_status(file, error))) {
        return {};  // evicted meanwhile by another process
    }
    if (problem.empty()) {
        const ProgramEntryCheck check = check_program_entry(entry, key);
        problem = check.problem;
        if (problem.empty()) {
            try {
                const std::vector<unsigned char> binary(check.binary.begin(), check.binary.end());
                cl::Program loaded(device.context, {device.device}, cl::Program::Binaries{binary});
                loaded.build({device.device}, full_options(program).c_str());
                return loaded;
            } catch (const cl::Error& refused) {
                problem = fmt::format("the driver refused it: {}", cl_error_name(refused.err()));
            }
        }
    }
    // The cache only saves time: a bad entry costs one compile, never the render.
    const bool removed = fs::remove(file, error);
    spdlog::warn(
        "kernel cache entry {} is unusable ({}): {}compiling the program again", quoted(file),
        problem,
        removed ? "removed it, "
                : fmt::format("cannot remove it ({}), ", error ? error.message() : "it is gone"));
    return {};
}

void ProgramCache::store_binary(const cl::Program& program, const std::string& key,
                                const std::filesystem::path& file) {
    std::string failure;
    try {
        const auto binaries = program.getInfo<CL_PROGRAM_BINARIES>();
        if (binaries.empty() || binaries.front().empty()) {
            spdlog::debug("driver returned no program binary to cache");
            return;
        }
        const std::vector<unsigned char>& binary = binaries.front();
        failure = store_cache_entry(
            file,
            program_entry(
                std::string_view(reinterpret_cast<const char*>(binary.data()), binary.size()), key),
            size_limit_);
    } catch (const std::exception& error) {
        failure = error.what();
    }
    // The cache only saves time; failing to fill it must never fail a render.
    if (!failure.empty()) {
        spdlog::debug("could not cache program binary {}: {}", file.string(), failure);
    }
}

}  // namespace fgr
