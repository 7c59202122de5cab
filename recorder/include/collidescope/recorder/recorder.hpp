#pragma once
/// The recorder: a TraceSink that writes one HDF5 file per session (schema.hpp,
/// docs/reference/recording.md).
///
/// on_frame runs on the engine's thread and only copies the frame into a bounded queue; a
/// writer thread appends the frames waiting to the file and flushes, in SWMR mode, so a killed
/// process leaves every frame flushed before it readable. Not thread-safe: one engine thread calls it.

#include "collidescope/recorder/session_info.hpp"
#include "collidescope/regions.hpp"

#include "collidescope/trace.hpp"

#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

namespace collidescope::recorder {

/// Options of one recording.
struct RecorderConfig {
    std::filesystem::path path;                 ///< the file to create (truncated if it exists)
    std::size_t queue_bytes = 256u << 20;       ///< memory cap of frames waiting for the writer
    std::uint64_t budget_bytes = 0;             ///< file size bound (0 = none): depth images, then positions decimated to fit
    int deflate_level = 1;                      ///< gzip level of compressed datasets (0-9; 1: cheapest)
    int writer_nice = 10;                       ///< nice increment of the writer thread (Linux; 0 = none)
};

/// What a finished recording did.
struct RecordSummary {
    std::uint64_t frames = 0;              ///< frames written
    std::uint64_t file_bytes = 0;          ///< final file size
    std::uint32_t positions_stride = 1;    ///< positions kept every Nth frame at the end (1 = all, 0 = none; --budget)
    std::uint64_t positions_dropped = 0;   ///< frames whose positions were dropped (--budget)
    std::uint64_t depth_frames = 0;        ///< frames that came with depth images
    std::uint64_t depth_dropped = 0;       ///< of those, frames whose depth images were dropped (--budget)
    std::uint32_t depth_stride = 1;        ///< depth images kept every Nth such frame at the end (1 = all, 0 = none)
    std::uint64_t queue_peak_bytes = 0;    ///< largest queue held
};

class Recorder final : public TraceSink {
public:
    /// Creates the file with every group, dataset and attribute, switches to SWMR writing and
    /// starts the writer thread. `first_frame` (the first frame to be recorded) sizes the
    /// chunks; it is not recorded here. Throws InputError naming the file on failure.
    Recorder(RecorderConfig config, SessionInfo session, const Frame& first_frame);
    /// Stops the writer (dropping nothing already queued) and closes the file, if finish() was
    /// not called; errors are swallowed there.
    ~Recorder() override;
    Recorder(const Recorder&) = delete;
    Recorder& operator=(const Recorder&) = delete;

    /// Copies the frame into the queue (blocks while the queue is full). Rethrows, as
    /// InputError, an error the writer thread met: one line naming the file, the frame it
    /// failed on and the frames before it that are intact; the file is left unfinished
    /// (partial), with those frames readable.
    void on_frame(const FrameReport& report) override;
    /// Writes what is queued, closes the file and marks it finished. `interrupted` names the
    /// signal that stopped the run early ("SIGINT"; "" = it ran to its last frame): the file is
    /// then marked partial (attribute `interrupted`). Throws InputError on any write failure.
    RecordSummary finish(const std::string& interrupted = {});
    /// With SessionInfo::regions: the regions on_frame found and followed for the last frame
    /// (what it recorded), so a caller that also wants them need not find them again; empty
    /// before the first frame and without regions.
    const std::vector<Region>& last_regions() const;

private:
    struct State;
    std::unique_ptr<State> m_state;
};

}  // namespace collidescope::recorder
