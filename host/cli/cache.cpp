// SPDX-License-Identifier: Apache-2.0
// fgr cache: the kernel cache directory's size (`fgr cache size`) and emptying it
// (`fgr cache clear`). Programs and the math self-test's verdicts are its entries.
#include <fmt/format.h>

#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <string>

#include "commands.hpp"
#include "device/cache_directory.hpp"
#include "device/program_cache.hpp"

namespace fgr {
namespace {

std::filesystem::path cache_directory() {
    const std::filesystem::path directory = ProgramCache::default_directory();
    if (directory.empty()) {
        throw RuntimeFailure(
            "no kernel cache directory: set FGR_CACHE_DIR, XDG_CACHE_HOME or HOME");
    }
    return directory;
}

std::string mebibytes(std::uintmax_t bytes) {
    return fmt::format("{:.1f} MiB", static_cast<double>(bytes) / double(1 << 20));
}

int command_cache_size() {
    const std::filesystem::path directory = cache_directory();
    const CacheUsage usage = cache_usage(directory);
    const std::uintmax_t limit = cache_size_limit();
    const char* setting = std::getenv(kCacheLimitVariable);
    const bool from_environment = setting && parse_cache_limit(setting).has_value();
    fmt::print("directory {}\n", directory.string());
    fmt::print("entries {}\n", usage.entries);
    fmt::print("bytes {} ({})\n", usage.bytes, mebibytes(usage.bytes));
    fmt::print("limit {} ({}, {})\n", limit, mebibytes(limit),
               from_environment ? fmt::format("from {}", kCacheLimitVariable)
                                : fmt::format("default; {} changes it", kCacheLimitVariable));
    return 0;
}

int command_cache_clear() {
    const std::filesystem::path directory = cache_directory();
    const CacheUsage removed = clear_cache(directory);
    fmt::print("removed {} entries ({}) from {}\n", removed.entries, mebibytes(removed.bytes),
               directory.string());
    return 0;
}

}  // namespace

void add_cache_command(CLI::App& app, CacheOptions& options) {
    CLI::App* cache = app.add_subcommand(
        "cache", "the kernel cache on disk: compiled programs and device self-test verdicts");
    cache->require_subcommand(0, 1);
    options.size = cache->add_subcommand(
        "size", "print the cache directory, its entries, their bytes and the size limit");
    options.clear = cache->add_subcommand("clear", "remove every entry of the kernel cache");
}

int command_cache(const CacheOptions& options) {
    if (options.clear->parsed()) return command_cache_clear();
    if (options.size->parsed()) return command_cache_size();
    throw UsageError("`fgr cache` needs a subcommand: size or clear");
}

}  // namespace fgr
