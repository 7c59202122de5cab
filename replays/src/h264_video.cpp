// H.264 in MP4 (libx264 through libavcodec): yuv420p, even dimensions, High profile, the
// index at the front (faststart), so browsers and common players play it as it downloads.

#include "av_clip.hpp"
#include "video_backends.hpp"

#include "collidescope/error.hpp"

#include <cstring>
#include <vector>

namespace collidescope::replays {
namespace {

struct SwsFree {
    void operator()(SwsContext* c) const { av().sws_freeContext(c); }
};

class H264Video final : public VideoEncoder {
public:
    explicit H264Video(const VideoSettings& settings)
        : m_settings(settings),
          // yuv420p halves chroma both ways: odd sizes grow by one pixel (the last column or
          // row repeated).
          m_width((settings.width + 1) / 2 * 2),
          m_height((settings.height + 1) / 2 * 2),
          m_clip(settings.path, "mp4") {
        const AVCodec* codec = av().avcodec_find_encoder_by_name("libx264");
        if (codec == nullptr) {
            throw UnavailableError(settings.path.string() +
                                   ": this FFmpeg has no H.264 encoder (libx264); write a .gif, or install an "
                                   "FFmpeg built with libx264 (Debian's libavcodec59 is)");
        }
        m_encoder.reset(av().avcodec_alloc_context3(codec));
        if (!m_encoder) m_clip.fail("out of memory for the encoder");
        configure(*m_encoder);
        if (m_clip.wants_global_header()) m_encoder->flags |= AV_CODEC_FLAG_GLOBAL_HEADER;
        AVDictionary* options = nullptr;
        av().av_dict_set(&options, "preset", settings.h264_preset.c_str(), 0);
        av().av_dict_set(&options, "crf", "20", 0);           // text and thin edges stay sharp
        av().av_dict_set(&options, "profile", "high", 0);
        // No lookahead and no B-frames: each frame leaves the encoder as it arrives, so the
        // replay does not wait for a buffered tail of frames at the end (the MP4 replay was 4%
        // slower than the PNG one with it; records/video-encoding.md).
        av().av_dict_set(&options, "tune", "zerolatency", 0);
        const int status = av().avcodec_open2(m_encoder.get(), codec, &options);
        av().av_dict_free(&options);
        m_clip.check(status, "cannot open the H.264 encoder");
        m_clip.start(m_encoder.get(), "movflags=+faststart");
        m_scaler.reset(av().sws_getContext(m_width, m_height, AV_PIX_FMT_RGBA, m_width, m_height, AV_PIX_FMT_YUV420P,
                                      SWS_BILINEAR, nullptr, nullptr, nullptr));
        if (!m_scaler) m_clip.fail("cannot set up the RGBA to yuv420p conversion");
        if (m_width != settings.width || m_height != settings.height) {
            m_padded.resize(std::size_t(m_width) * std::size_t(m_height) * 4);
        }
        m_frame = make_frame(AV_PIX_FMT_YUV420P, m_width, m_height, settings.path.string());
    }

    void add_frame(std::span<const std::uint8_t> rgba) override {
        const std::uint8_t* source = pad(rgba);
        m_clip.check(av().av_frame_make_writable(m_frame.get()), "cannot reuse a video frame");
        const int stride = 4 * m_width;
        m_clip.check(av().sws_scale(m_scaler.get(), &source, &stride, 0, m_height, m_frame->data, m_frame->linesize),
                     "cannot convert a frame to yuv420p");
        m_frame->pts = static_cast<std::int64_t>(m_frames);
        m_clip.encode(m_encoder.get(), m_frame.get());
        ++m_frames;
    }

    void finish() override { m_clip.finish(m_encoder.get()); }
    std::uint64_t frames() const override { return m_frames; }

private:
    void configure(AVCodecContext& encoder) const {
        encoder.width = m_width;
        encoder.height = m_height;
        encoder.pix_fmt = AV_PIX_FMT_YUV420P;
        encoder.framerate = av().av_d2q(m_settings.fps, 100000);
        encoder.time_base = av_inv_q(encoder.framerate);
        encoder.gop_size = 2 * static_cast<int>(m_settings.fps + 0.5);  // a key frame every 2 s: seeking
        // What swscale's default conversion produces: BT.601, limited range; said in the stream.
        encoder.color_range = AVCOL_RANGE_MPEG;
        encoder.colorspace = AVCOL_SPC_SMPTE170M;
        encoder.color_primaries = AVCOL_PRI_SMPTE170M;
        encoder.color_trc = AVCOL_TRC_SMPTE170M;
        // One encoder thread: the render threads already fill the cores, and x264's own pool
        // (frame threads, lookahead) only competed with them (records/video-encoding.md).
        encoder.thread_count = 1;
    }

    // The frame as m_width x m_height: itself, or copied with its last column and row repeated.
    const std::uint8_t* pad(std::span<const std::uint8_t> rgba) {
        if (rgba.size() != std::size_t(m_settings.width) * std::size_t(m_settings.height) * 4) {
            m_clip.fail("a frame of " + std::to_string(rgba.size()) + " bytes, not " +
                        std::to_string(m_settings.width) + "x" + std::to_string(m_settings.height) + " RGBA");
        }
        if (m_padded.empty()) return rgba.data();
        const std::size_t row = std::size_t(m_settings.width) * 4;
        for (int y = 0; y < m_height; ++y) {
            const std::uint8_t* from = rgba.data() + std::size_t(std::min(y, m_settings.height - 1)) * row;
            std::uint8_t* to = m_padded.data() + std::size_t(y) * std::size_t(m_width) * 4;
            std::memcpy(to, from, row);
            if (m_width != m_settings.width) std::memcpy(to + row, from + row - 4, 4);
        }
        return m_padded.data();
    }

    VideoSettings m_settings;
    int m_width;
    int m_height;
    AvClip m_clip;
    AvCodecContextPtr m_encoder;
    std::unique_ptr<SwsContext, SwsFree> m_scaler;
    AvFramePtr m_frame;
    std::vector<std::uint8_t> m_padded;
    std::uint64_t m_frames = 0;
};

}  // namespace

std::unique_ptr<VideoEncoder> open_h264_video(const VideoSettings& settings) {
    return std::make_unique<H264Video>(settings);
}

}  // namespace collidescope::replays
