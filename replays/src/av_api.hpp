#pragma once
// FFmpeg's functions as the video backends call them: av().avcodec_open2(...). The five
// libraries are opened at the first call (collidescope/shared_library.hpp), not linked, so
// that only `replay --video` loads libavcodec and the ~160 codec libraries behind it (105 ms
// of every start of `collidescope` otherwise, 175 ms under AddressSanitizer). The sonames come
// from the headers' major versions, and each pointer's type from the header's declaration.

extern "C" {
#include <libavcodec/avcodec.h>
#include <libavfilter/avfilter.h>
#include <libavfilter/buffersink.h>
#include <libavfilter/buffersrc.h>
#include <libavformat/avformat.h>
#include <libavutil/dict.h>
#include <libavutil/error.h>
#include <libavutil/frame.h>
#include <libavutil/log.h>
#include <libavutil/mathematics.h>
#include <libavutil/opt.h>
#include <libavutil/rational.h>
#include <libswscale/swscale.h>
}

namespace collidescope::replays {

// Every FFmpeg function the backends call, with the library that exports it: X(library, name).
#define COLLIDESCOPE_AV_FUNCTIONS(X)                 \
    X(avcodec, avcodec_alloc_context3)               \
    X(avcodec, avcodec_find_encoder)                 \
    X(avcodec, avcodec_find_encoder_by_name)         \
    X(avcodec, avcodec_free_context)                 \
    X(avcodec, avcodec_open2)                        \
    X(avcodec, avcodec_parameters_from_context)      \
    X(avcodec, avcodec_receive_packet)               \
    X(avcodec, avcodec_send_frame)                   \
    X(avcodec, av_packet_alloc)                      \
    X(avcodec, av_packet_free)                       \
    X(avcodec, av_packet_rescale_ts)                 \
    X(avformat, avformat_alloc_output_context2)      \
    X(avformat, avformat_free_context)               \
    X(avformat, avformat_new_stream)                 \
    X(avformat, avformat_write_header)               \
    X(avformat, avio_closep)                         \
    X(avformat, avio_open)                           \
    X(avformat, av_interleaved_write_frame)          \
    X(avformat, av_write_trailer)                    \
    X(avfilter, avfilter_get_by_name)                \
    X(avfilter, avfilter_graph_alloc)                \
    X(avfilter, avfilter_graph_config)               \
    X(avfilter, avfilter_graph_create_filter)        \
    X(avfilter, avfilter_graph_free)                 \
    X(avfilter, avfilter_graph_parse_ptr)            \
    X(avfilter, avfilter_inout_alloc)                \
    X(avfilter, avfilter_inout_free)                 \
    X(avfilter, av_buffersink_get_frame)             \
    X(avfilter, av_buffersink_get_time_base)         \
    X(avfilter, av_buffersrc_add_frame_flags)        \
    X(swscale, sws_freeContext)                      \
    X(swscale, sws_getContext)                       \
    X(swscale, sws_scale)                            \
    X(avutil, av_d2q)                                \
    X(avutil, av_dict_free)                          \
    X(avutil, av_dict_parse_string)                  \
    X(avutil, av_dict_set)                           \
    X(avutil, av_frame_alloc)                        \
    X(avutil, av_frame_free)                         \
    X(avutil, av_frame_get_buffer)                   \
    X(avutil, av_frame_make_writable)                \
    X(avutil, av_frame_unref)                        \
    X(avutil, av_log_set_level)                      \
    X(avutil, av_opt_set_bin)                        \
    X(avutil, av_rescale_q)                          \
    X(avutil, av_strdup)                             \
    X(avutil, av_strerror)

struct AvFunctions {
#define COLLIDESCOPE_AV_POINTER(library, name) decltype(&::name) name = nullptr;
    COLLIDESCOPE_AV_FUNCTIONS(COLLIDESCOPE_AV_POINTER)
#undef COLLIDESCOPE_AV_POINTER
};

/// The functions, loaded at the first call (thread-safe). Throws UnavailableError
/// "FFmpeg: <soname>: <reason>" when a library or function is missing, at every call.
const AvFunctions& av();

}  // namespace collidescope::replays
