#pragma once
// Where a data output goes: a file, or stdout for `-`. A file is written under a `.partial`
// name, flushed after every frame, and takes its own name only when the run completes: a run
// that is interrupted (a signal, a kill, a full disk) never leaves a truncated file that looks
// complete, and keeps every frame it finished in the `.partial` file.

#include <cstdint>
#include <memory>
#include <ostream>
#include <string>

namespace collidescope::app {

/// An output named on the command line: `-` is stdout, an existing device or pipe
/// (/dev/null, a FIFO) is written in place, anything else a file.
class OutputStream {
public:
    /// Opens `target` (a file: removes an existing `target`, creates `target.partial`). Throws
    /// InputError naming it when the file cannot be created.
    explicit OutputStream(const std::string& target);
    ~OutputStream();
    OutputStream(const OutputStream&) = delete;
    OutputStream& operator=(const OutputStream&) = delete;

    std::ostream& stream() { return *m_stream; }
    /// Flushes what frame `frame` wrote; throws InputError naming the file, the frame and the
    /// system's reason when it could not be written (disk full, file size limit), after
    /// cutting the file back to the frames before it.
    void end_frame(std::uint32_t frame);
    /// Flushes and closes; a file takes its name (the rename is atomic). Throws InputError
    /// naming the file when anything failed to write.
    void finish();
    /// Flushes and closes an interrupted run's output, keeping the `.partial` name.
    void finish_partial();
    /// Where the data is: "stdout", the `.partial` file, or (after finish) the file.
    std::string location() const;

    /// The name a file output has until the run completes.
    static std::string partial_name(const std::string& target) { return target + ".partial"; }

private:
    class FileBuffer;
    void flush_or_throw(const std::string& what);

    std::string m_target;
    bool m_to_stdout;
    bool m_direct = false;  ///< an existing device or pipe: written in place, never renamed
    bool m_renamed = false;
    std::uint64_t m_good_bytes = 0;  ///< file size after the last frame written whole
    std::unique_ptr<FileBuffer> m_buffer;
    std::unique_ptr<std::ostream> m_file_stream;
    std::ostream* m_stream = nullptr;
};

}  // namespace collidescope::app
