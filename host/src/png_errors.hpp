#pragma once
// libpng's error and warning handlers as fgr's PNG readers and writers use them (image_io.cpp,
// tiled/streaming_image.cpp).

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

}  // namespace fgr
