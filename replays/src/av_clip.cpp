// The muxing half of a clip: temporary file, header, packets, trailer, rename.

#include "av_clip.hpp"

#include "collidescope/error.hpp"

#include <system_error>

namespace collidescope::replays {
namespace {

// ".NAME.partial" beside the target: same file system (so the rename is atomic), hidden, and
// never mistaken for a finished clip.
std::filesystem::path temporary_name(const std::filesystem::path& target) {
    std::string name = ".";  // appended, not "." + ...: GCC 12 warns falsely (-Wrestrict) on that
    name += target.filename().string();
    name += ".partial";
    return target.parent_path() / name;
}

}  // namespace

std::string av_error_text(int code) {
    char text[AV_ERROR_MAX_STRING_SIZE] = {};
    av().av_strerror(code, text, sizeof text);
    return text;
}

AvFramePtr make_frame(AVPixelFormat format, int width, int height, const std::string& where) {
    AvFramePtr frame(av().av_frame_alloc());
    if (!frame) throw InputError(where + ": out of memory for a video frame");
    frame->format = format;
    frame->width = width;
    frame->height = height;
    const int status = av().av_frame_get_buffer(frame.get(), 0);
    if (status < 0) throw InputError(where + ": cannot allocate a video frame (" + av_error_text(status) + ")");
    return frame;
}

AvClip::AvClip(const std::filesystem::path& target, const char* format)
    : m_target(target), m_temporary(temporary_name(target)), m_packet(av().av_packet_alloc()) {
    if (!m_packet) fail("out of memory for a packet");
    check(av().avformat_alloc_output_context2(&m_format, nullptr, format, m_temporary.c_str()),
          std::string("cannot set up the ") + format + " muxer");
    const int status = av().avio_open(&m_format->pb, m_temporary.c_str(), AVIO_FLAG_WRITE);
    if (status < 0) {
        av().avformat_free_context(m_format);
        m_format = nullptr;
        fail("cannot create " + m_temporary.filename().string() + " beside it (" + av_error_text(status) +
             "; is the directory there and writable?)");
    }
}

AvClip::~AvClip() { close_and_remove(); }

void AvClip::close_and_remove() {
    if (m_format == nullptr) return;
    if (m_format->pb != nullptr) av().avio_closep(&m_format->pb);
    av().avformat_free_context(m_format);
    m_format = nullptr;
    std::error_code ignored;
    std::filesystem::remove(m_temporary, ignored);
}

bool AvClip::wants_global_header() const { return (m_format->oformat->flags & AVFMT_GLOBALHEADER) != 0; }

void AvClip::start(AVCodecContext* encoder, const std::string& options) {
    m_stream = av().avformat_new_stream(m_format, nullptr);
    if (m_stream == nullptr) fail("cannot add a video stream");
    check(av().avcodec_parameters_from_context(m_stream->codecpar, encoder), "cannot describe the video stream");
    m_stream->time_base = encoder->time_base;
    m_stream->avg_frame_rate = encoder->framerate;
    AVDictionary* dictionary = nullptr;
    if (!options.empty()) check(av().av_dict_parse_string(&dictionary, options.c_str(), "=", ":", 0), "bad muxer options");
    const int status = av().avformat_write_header(m_format, &dictionary);
    av().av_dict_free(&dictionary);
    check(status, "cannot write the file header");
    m_header_written = true;
}

void AvClip::encode(AVCodecContext* encoder, const AVFrame* frame) {
    check(av().avcodec_send_frame(encoder, frame), "cannot encode a frame");
    for (;;) {
        const int status = av().avcodec_receive_packet(encoder, m_packet.get());
        if (status == AVERROR(EAGAIN) || status == AVERROR_EOF) return;
        check(status, "cannot encode a frame");
        av().av_packet_rescale_ts(m_packet.get(), encoder->time_base, m_stream->time_base);
        m_packet->stream_index = m_stream->index;
        // Takes the packet's reference (and unreferences it) whatever it returns.
        check(av().av_interleaved_write_frame(m_format, m_packet.get()), "cannot write to the file (disk full?)");
    }
}

void AvClip::finish(AVCodecContext* encoder) {
    if (!m_header_written) fail("no frame to write");
    encode(encoder, nullptr);
    // The mp4 muxer's faststart moves the index to the front here, reading the file back.
    check(av().av_write_trailer(m_format), "cannot complete the file");
    check(av().avio_closep(&m_format->pb), "cannot close the file (disk full?)");
    std::error_code error;
    std::filesystem::rename(m_temporary, m_target, error);
    if (error) fail("cannot move " + m_temporary.filename().string() + " onto it (" + error.message() + ")");
    av().avformat_free_context(m_format);
    m_format = nullptr;
}

void AvClip::check(int code, const std::string& what) const {
    if (code < 0) fail(what + " (" + av_error_text(code) + ")");
}

void AvClip::fail(const std::string& what) const { throw InputError(m_target.string() + ": " + what); }

}  // namespace collidescope::replays
