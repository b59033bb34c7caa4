// SPDX-License-Identifier: Apache-2.0
#include "device/cache_directory.hpp"

#include <spdlog/spdlog.h>

#include <algorithm>
#include <atomic>
#include <charconv>
#include <cstdlib>
#include <exception>
#include <system_error>

#include "scene/scene_index.hpp"
#include "util/atomic_file.hpp"

namespace fgr {
namespace {

namespace fs = std::filesystem;

bool is_key(std::string_view text) {
    return text.size() == 16 && std::all_of(text.begin(), text.end(), [](char c) {
               return (c >= '0' && c <= '9') || (c >= 'a' && c <= 'f');
           });
}

// "<entry>.tmp-<pid>-<n>", the temporary write_text_file_atomically writes beside an entry.
bool is_entry_temporary(std::string_view name) {
    const std::size_t tmp = name.find(".tmp-");
    return tmp != std::string_view::npos && is_cache_entry_name(name.substr(0, tmp));
}

}  // namespace

std::optional<std::uintmax_t> parse_cache_limit(std::string_view mib) {
    std::uintmax_t value = 0;
    const auto [end, error] = std::from_chars(mib.data(), mib.data() + mib.size(), value);
    if (error != std::errc() || end != mib.data() + mib.size() || value < 1 ||
        value > (std::uintmax_t{1} << 40)) {
        return std::nullopt;
    }
    return value << 20;
}

std::uintmax_t cache_size_limit() {
    const char* text = std::getenv(kCacheLimitVariable);
    if (text == nullptr || *text == '\0') return kDefaultCacheLimitBytes;
    if (const std::optional<std::uintmax_t> limit = parse_cache_limit(text)) return *limit;
    static std::atomic<bool> warned{false};
    if (!warned.exchange(true)) {
        spdlog::warn(
            "{}='{}' is not a whole number of MiB >= 1: keeping the kernel cache under "
            "the default {} MiB",
            kCacheLimitVariable, text, kDefaultCacheLimitBytes >> 20);
    }
    return kDefaultCacheLimitBytes;
}

bool is_cache_entry_name(std::string_view name) {
    if (name == kSceneIndexName) return true;
    if (name.size() == 20 && name.ends_with(".bin")) return is_key(name.substr(0, 16));
    if (name.size() == 25 && name.starts_with("math-") && name.ends_with(".txt")) {
        return is_key(name.substr(5, 16));
    }
    return false;
}

std::vector<CacheEntry> cache_entries(const fs::path& directory) {
    std::vector<CacheEntry> entries;
    std::error_code error;
    for (fs::directory_iterator it(directory, error), end; !error && it != end;
         it.increment(error)) {
        if (!is_cache_entry_name(it->path().filename().string())) continue;
        // Each entry may vanish meanwhile (another process evicting it): skip it then.
        std::error_code stat_error;
        if (!it->is_regular_file(stat_error)) continue;
        const std::uintmax_t bytes = it->file_size(stat_error);
        if (stat_error) continue;
        const fs::file_time_type used = it->last_write_time(stat_error);
        if (stat_error) continue;
        entries.push_back({it->path(), bytes, used});
    }
    std::sort(entries.begin(), entries.end(), [](const CacheEntry& a, const CacheEntry& b) {
        return a.last_used != b.last_used ? a.last_used < b.last_used : a.file < b.file;
    });
    return entries;
}

CacheUsage cache_usage(const fs::path& directory) {
    CacheUsage usage;
    for (const CacheEntry& entry : cache_entries(directory)) {
        ++usage.entries;
        usage.bytes += entry.bytes;
    }
    return usage;
}

void touch_cache_entry(const fs::path& file) {
    std::error_code ignored;
    fs::last_write_time(file, fs::file_time_type::clock::now(), ignored);
}

CacheUsage trim_cache(const fs::path& directory, std::uintmax_t limit, const fs::path& keep) {
    const std::vector<CacheEntry> entries = cache_entries(directory);
    std::uintmax_t total = 0;
    for (const CacheEntry& entry : entries) total += entry.bytes;
    CacheUsage evicted;
    for (const CacheEntry& entry : entries) {
        if (total <= limit) break;
        if (!keep.empty() && entry.file == keep) continue;
        std::error_code error;
        if (!fs::remove(entry.file, error)) continue;  // gone already (another process evicted it)
        total -= entry.bytes;
        ++evicted.entries;
        evicted.bytes += entry.bytes;
    }
    if (evicted.entries > 0) {
        spdlog::debug("kernel cache over {} MiB: evicted {} least recently used entries ({} bytes)",
                      limit >> 20, evicted.entries, evicted.bytes);
    }
    return evicted;
}

std::string store_cache_entry(const fs::path& file, std::string_view bytes, std::uintmax_t limit) {
    try {
        std::error_code ignored;
        fs::create_directories(file.parent_path(), ignored);
        write_text_file_atomically(file, bytes);
    } catch (const std::exception& error) {
        return error.what();
    }
    trim_cache(file.parent_path(), limit, file);
    return {};
}

CacheUsage clear_cache(const fs::path& directory) {
    std::vector<fs::path> doomed;
    std::error_code error;
    for (fs::directory_iterator it(directory, error), end; !error && it != end;
         it.increment(error)) {
        const std::string name = it->path().filename().string();
        if (is_cache_entry_name(name) || is_entry_temporary(name)) doomed.push_back(it->path());
    }
    CacheUsage removed;
    for (const fs::path& file : doomed) {
        std::error_code size_error;
        std::uintmax_t bytes = fs::file_size(file, size_error);
        if (size_error) bytes = 0;
        std::error_code remove_error;
        if (!fs::remove(file, remove_error)) continue;
        ++removed.entries;
        removed.bytes += bytes;
    }
    return removed;
}

}  // namespace fgr
