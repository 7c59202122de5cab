// Animated GIF: each frame quantised to its own 256-colour palette by libavfilter's
// palettegen (stats_mode=single) and paletteuse (new=1), then libavcodec's GIF encoder, which
// writes a frame's palette as a local colour table where it differs from the first. A per-frame
// palette streams (no frame is held back for a global palette) and keeps the red of colliding
// triangles and the overlay's colours exact where a frame has few colours.

#include "av_clip.hpp"
#include "video_backends.hpp"

#include "collidescope/error.hpp"

#include <cstring>

namespace collidescope::replays {
namespace {

constexpr const char* k_palette_filters =
    "split[a][b];[a]palettegen=stats_mode=single:reserve_transparent=0[p];[b][p]paletteuse=new=1:dither=bayer:bayer_scale=3";

struct GraphFree {
    void operator()(AVFilterGraph* g) const { av().avfilter_graph_free(&g); }
};
struct InOutFree {
    void operator()(AVFilterInOut* io) const { av().avfilter_inout_free(&io); }
};

class GifVideo final : public VideoEncoder {
public:
    explicit GifVideo(const VideoSettings& settings) : m_settings(settings), m_clip(settings.path, "gif") {
        const AVCodec* codec = av().avcodec_find_encoder(AV_CODEC_ID_GIF);
        if (codec == nullptr || av().avfilter_get_by_name("palettegen") == nullptr ||
            av().avfilter_get_by_name("paletteuse") == nullptr) {
            throw UnavailableError(settings.path.string() +
                                   ": this FFmpeg lacks the GIF encoder or the palettegen/paletteuse filters");
        }
        build_graph();
        m_encoder.reset(av().avcodec_alloc_context3(codec));
        if (!m_encoder) m_clip.fail("out of memory for the encoder");
        m_encoder->width = settings.width;
        m_encoder->height = settings.height;
        m_encoder->pix_fmt = AV_PIX_FMT_PAL8;
        m_encoder->framerate = av().av_d2q(settings.fps, 100000);
        m_encoder->time_base = av_inv_q(m_encoder->framerate);
        if (m_clip.wants_global_header()) m_encoder->flags |= AV_CODEC_FLAG_GLOBAL_HEADER;
        m_clip.check(av().avcodec_open2(m_encoder.get(), codec, nullptr), "cannot open the GIF encoder");
        m_clip.start(m_encoder.get(), "loop=0");  // loop forever
        m_input = make_frame(AV_PIX_FMT_RGBA, settings.width, settings.height, settings.path.string());
        m_output.reset(av().av_frame_alloc());
        if (!m_output) m_clip.fail("out of memory for a video frame");
    }

    void add_frame(std::span<const std::uint8_t> rgba) override {
        const std::size_t row = std::size_t(m_settings.width) * 4;
        if (rgba.size() != row * std::size_t(m_settings.height)) {
            m_clip.fail("a frame of " + std::to_string(rgba.size()) + " bytes, not " +
                        std::to_string(m_settings.width) + "x" + std::to_string(m_settings.height) + " RGBA");
        }
        m_clip.check(av().av_frame_make_writable(m_input.get()), "cannot reuse a video frame");
        for (int y = 0; y < m_settings.height; ++y) {
            std::memcpy(m_input->data[0] + std::ptrdiff_t(y) * m_input->linesize[0], rgba.data() + std::size_t(y) * row, row);
        }
        m_input->pts = static_cast<std::int64_t>(m_frames);
        m_clip.check(av().av_buffersrc_add_frame_flags(m_source, m_input.get(), AV_BUFFERSRC_FLAG_KEEP_REF),
                     "cannot quantise a frame");
        drain();
        ++m_frames;
    }

    void finish() override {
        m_clip.check(av().av_buffersrc_add_frame_flags(m_source, nullptr, 0), "cannot quantise the last frames");
        drain();
        m_clip.finish(m_encoder.get());
    }

    std::uint64_t frames() const override { return m_frames; }

private:
    // buffer (RGBA) -> split -> palettegen / paletteuse -> buffersink (PAL8). The graph inserts
    // the RGBA to BGRA conversion palettegen and paletteuse take.
    void build_graph() {
        m_graph.reset(av().avfilter_graph_alloc());
        if (!m_graph) m_clip.fail("out of memory for the palette filters");
        const AVRational rate = av().av_d2q(m_settings.fps, 100000);
        const std::string source_args = "video_size=" + std::to_string(m_settings.width) + "x" +
                                        std::to_string(m_settings.height) + ":pix_fmt=" +
                                        std::to_string(int(AV_PIX_FMT_RGBA)) + ":time_base=" + std::to_string(rate.den) +
                                        "/" + std::to_string(rate.num) + ":pixel_aspect=1/1";
        m_clip.check(av().avfilter_graph_create_filter(&m_source, av().avfilter_get_by_name("buffer"), "in", source_args.c_str(),
                                                  nullptr, m_graph.get()),
                     "cannot set up the palette filters' input");
        m_clip.check(av().avfilter_graph_create_filter(&m_sink, av().avfilter_get_by_name("buffersink"), "out", nullptr, nullptr,
                                                  m_graph.get()),
                     "cannot set up the palette filters' output");
        // What av_opt_set_int_list does for a one-entry list (its macro casts in C style).
        const AVPixelFormat format = AV_PIX_FMT_PAL8;
        m_clip.check(av().av_opt_set_bin(m_sink, "pix_fmts", reinterpret_cast<const std::uint8_t*>(&format), sizeof format,
                                    AV_OPT_SEARCH_CHILDREN),
                     "cannot ask the palette filters for PAL8");
        std::unique_ptr<AVFilterInOut, InOutFree> outputs(av().avfilter_inout_alloc());
        std::unique_ptr<AVFilterInOut, InOutFree> inputs(av().avfilter_inout_alloc());
        if (!outputs || !inputs) m_clip.fail("out of memory for the palette filters");
        outputs->name = av().av_strdup("in");
        outputs->filter_ctx = m_source;
        inputs->name = av().av_strdup("out");
        inputs->filter_ctx = m_sink;
        AVFilterInOut* in = inputs.release();
        AVFilterInOut* out = outputs.release();
        const int status = av().avfilter_graph_parse_ptr(m_graph.get(), k_palette_filters, &in, &out, nullptr);
        av().avfilter_inout_free(&in);
        av().avfilter_inout_free(&out);
        m_clip.check(status, "cannot build the palette filters");
        m_clip.check(av().avfilter_graph_config(m_graph.get(), nullptr), "cannot configure the palette filters");
    }

    // Encodes every quantised frame the filters have ready.
    void drain() {
        for (;;) {
            const int status = av().av_buffersink_get_frame(m_sink, m_output.get());
            if (status == AVERROR(EAGAIN) || status == AVERROR_EOF) return;
            m_clip.check(status, "cannot quantise a frame");
            m_output->pict_type = AV_PICTURE_TYPE_NONE;
            m_output->pts = av().av_rescale_q(m_output->pts, av().av_buffersink_get_time_base(m_sink), m_encoder->time_base);
            m_clip.encode(m_encoder.get(), m_output.get());
            av().av_frame_unref(m_output.get());
        }
    }

    VideoSettings m_settings;
    AvClip m_clip;
    std::unique_ptr<AVFilterGraph, GraphFree> m_graph;
    AVFilterContext* m_source = nullptr;  ///< owned by m_graph
    AVFilterContext* m_sink = nullptr;    ///< owned by m_graph
    AvCodecContextPtr m_encoder;
    AvFramePtr m_input;
    AvFramePtr m_output;
    std::uint64_t m_frames = 0;
};

}  // namespace

std::unique_ptr<VideoEncoder> open_gif_video(const VideoSettings& settings) {
    return std::make_unique<GifVideo>(settings);
}

}  // namespace collidescope::replays
