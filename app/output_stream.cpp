// Output files and stdout.

#include "output_stream.hpp"

#include "collidescope/error.hpp"

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <streambuf>
#include <vector>

#include <fcntl.h>
#include <unistd.h>

namespace collidescope::app {

// A buffered file that remembers why its first write failed: std::ofstream reports only that
// one did, and errno is long overwritten by the time the caller looks.
class OutputStream::FileBuffer final : public std::streambuf {
public:
    explicit FileBuffer(const std::string& path) : m_buffer(1u << 16) {
        m_fd = ::open(path.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
        if (m_fd < 0) m_error = errno;
        setp(m_buffer.data(), m_buffer.data() + m_buffer.size());
    }
    ~FileBuffer() override { close(); }

    bool is_open() const { return m_fd >= 0; }
    int error() const { return m_error; }        ///< errno of the first failure, 0 while none
    std::uint64_t written() const { return m_written; }  ///< bytes that reached the file

    bool close() {
        const bool ok = drain();
        if (m_fd >= 0 && ::close(m_fd) != 0 && m_error == 0) m_error = errno;
        m_fd = -1;
        return ok && m_error == 0;
    }

protected:
    int_type overflow(int_type ch) override {
        if (!drain()) return traits_type::eof();
        if (!traits_type::eq_int_type(ch, traits_type::eof())) {
            *pptr() = traits_type::to_char_type(ch);
            pbump(1);
        }
        return traits_type::not_eof(ch);
    }
    int sync() override { return drain() ? 0 : -1; }

private:
    // Writes the buffer out; false (and the reason kept) on the first failure.
    bool drain() {
        if (m_error != 0 || m_fd < 0) return false;
        const char* data = pbase();
        std::size_t left = static_cast<std::size_t>(pptr() - pbase());
        while (left > 0) {
            const ssize_t n = ::write(m_fd, data, left);
            if (n < 0 && errno == EINTR) continue;
            if (n <= 0) {
                m_error = n < 0 ? errno : ENOSPC;
                return false;
            }
            data += n;
            left -= static_cast<std::size_t>(n);
            m_written += static_cast<std::uint64_t>(n);
        }
        setp(m_buffer.data(), m_buffer.data() + m_buffer.size());
        return true;
    }

    std::vector<char> m_buffer;
    int m_fd = -1;
    int m_error = 0;
    std::uint64_t m_written = 0;
};

OutputStream::OutputStream(const std::string& target) : m_target(target), m_to_stdout(target == "-") {
    if (m_to_stdout) {
        m_stream = &std::cout;
        return;
    }
    // A device or a pipe (/dev/null, a FIFO) is written as it is: it has no .partial to keep,
    // and removing or renaming over it would replace the device with a file.
    std::error_code status_error;
    const std::filesystem::file_status status = std::filesystem::status(target, status_error);
    m_direct = !status_error && std::filesystem::exists(status) && !std::filesystem::is_regular_file(status) &&
               !std::filesystem::is_directory(status);
    const std::string path = m_direct ? target : partial_name(target);
    m_buffer = std::make_unique<FileBuffer>(path);
    if (!m_buffer->is_open()) {
        throw InputError(path + ": cannot " + (m_direct ? "open" : "create file") + " (" + std::strerror(m_buffer->error()) + ")");
    }
    m_file_stream = std::make_unique<std::ostream>(m_buffer.get());
    m_stream = m_file_stream.get();
    if (m_direct) return;
    // A complete file from an earlier run must not pass for this run's output if it stops.
    std::error_code ignored;
    std::filesystem::remove(target, ignored);
}

OutputStream::~OutputStream() = default;

void OutputStream::flush_or_throw(const std::string& what) {
    m_stream->flush();
    if (*m_stream && (m_buffer == nullptr || m_buffer->error() == 0)) return;
    std::string message = location() + ": " + what;
    if (m_buffer == nullptr) throw InputError(message);
    message += " (" + std::string(std::strerror(m_buffer->error())) + ")";
    // Cut what reached the disk of the failed frame, so the file ends on a whole frame.
    m_buffer->close();
    std::error_code ignored;
    if (!m_direct) std::filesystem::resize_file(partial_name(m_target), m_good_bytes, ignored);
    throw InputError(message + "; the file holds the frames before it");
}

void OutputStream::end_frame(std::uint32_t frame) {
    flush_or_throw("cannot write frame " + std::to_string(frame));
    if (m_buffer) m_good_bytes = m_buffer->written();
}

void OutputStream::finish() {
    flush_or_throw("cannot write the end of the output");
    if (m_to_stdout) return;
    if (!m_buffer->close()) {
        throw InputError(location() + ": cannot close the file (" + std::strerror(m_buffer->error()) + ")");
    }
    if (m_direct) {
        m_renamed = true;
        return;
    }
    std::error_code error;
    std::filesystem::rename(partial_name(m_target), m_target, error);
    if (error) throw InputError(partial_name(m_target) + ": cannot rename it to " + m_target + " (" + error.message() + ")");
    m_renamed = true;
}

void OutputStream::finish_partial() {
    flush_or_throw("cannot write the end of the output");
    if (m_buffer) m_buffer->close();
}

std::string OutputStream::location() const {
    if (m_to_stdout) return "stdout";
    return m_renamed || m_direct ? m_target : partial_name(m_target);
}

}  // namespace collidescope::app
