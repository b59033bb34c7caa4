// SPDX-License-Identifier: Apache-2.0
#include "util/content_hash.hpp"

#include <fmt/format.h>

namespace fgr {

namespace {
constexpr std::uint64_t kFnvPrime = 0x100000001b3ull;
}  // namespace

ContentHash& ContentHash::add(std::string_view bytes) {
    for (const unsigned char byte : bytes) {
        hash_ ^= byte;
        hash_ *= kFnvPrime;
    }
    hash_ ^= 0xff;
    hash_ *= kFnvPrime;
    return *this;
}

std::string ContentHash::hex() const { return fmt::format("{:016x}", hash_); }

}  // namespace fgr
