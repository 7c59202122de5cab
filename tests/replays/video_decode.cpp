// decode_video(): a clip back to frames, through FFmpeg's libraries.

#include "video_decode.hpp"

extern "C" {
#include <libavcodec/avcodec.h>
#include <libavformat/avformat.h>
#include <libavutil/pixdesc.h>
#include <libswscale/swscale.h>
}

#include <cmath>
#include <cstdlib>
#include <limits>
#include <memory>

namespace collidescope::testing {
namespace {

struct Decoder {
    AVFormatContext* format = nullptr;
    AVCodecContext* codec = nullptr;
    AVPacket* packet = av_packet_alloc();
    AVFrame* frame = av_frame_alloc();
    ~Decoder() {
        av_frame_free(&frame);
        av_packet_free(&packet);
        avcodec_free_context(&codec);
        avformat_close_input(&format);
    }
};

std::vector<std::uint8_t> to_rgba(const AVFrame* frame) {
    SwsContext* sws = sws_getContext(frame->width, frame->height, static_cast<AVPixelFormat>(frame->format), frame->width,
                                     frame->height, AV_PIX_FMT_RGBA, SWS_BILINEAR, nullptr, nullptr, nullptr);
    // swscale's SIMD stores run past the end of a row whose width is not a multiple of its
    // vector size: slack after the last row, cut off afterwards.
    const std::size_t bytes = std::size_t(frame->width) * std::size_t(frame->height) * 4;
    std::vector<std::uint8_t> rgba(bytes + 1024);
    std::uint8_t* planes[1] = {rgba.data()};
    const int strides[1] = {4 * frame->width};
    sws_scale(sws, frame->data, frame->linesize, 0, frame->height, planes, strides);
    sws_freeContext(sws);
    rgba.resize(bytes);
    return rgba;
}

// Takes every frame the decoder has ready.
void receive(Decoder& d, DecodedVideo& out) {
    while (avcodec_receive_frame(d.codec, d.frame) == 0) {
        if (out.frames == 0) {
            out.width = d.frame->width;
            out.height = d.frame->height;
            const char* name = av_get_pix_fmt_name(static_cast<AVPixelFormat>(d.frame->format));
            out.pixel_format = name != nullptr ? name : "";
        }
        out.rgba.push_back(to_rgba(d.frame));
        ++out.frames;
        av_frame_unref(d.frame);
    }
}

}  // namespace

DecodedVideo decode_video(const std::filesystem::path& file) {
    DecodedVideo out;
    Decoder d;
    if (avformat_open_input(&d.format, file.c_str(), nullptr, nullptr) < 0) {
        out.error = "cannot open " + file.string();
        return out;
    }
    if (avformat_find_stream_info(d.format, nullptr) < 0) {
        out.error = "no stream info";
        return out;
    }
    const AVCodec* codec = nullptr;
    const int stream = av_find_best_stream(d.format, AVMEDIA_TYPE_VIDEO, -1, -1, &codec, 0);
    if (stream < 0 || codec == nullptr) {
        out.error = "no video stream";
        return out;
    }
    d.codec = avcodec_alloc_context3(codec);
    avcodec_parameters_to_context(d.codec, d.format->streams[stream]->codecpar);
    d.codec->thread_count = 1;
    if (avcodec_open2(d.codec, codec, nullptr) < 0) {
        out.error = "cannot open the decoder";
        return out;
    }
    out.opened = true;
    out.codec = codec->name;
    const char* profile = avcodec_profile_name(codec->id, d.format->streams[stream]->codecpar->profile);
    out.profile = profile != nullptr ? profile : "";
    const AVRational rate = d.format->streams[stream]->avg_frame_rate;
    out.fps = rate.den != 0 ? av_q2d(rate) : 0;
    while (av_read_frame(d.format, d.packet) >= 0) {
        if (d.packet->stream_index == stream) {
            avcodec_send_packet(d.codec, d.packet);
            receive(d, out);
        }
        av_packet_unref(d.packet);
    }
    avcodec_send_packet(d.codec, nullptr);
    receive(d, out);
    return out;
}

double mean_rgb_difference(const std::vector<std::uint8_t>& a, const std::vector<std::uint8_t>& b) {
    if (a.size() != b.size() || a.empty()) return 255;
    double sum = 0;
    for (std::size_t i = 0; i < a.size(); i += 4) {
        for (std::size_t c = 0; c < 3; ++c) sum += std::abs(int(a[i + c]) - int(b[i + c]));
    }
    return sum / double(a.size() / 4 * 3);
}

std::vector<FrameMatch> match_frames(const DecodedVideo& video, const std::vector<std::vector<std::uint8_t>>& images) {
    std::vector<FrameMatch> matches;
    for (const std::vector<std::uint8_t>& frame : video.rgba) {
        FrameMatch best{0, std::numeric_limits<double>::infinity()};
        for (std::size_t i = 0; i < images.size(); ++i) {
            const double difference = mean_rgb_difference(frame, images[i]);
            if (difference < best.difference) best = {i, difference};
        }
        matches.push_back(best);
    }
    return matches;
}

}  // namespace collidescope::testing
