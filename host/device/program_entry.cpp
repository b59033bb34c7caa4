// SPDX-License-Identifier: Apache-2.0
#include "device/program_entry.hpp"

#include <fmt/format.h>

#include <stdexcept>

#include "util/content_hash.hpp"

namespace fgr {
namespace {

constexpr std::string_view kMagic{"fgrkbin\0", 8};
constexpr std::size_t kHexDigits = 16;
// Field offsets in the header.
constexpr std::size_t kVersionAt = 8, kHeaderSizeAt = 12, kLengthAt = 16, kHashAt = 24,
                      kFingerprintAt = kHashAt + kHexDigits;
static_assert(kFingerprintAt + kHexDigits == kProgramEntryHeaderBytes);

void put_le(std::string& out, std::uint64_t value, int bytes) {
    for (int i = 0; i < bytes; ++i) out += static_cast<char>((value >> (8 * i)) & 0xff);
}

std::uint64_t get_le(std::string_view in, std::size_t at, int bytes) {
    std::uint64_t value = 0;
    for (int i = bytes - 1; i >= 0; --i) {
        value = value << 8 | static_cast<unsigned char>(in[at + static_cast<std::size_t>(i)]);
    }
    return value;
}

std::string binary_hash(std::string_view binary) { return ContentHash().add(binary).hex(); }

// Hex digits as a message may quote them: anything else shown as '?'.
std::string printable_hex(std::string_view text) {
    std::string shown(text);
    for (char& c : shown) {
        if (!((c >= '0' && c <= '9') || (c >= 'a' && c <= 'f'))) c = '?';
    }
    return shown;
}

}  // namespace

std::string program_entry(std::string_view binary, std::string_view fingerprint) {
    if (fingerprint.size() != kHexDigits) {
        throw std::invalid_argument(fmt::format("a program's fingerprint is {} hex digits, not {}",
                                                kHexDigits, fingerprint.size()));
    }
    std::string entry;
    entry.reserve(kProgramEntryHeaderBytes + binary.size());
    entry += kMagic;
    put_le(entry, kProgramEntryVersion, 4);
    put_le(entry, kProgramEntryHeaderBytes, 4);
    put_le(entry, binary.size(), 8);
    entry += binary_hash(binary);
    entry += fingerprint;
    entry += binary;
    return entry;
}

ProgramEntryCheck check_program_entry(std::string_view entry, std::string_view fingerprint) {
    ProgramEntryCheck check;
    if (entry.empty()) {
        check.problem = "empty";
        return check;
    }
    if (entry.size() < kProgramEntryHeaderBytes) {
        check.problem = fmt::format("{} bytes, shorter than its header", entry.size());
        return check;
    }
    if (entry.substr(0, kMagic.size()) != kMagic) {
        check.problem = "not a kernel cache entry (no fgr header)";
        return check;
    }
    if (const std::uint64_t version = get_le(entry, kVersionAt, 4);
        version != kProgramEntryVersion) {
        check.problem = fmt::format("format version {}, not {}", version, kProgramEntryVersion);
        return check;
    }
    if (get_le(entry, kHeaderSizeAt, 4) != kProgramEntryHeaderBytes) {
        check.problem = "its header has the wrong size";
        return check;
    }
    const std::uint64_t length = get_le(entry, kLengthAt, 8);
    const std::size_t follow = entry.size() - kProgramEntryHeaderBytes;
    if (length != follow) {
        check.problem =
            fmt::format("its header says {} bytes of binary but {} follow", length, follow);
        return check;
    }
    if (length == 0) {
        check.problem = "it holds no binary";
        return check;
    }
    const std::string_view stored_fingerprint = entry.substr(kFingerprintAt, kHexDigits);
    if (stored_fingerprint != fingerprint) {
        check.problem = fmt::format("built from another program (fingerprint {})",
                                    printable_hex(stored_fingerprint));
        return check;
    }
    const std::string_view binary = entry.substr(kProgramEntryHeaderBytes);
    if (entry.substr(kHashAt, kHexDigits) != binary_hash(binary)) {
        check.problem = "its binary does not match its hash";
        return check;
    }
    check.binary = binary;
    return check;
}

}  // namespace fgr
