// SPDX-License-Identifier: Apache-2.0
#pragma once
// The kernel cache directory on disk (ProgramCache::default_directory()): compiled programs
// (<key>.bin, program_cache.cpp), the device math self-test's verdicts (math-<key>.txt,
// math_check.cpp) and the scene index (scene-index.json, scene/scene_index.hpp). Entries are
// written atomically and durably, marked when used, and kept under a size limit by evicting the
// least recently used; `fgr cache` reports and clears them.

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace fgr {

// The disk cache's size limit unless $FGR_CACHE_MAX_MB says otherwise: about 500 programs of a
// CPU driver (~0.5 MB each).
constexpr std::uintmax_t kDefaultCacheLimitBytes = std::uintmax_t{256} << 20;
constexpr const char* kCacheLimitVariable = "FGR_CACHE_MAX_MB";

// $FGR_CACHE_MAX_MB MiB (a whole number >= 1), else kDefaultCacheLimitBytes; a value that is not
// such a number is reported once as a warning and ignored.
std::uintmax_t cache_size_limit();

// A limit in bytes from its text in MiB, or nothing when the text is not a whole number >= 1.
std::optional<std::uintmax_t> parse_cache_limit(std::string_view mib);

// Whether a file name is one of the cache's entries: a program "<16 hex digits>.bin", a verdict
// "math-<16 hex digits>.txt" or the scene index (kSceneIndexName). Nothing else in the directory
// is ever evicted or cleared, except clear_cache's temporaries.
bool is_cache_entry_name(std::string_view name);

struct CacheEntry {
    std::filesystem::path file;
    std::uintmax_t bytes = 0;
    std::filesystem::file_time_type last_used{};  // the file's modification time
};

// The entries in `directory`, least recently used first; none when it does not exist.
std::vector<CacheEntry> cache_entries(const std::filesystem::path& directory);

struct CacheUsage {
    std::size_t entries = 0;
    std::uintmax_t bytes = 0;
};

CacheUsage cache_usage(const std::filesystem::path& directory);

// Marks an entry as used now (its modification time), which is what the eviction order follows:
// access times are unreliable (noatime, relatime). Failures are ignored: the cache only saves time.
void touch_cache_entry(const std::filesystem::path& file);

// Evicts least recently used entries of `directory` until they take at most `limit` bytes, never
// `keep` (the entry just written, which stays even when it alone is over the limit). Returns what
// was evicted.
CacheUsage trim_cache(const std::filesystem::path& directory, std::uintmax_t limit,
                      const std::filesystem::path& keep = {});

// Writes `bytes` as the entry `file` (creating its directory) through write_text_file_atomically:
// a temporary beside it, fsync'd, renamed, removed on any failure, so no reader ever sees a
// partial entry. Then trims the directory to `limit`, keeping `file`. Returns "" or the reason it
// could not be stored.
std::string store_cache_entry(const std::filesystem::path& file, std::string_view bytes,
                              std::uintmax_t limit);

// Removes every entry, and the temporaries of writers that died before renaming theirs
// ("<entry>.tmp-*"). Returns what was removed (temporaries included).
CacheUsage clear_cache(const std::filesystem::path& directory);

}  // namespace fgr
