// SPDX-License-Identifier: Apache-2.0
#pragma once
// A compiled program as the kernel cache keeps it on disk (<key>.bin, program_cache.cpp): a fixed
// header, then the driver's binary. The header says what the bytes are (a magic and a format
// version), how many follow, their hash, and the fingerprint of the source, options and device
// they were built from (the cache key), so that a truncated, damaged or misplaced entry is
// recognised before any of its bytes reach the driver: clCreateProgramWithBinary trusts what it is
// given, and a truncated PoCL binary crashes it.
//
// The header, 56 bytes: "fgrkbin\0", the format version (u32), the header's size (u32), the
// binary's length (u64), all little-endian; the binary's hash (util/content_hash.hpp) and the
// fingerprint, 16 lower-case hex digits each.

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

namespace fgr {

constexpr std::uint32_t kProgramEntryVersion = 1;
constexpr std::size_t kProgramEntryHeaderBytes = 56;
// An entry larger than this is refused unread: a CPU driver's binary is about 0.5 MB, a GPU's a
// few MB.
constexpr std::uintmax_t kMaxProgramEntryBytes = std::uintmax_t{256} << 20;

// The entry for `binary` built from what `fingerprint` (16 hex digits, the cache key) names.
// Throws std::invalid_argument for a fingerprint of another length.
std::string program_entry(std::string_view binary, std::string_view fingerprint);

struct ProgramEntryCheck {
    std::string problem;      // "" when the entry is sound
    std::string_view binary;  // the driver's bytes within the entry, when sound
};

// Whether `entry` is a whole, undamaged entry of the program `fingerprint` names: problem says why
// not in a few words ("empty", "shorter than its header", "not a kernel cache entry", "format
// version N, not 1", "its header says N bytes of binary but M follow", "its binary does not match
// its hash", "built from another program (fingerprint F)", ...).
ProgramEntryCheck check_program_entry(std::string_view entry, std::string_view fingerprint);

}  // namespace fgr
