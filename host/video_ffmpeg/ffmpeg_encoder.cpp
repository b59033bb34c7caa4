// SPDX-License-Identifier: Apache-2.0
// FFmpeg's side of `fgr video` and `fgr merge`'s videos: the module fgr loads on first use (see
// host/output/video/video_backend.hpp for why it is not linked in).
#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include <array>
#include <cctype>
#include <cstdarg>
#include <stdexcept>
#include <system_error>

#include "output/video/video_backend.hpp"

extern "C" {
#include <libavcodec/avcodec.h>
#include <libavformat/avformat.h>
#include <libavutil/imgutils.h>
#include <libavutil/opt.h>
#include <libavutil/pixdesc.h>
#include <libswscale/swscale.h>
}

namespace fgr {
namespace {

// FFmpeg's own log lines (x264's settings and statistics, the muxer's passes) go to fgr's debug
// log (`fgr -v`): errors reach the user as the one-line error fgr throws, not as FFmpeg's lines.
void log_to_spdlog(void* context, int level, const char* format, va_list arguments) {
    if (level > av_log_get_level()) return;
    std::array<char, 1024> line{};
    int print_prefix = 1;
    av_log_format_line2(context, level, format, arguments, line.data(),
                        static_cast<int>(line.size()), &print_prefix);
    std::string text = line.data();
    while (!text.empty() && (text.back() == '\n' || text.back() == '\r')) text.pop_back();
    if (!text.empty()) spdlog::debug("ffmpeg: {}", text);
}

void route_ffmpeg_log() {
    static const bool routed = [] {
        av_log_set_callback(log_to_spdlog);
        return true;
    }();
    (void)routed;
}

std::string av_error_text(int code) {
    std::array<char, AV_ERROR_MAX_STRING_SIZE> text{};
    av_strerror(code, text.data(), text.size());
    return text.data();
}

void check_av(int code, const std::string& what) {
    if (code < 0) throw std::runtime_error(fmt::format("{}: {}", what, av_error_text(code)));
}

const AVOutputFormat* container_for(const std::filesystem::path& output) {
    const AVOutputFormat* format = av_guess_format(nullptr, output.string().c_str(), nullptr);
    if (!format) {
        throw std::invalid_argument(
            fmt::format("no video container for '{}' (use .mp4, .mkv, .webm, .gif, .webp or .apng)",
                        output.filename().string()));
    }
    return format;
}

const AVCodec* encoder_named(const std::string& name) {
    const AVCodec* codec = avcodec_find_encoder_by_name(name.c_str());
    if (!codec || codec->type != AVMEDIA_TYPE_VIDEO) {
        throw std::invalid_argument(fmt::format(
            "unknown video codec '{}' (try libx264, mpeg4, libvpx-vp9; `ffmpeg -encoders` lists "
            "FFmpeg's)",
            name));
    }
    return codec;
}

// yuv420p where the codec takes it (what players expect), else full RGB, else its first format.
AVPixelFormat pixel_format_for(const AVCodec* codec) {
    if (!codec->pix_fmts) return AV_PIX_FMT_YUV420P;
    for (const AVPixelFormat* format = codec->pix_fmts; *format != AV_PIX_FMT_NONE; ++format) {
        if (*format == AV_PIX_FMT_YUV420P) return *format;
    }
    for (const AVPixelFormat* format = codec->pix_fmts; *format != AV_PIX_FMT_NONE; ++format) {
        if (*format == AV_PIX_FMT_RGB24) return *format;
    }
    return codec->pix_fmts[0];
}

void check_size(const AVCodec* codec, AVPixelFormat format, int width, int height) {
    const AVPixFmtDescriptor* descriptor = av_pix_fmt_desc_get(format);
    const int step_x = 1 << descriptor->log2_chroma_w, step_y = 1 << descriptor->log2_chroma_h;
    if (width % step_x != 0 || height % step_y != 0) {
        throw std::invalid_argument(fmt::format(
            "codec {} encodes {}, which needs a width that is a multiple of {} and a height that "
            "is a multiple of {} (got {}x{})",
            codec->name, descriptor->name, step_x, step_y, width, height));
    }
}

// High quality for each encoder we know: visually lossless at typical viewing.
void set_quality(AVCodecContext* context, const std::string& name, std::optional<int> crf,
                 std::string& description) {
    if (name == "libx264" || name == "libx265") {
        const std::string level = std::to_string(crf.value_or(18));
        av_opt_set(context->priv_data, "crf", level.c_str(), 0);
        av_opt_set(context->priv_data, "preset", "medium", 0);
        description += ", crf " + level;
    } else if (name == "libvpx-vp9" || name == "libaom-av1") {
        const std::string level = std::to_string(crf.value_or(24));
        av_opt_set(context->priv_data, "crf", level.c_str(), 0);
        context->bit_rate = 0;  // constant quality
        description += ", crf " + level;
    } else if (name == "mpeg4" || name == "mpeg2video" || name == "mjpeg") {
        context->flags |= AV_CODEC_FLAG_QSCALE;
        context->global_quality = FF_QP2LAMBDA * 2;
        description += ", qscale 2";
    } else if (name == "libwebp_anim" || name == "libwebp") {
        av_opt_set(context->priv_data, "quality", "80", 0);
        description += ", quality 80";
    }
}

std::string default_codec(const std::filesystem::path& output) {
    const std::string container = container_for(output)->name;
    if (container == "webm") return "libvpx-vp9";
    if (container == "gif") return "gif";
    if (container == "webp") return "libwebp_anim";
    if (container == "apng") return "apng";
    // mp4, mov, matroska and anything else: H.264 where this FFmpeg was built with x264.
    return avcodec_find_encoder_by_name("libx264") ? "libx264" : "mpeg4";
}

void check_settings(const std::filesystem::path& output, const VideoSettings& settings) {
    const AVOutputFormat* container = container_for(output);
    const std::string name = settings.codec.empty() ? default_codec(output) : settings.codec;
    const AVCodec* codec = encoder_named(name);
    if (avformat_query_codec(container, codec->id, FF_COMPLIANCE_NORMAL) != 1) {
        throw std::invalid_argument(fmt::format("codec {} cannot go into a .{} file ({})", name,
                                                container->name, container->long_name));
    }
    check_size(codec, pixel_format_for(codec), settings.width, settings.height);
    // MOV (QuickTime) stores metadata text behind a 16-bit length: a longer view would be cut.
    constexpr std::size_t kMaxMovText = 0xffff;
    if (std::string(container->name) == "mov" && settings.embedded_view.size() > kMaxMovText) {
        throw std::invalid_argument(fmt::format(
            "a .mov file keeps at most {} bytes of metadata, and the view is {} (use .mp4 or .mkv)",
            kMaxMovText, settings.embedded_view.size()));
    }
    const bool has_crf =
        name == "libx264" || name == "libx265" || name == "libvpx-vp9" || name == "libaom-av1";
    const int most = name == "libx264" || name == "libx265" ? 51 : 63;
    if (settings.crf && !has_crf) {
        throw std::invalid_argument(
            fmt::format("--crf is for libx264, libx265, libvpx-vp9 and "
                        "libaom-av1, not {}",
                        name));
    }
    if (settings.crf && (*settings.crf < 0 || *settings.crf > most)) {
        throw std::invalid_argument(
            fmt::format("--crf {} is outside {}'s range [0, {}]", *settings.crf, name, most));
    }
}

}  // namespace

namespace video_backend {

struct Encoder {
    AVFormatContext* format = nullptr;
    AVCodecContext* codec = nullptr;
    AVStream* stream = nullptr;
    SwsContext* scaler = nullptr;
    AVFrame* frame = nullptr;
    AVPacket* packet = nullptr;
    long frames = 0;
    std::string output;  // for error messages

    ~Encoder() {
        av_packet_free(&packet);
        av_frame_free(&frame);
        sws_freeContext(scaler);
        avcodec_free_context(&codec);
        if (format) {
            if (format->pb) avio_closep(&format->pb);
            avformat_free_context(format);
        }
    }

    // Hands every packet the encoder has ready to the muxer.
    void drain() {
        while (true) {
            const int received = avcodec_receive_packet(codec, packet);
            if (received == AVERROR(EAGAIN) || received == AVERROR_EOF) return;
            check_av(received, "encoding a video frame");
            av_packet_rescale_ts(packet, codec->time_base, stream->time_base);
            packet->stream_index = stream->index;
            check_av(av_interleaved_write_frame(format, packet), "writing the video");
        }
    }
};

namespace {

void open_encoder(Encoder& state, const std::filesystem::path& output,
                  const std::filesystem::path& temporary, const VideoSettings& settings,
                  std::string& description) {
    route_ffmpeg_log();
    check_settings(output, settings);
    const AVOutputFormat* container = container_for(output);
    const AVCodec* codec = encoder_named(settings.codec);
    const AVPixelFormat pixels = pixel_format_for(codec);
    state.output = output.string();

    check_av(avformat_alloc_output_context2(&state.format, container, nullptr,
                                            temporary.string().c_str()),
             "opening the video container");
    state.codec = avcodec_alloc_context3(codec);
    state.codec->width = settings.width;
    state.codec->height = settings.height;
    state.codec->pix_fmt = pixels;
    state.codec->framerate = av_d2q(settings.fps, 100000);
    state.codec->time_base = av_inv_q(state.codec->framerate);
    // Tagged BT.709 (the matrix the conversion below uses), limited range, sRGB transfer.
    state.codec->colorspace = AVCOL_SPC_BT709;
    state.codec->color_primaries = AVCOL_PRI_BT709;
    state.codec->color_trc = AVCOL_TRC_IEC61966_2_1;
    state.codec->color_range = AVCOL_RANGE_MPEG;
    if (container->flags & AVFMT_GLOBALHEADER) state.codec->flags |= AV_CODEC_FLAG_GLOBAL_HEADER;
    description = fmt::format("{} ({}", settings.codec, av_get_pix_fmt_name(pixels));
    set_quality(state.codec, settings.codec, settings.crf, description);
    description += ")";
    check_av(avcodec_open2(state.codec, codec, nullptr), "opening codec " + settings.codec);

    state.stream = avformat_new_stream(state.format, nullptr);
    if (!state.stream) throw std::runtime_error("cannot add a video stream");
    state.stream->time_base = state.codec->time_base;
    state.stream->avg_frame_rate = state.codec->framerate;
    check_av(avcodec_parameters_from_context(state.stream->codecpar, state.codec),
             "setting up the video stream");

    state.frame = av_frame_alloc();
    state.packet = av_packet_alloc();
    state.frame->format = pixels;
    state.frame->width = settings.width;
    state.frame->height = settings.height;
    check_av(av_frame_get_buffer(state.frame, 0), "allocating a video frame");
    state.scaler = sws_getContext(
        settings.width, settings.height, AV_PIX_FMT_RGB24, settings.width, settings.height, pixels,
        SWS_BICUBIC | SWS_ACCURATE_RND | SWS_FULL_CHR_H_INT, nullptr, nullptr, nullptr);
    if (!state.scaler) throw std::runtime_error("cannot convert RGB to the codec's pixel format");
    const int* bt709 = sws_getCoefficients(SWS_CS_ITU709);
    sws_setColorspaceDetails(state.scaler, bt709, 1, bt709, 0, 0, 1 << 16, 1 << 16);

    check_av(avio_open(&state.format->pb, temporary.string().c_str(), AVIO_FLAG_WRITE),
             fmt::format("cannot write '{}'", output.string()));
    AVDictionary* options = nullptr;
    // MP4/MOV: the index at the front, so a browser plays the file while it downloads.
    const std::string container_name = container->name;
    if (container_name == "mp4" || container_name == "mov") {
        av_dict_set(&options, "movflags", "+faststart", 0);
    }
    // Animations loop forever, as on a web page (FFmpeg's WebP muxer plays once by default).
    if (container_name == "webp" || container_name == "gif" || container_name == "apng") {
        av_dict_set(&options, container_name == "apng" ? "plays" : "loop", "0", 0);
    }
    // The view that made the video: MP4 and MOV keep "comment" as iTunes-style metadata (©cmt),
    // Matroska and WebM as a COMMENT tag; the GIF, WebP and APNG muxers write no metadata at all.
    if (!settings.embedded_view.empty()) {
        check_av(av_dict_set(&state.format->metadata, "comment", settings.embedded_view.c_str(), 0),
                 "setting the video's metadata");
    }
    const int header = avformat_write_header(state.format, &options);
    av_dict_free(&options);
    check_av(header, "writing the video header");
}

Encoder* open(const std::filesystem::path& output, const std::filesystem::path& temporary,
              const VideoSettings& settings, std::string* description) {
    auto encoder = std::make_unique<Encoder>();
    open_encoder(*encoder, output, temporary, settings, *description);
    return encoder.release();
}

void add_frame(Encoder* encoder, const Image8& image) {
    Encoder& state = *encoder;
    if (image.width != state.codec->width || image.height != state.codec->height) {
        throw std::runtime_error(fmt::format("a {}x{} frame in a {}x{} video", image.width,
                                             image.height, state.codec->width,
                                             state.codec->height));
    }
    check_av(av_frame_make_writable(state.frame), "preparing a video frame");
    const uint8_t* source[1] = {image.rgb.data()};
    const int source_stride[1] = {3 * image.width};
    sws_scale(state.scaler, source, source_stride, 0, image.height, state.frame->data,
              state.frame->linesize);
    state.frame->pts = state.frames++;
    check_av(avcodec_send_frame(state.codec, state.frame), "encoding a video frame");
    state.drain();
}

void finish(Encoder* encoder) {
    Encoder& state = *encoder;
    check_av(avcodec_send_frame(state.codec, nullptr), "flushing the video encoder");
    state.drain();
    check_av(av_write_trailer(state.format), "writing the video trailer");
    check_av(avio_closep(&state.format->pb), fmt::format("cannot write '{}'", state.output));
}

void close(Encoder* encoder) { delete encoder; }

const Table table = {kVersion, default_codec, check_settings, open, add_frame, finish, close};

}  // namespace
}  // namespace video_backend
}  // namespace fgr

extern "C" __attribute__((visibility("default"))) const fgr::video_backend::Table*
fgr_video_backend() {
    return &fgr::video_backend::table;
}
