#pragma once
// The muxing half of a clip (replays/src, private), shared by the H.264 and GIF backends:
// an FFmpeg output file written under a temporary name, an encoder's packets into it, and the
// rename onto the real name at the end.

#include "av_api.hpp"

#include <filesystem>
#include <memory>
#include <string>

namespace collidescope::replays {

/// FFmpeg's text for an error code.
std::string av_error_text(int code);

/// Deleters for FFmpeg's objects, for std::unique_ptr.
struct AvCodecContextFree {
    void operator()(AVCodecContext* c) const { av().avcodec_free_context(&c); }
};
struct AvFrameFree {
    void operator()(AVFrame* f) const { av().av_frame_free(&f); }
};
struct AvPacketFree {
    void operator()(AVPacket* p) const { av().av_packet_free(&p); }
};
using AvCodecContextPtr = std::unique_ptr<AVCodecContext, AvCodecContextFree>;
using AvFramePtr = std::unique_ptr<AVFrame, AvFrameFree>;
using AvPacketPtr = std::unique_ptr<AVPacket, AvPacketFree>;

/// An RGBA-sized frame of `format` (width x height), its buffers allocated. Throws InputError
/// naming `where` on failure.
AvFramePtr make_frame(AVPixelFormat format, int width, int height, const std::string& where);

/// One output file being written. Order: construct (opens the temporary file, so an
/// unwritable directory fails before any frame is rendered), set up and open the encoder
/// (asking wants_global_header()), start(), encode() each frame, finish(). Every failure is an
/// InputError naming the target file. Destroyed without finish(), it closes and removes the
/// temporary file.
class AvClip {
public:
    /// `format`: libavformat's muxer name ("mp4", "gif").
    AvClip(const std::filesystem::path& target, const char* format);
    ~AvClip();
    AvClip(const AvClip&) = delete;
    AvClip& operator=(const AvClip&) = delete;

    /// Whether the muxer wants the codec's headers out of band (AV_CODEC_FLAG_GLOBAL_HEADER).
    bool wants_global_header() const;
    /// Adds the stream of the opened `encoder` and writes the file header with the muxer
    /// options `options` ("movflags=+faststart"; may be "").
    void start(AVCodecContext* encoder, const std::string& options);
    /// Sends `frame` (nullptr: flush) to `encoder` and writes every packet it gives back.
    void encode(AVCodecContext* encoder, const AVFrame* frame);
    /// Flushes `encoder`, writes the trailer, closes and renames onto the target.
    void finish(AVCodecContext* encoder);
    /// Throws InputError "<target>: <what> (<FFmpeg's reason>)" when `code` < 0.
    void check(int code, const std::string& what) const;
    [[noreturn]] void fail(const std::string& what) const;

private:
    void close_and_remove();

    std::filesystem::path m_target;
    std::filesystem::path m_temporary;
    AVFormatContext* m_format = nullptr;
    AVStream* m_stream = nullptr;
    AvPacketPtr m_packet;
    bool m_header_written = false;
};

}  // namespace collidescope::replays
