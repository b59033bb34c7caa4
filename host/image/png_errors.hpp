// SPDX-License-Identifier: Apache-2.0
#pragma once
// libpng's error and warning handlers as fgr's PNG readers and writers use them (image_io.cpp,
// tiled/streaming_image.cpp), and the compression and the embedded view both writers write.

#include <png.h>
#include <zlib.h>

#include <cstdio>
#include <string>

#include "image/embedded_view.hpp"

namespace fgr {

// libpng reports an error by calling a handler that must not return. Ours keeps the message for
// the exception thrown once control is back in C++ code, then jumps to the setjmp point.
struct PngErrorSink {
    char message[256] = "libpng error";
};

[[noreturn]] inline void record_png_error(png_structp png, png_const_charp message) {
    auto* sink = static_cast<PngErrorSink*>(png_get_error_ptr(png));
    std::snprintf(sink->message, sizeof sink->message, "%s", message);
    png_longjmp(png, 1);
}

// Warnings concern recoverable oddities (e.g. unknown chunks); a library must not print them.
inline void ignore_png_warning(png_structp, png_const_charp) {}

// Every row filtered by Sub (the left neighbour) and deflated as runs (zlib's Z_RLE) instead of
// libpng's defaults (each row tries all five filters, then zlib level 6): renders are smooth
// gradients, whose Sub differences are runs of small values. Measured on fgr's renders
// (bench/compare_mandelbulber.sh's 640x480 Mandelbulb, the benchmark scene at 1280x720):
// 6.6 ms instead of 17.3 at libpng's filters with level 3 (24 at the defaults), and 12 ms
// instead of 31 at 1280x720; the files come out within 1% of level 3's size (the Mandelbulb's
// 1% smaller). A whole 640x480 `fgr render` takes about 110 ms, so this was a tenth of it; a
// gigapixel still's writer gains as much.
inline void use_png_compression(png_structp png) {
    png_set_filter(png, PNG_FILTER_TYPE_BASE, PNG_FILTER_SUB);
    png_set_compression_strategy(png, Z_RLE);
}

// Puts `document` (checked with check_embedded_view; empty: none) into `info` as the iTXt chunk
// "fgr:view", which png_write_info writes before the pixels. libpng copies the text; it may
// longjmp (out of memory), so call it where setjmp is armed.
inline void set_png_embedded_view(png_structp png, png_infop info, const std::string& document) {
    if (document.empty()) return;
    png_text text{};
    text.compression = document.size() > kPlainPngViewBytes ? PNG_ITXT_COMPRESSION_zTXt
                                                            : PNG_ITXT_COMPRESSION_NONE;
    text.key = const_cast<png_charp>(kPngViewKeyword);
    text.text = const_cast<png_charp>(document.c_str());
    text.lang = nullptr;  // no language tag, no translated keyword
    text.lang_key = nullptr;
    png_set_text(png, info, &text, 1);
}

}  // namespace fgr
