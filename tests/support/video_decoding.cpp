// SPDX-License-Identifier: Apache-2.0
#include "video_decoding.hpp"

#include <gtest/gtest.h>

#include <memory>

extern "C" {
#include <libavcodec/avcodec.h>
#include <libavformat/avformat.h>
#include <libswscale/swscale.h>
}

namespace fgr::test {

DecodedVideo decode_video(const std::filesystem::path& file) {
    DecodedVideo video;
    AVFormatContext* format = nullptr;
    if (avformat_open_input(&format, file.c_str(), nullptr, nullptr) < 0) {
        ADD_FAILURE() << "cannot open " << file;
        return video;
    }
    std::unique_ptr<AVFormatContext, void (*)(AVFormatContext*)> format_owner(
        format, [](AVFormatContext* f) { avformat_close_input(&f); });
    avformat_find_stream_info(format, nullptr);
    const AVCodec* decoder = nullptr;
    const int index = av_find_best_stream(format, AVMEDIA_TYPE_VIDEO, -1, -1, &decoder, 0);
    if (index < 0 || !decoder) {
        ADD_FAILURE() << "no video stream in " << file;
        return video;
    }
    const AVStream* stream = format->streams[index];
    video.codec = avcodec_get_name(stream->codecpar->codec_id);
    video.frames_in_header = static_cast<long>(stream->nb_frames);
    video.duration = static_cast<double>(format->duration) / AV_TIME_BASE;
    std::unique_ptr<AVCodecContext, void (*)(AVCodecContext*)> context(
        avcodec_alloc_context3(decoder), [](AVCodecContext* c) { avcodec_free_context(&c); });
    avcodec_parameters_to_context(context.get(), stream->codecpar);
    if (avcodec_open2(context.get(), decoder, nullptr) < 0) {
        ADD_FAILURE() << "cannot open the decoder";
        return video;
    }
    AVPacket* packet = av_packet_alloc();
    AVFrame* frame = av_frame_alloc();
    const auto take_frames = [&] {
        while (avcodec_receive_frame(context.get(), frame) >= 0) {
            Image8 image{
                frame->width, frame->height,
                std::vector<uint8_t>(static_cast<size_t>(frame->width) * frame->height * 3)};
            SwsContext* scaler = sws_getContext(
                frame->width, frame->height, static_cast<AVPixelFormat>(frame->format),
                frame->width, frame->height, AV_PIX_FMT_RGB24,
                SWS_BICUBIC | SWS_ACCURATE_RND | SWS_FULL_CHR_H_INT, nullptr, nullptr, nullptr);
            const int* bt709 = sws_getCoefficients(SWS_CS_ITU709);
            sws_setColorspaceDetails(scaler, bt709, frame->color_range == AVCOL_RANGE_JPEG, bt709,
                                     1, 0, 1 << 16, 1 << 16);
            uint8_t* destination[1] = {image.rgb.data()};
            const int stride[1] = {3 * frame->width};
            sws_scale(scaler, frame->data, frame->linesize, 0, frame->height, destination, stride);
            sws_freeContext(scaler);
            video.frames.push_back(std::move(image));
        }
    };
    while (av_read_frame(format, packet) >= 0) {
        if (packet->stream_index == index) {
            avcodec_send_packet(context.get(), packet);
            take_frames();
        }
        av_packet_unref(packet);
    }
    avcodec_send_packet(context.get(), nullptr);
    take_frames();
    av_frame_free(&frame);
    av_packet_free(&packet);
    return video;
}

}  // namespace fgr::test
