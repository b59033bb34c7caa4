// SPDX-License-Identifier: Apache-2.0
#pragma once
// The keys of fgr's disk caches (compiled kernels, the viewer's thumbnails): a 64-bit FNV-1a hash
// of everything that decides an entry, part by part. Each part is followed by a separator, so
// ("ab", "c") and ("a", "bc") hash differently.

#include <cstdint>
#include <string>
#include <string_view>

namespace fgr {

class ContentHash {
public:
    ContentHash& add(std::string_view bytes);
    // A value's bytes as they lie in memory (numbers, enums): the same build reads them back alike.
    template <typename T>
    ContentHash& add_bytes_of(const T& value) {
        return add({reinterpret_cast<const char*>(&value), sizeof value});
    }
    // 16 lower-case hex digits.
    std::string hex() const;

private:
    std::uint64_t hash_ = 0xcbf29ce484222325ull;
};

}  // namespace fgr
