// SPDX-License-Identifier: Apache-2.0
#include "util/strings.hpp"

#include <fmt/format.h>

#include <cstdint>

namespace fgr {
namespace {

// The length of the UTF-8 sequence that starts at text[at] (2 to 4), or 0 when the bytes there
// are not one (a stray continuation byte, an overlong form, a surrogate, past U+10FFFF, cut
// short).
std::size_t utf8_sequence_length(std::string_view text, std::size_t at) {
    const auto byte = [&](std::size_t i) {
        return at + i < text.size() ? static_cast<unsigned char>(text[at + i]) : 0u;
    };
    const auto continuation = [](unsigned c) { return c >= 0x80 && c <= 0xbf; };
    const unsigned lead = byte(0);
    if (lead >= 0xc2 && lead <= 0xdf) return continuation(byte(1)) ? 2 : 0;
    if (lead >= 0xe0 && lead <= 0xef) {
        const unsigned low = lead == 0xe0 ? 0xa0 : 0x80;
        const unsigned high = lead == 0xed ? 0x9f : 0xbf;
        return byte(1) >= low && byte(1) <= high && continuation(byte(2)) ? 3 : 0;
    }
    if (lead >= 0xf0 && lead <= 0xf4) {
        const unsigned low = lead == 0xf0 ? 0x90 : 0x80;
        const unsigned high = lead == 0xf4 ? 0x8f : 0xbf;
        return byte(1) >= low && byte(1) <= high && continuation(byte(2)) && continuation(byte(3))
                   ? 4
                   : 0;
    }
    return 0;
}

// The code point of the valid sequence of `length` bytes at text[at].
char32_t code_point(std::string_view text, std::size_t at, std::size_t length) {
    const auto byte = [&](std::size_t i) { return static_cast<unsigned char>(text[at + i]); };
    const char32_t lead_bits = length == 2 ? 0x1f : length == 3 ? 0x0f : 0x07;
    char32_t point = byte(0) & lead_bits;
    for (std::size_t i = 1; i < length; ++i) point = (point << 6) | (byte(i) & 0x3f);
    return point;
}

bool reorders_text(char32_t point) {
    return (point >= 0x202a && point <= 0x202e) || (point >= 0x2066 && point <= 0x2069);
}

void append_escaped_bytes(std::string& out, std::string_view bytes) {
    for (const char c : bytes) out += fmt::format("\\x{:02x}", static_cast<unsigned char>(c));
}

}  // namespace

std::string printable_text(std::string_view text) {
    std::string out;
    out.reserve(text.size());
    for (std::size_t at = 0; at < text.size();) {
        const auto c = static_cast<unsigned char>(text[at]);
        if (c >= 0x20 && c < 0x7f) {
            out += static_cast<char>(c);
            ++at;
        } else if (c == '\n') {
            out += "\\n";
            ++at;
        } else if (c == '\t') {
            out += "\\t";
            ++at;
        } else if (c == '\r') {
            out += "\\r";
            ++at;
        } else if (c < 0x80) {  // the other C0 controls and DEL
            append_escaped_bytes(out, text.substr(at, 1));
            ++at;
        } else if (const std::size_t length = utf8_sequence_length(text, at); length == 0) {
            append_escaped_bytes(out, text.substr(at, 1));
            ++at;
        } else {
            const char32_t point = code_point(text, at, length);
            if (point < 0xa0) {  // C1 controls: a terminal may read U+009B as an escape
                append_escaped_bytes(out, text.substr(at, length));
            } else if (reorders_text(point)) {
                out += fmt::format("\\u{:04x}", static_cast<std::uint32_t>(point));
            } else {
                out.append(text.substr(at, length));
            }
            at += length;
        }
    }
    return out;
}

std::string printable_excerpt(std::string_view text, std::size_t length) {
    if (text.size() <= length) return printable_text(text);
    return printable_text(text.substr(0, length)) + "...";
}

}  // namespace fgr
