#pragma once
// libpng's error and warning handlers as fgr's PNG readers and writers use them (image_io.cpp,
// tiled/streaming_image.cpp), and the compression both writers use.

#include <png.h>

#include <cstdio>

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

// zlib level 3 instead of libpng's 6: fgr's canonical 640x480 Mandelbulb render compresses in
// 12.5 ms instead of 20 (zlib alone, on its filtered rows) for a file 2.4% larger, which a whole
// `fgr render` of that size (about 160 ms) notices and a gigapixel still's writer more so.
inline void use_png_compression(png_structp png) { png_set_compression_level(png, 3); }

}  // namespace fgr
