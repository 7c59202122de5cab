// fallocate(2) ahead of each frame.

#include "space_reserve.hpp"

#include "collidescope/error.hpp"

#include <cerrno>
#include <cstring>

#include <fcntl.h>
#include <unistd.h>

namespace collidescope::recorder {

SpaceReserve::SpaceReserve(const std::filesystem::path& path) : m_path(path.string()) {
    m_fd = ::open(m_path.c_str(), O_WRONLY | O_CLOEXEC);
    if (m_fd < 0) throw InputError(m_path + ": cannot open it to reserve space (" + std::strerror(errno) + ")");
}

SpaceReserve::~SpaceReserve() { close(); }

void SpaceReserve::close() {
    if (m_fd >= 0) ::close(m_fd);
    m_fd = -1;
}

void SpaceReserve::reserve(std::uint64_t offset, std::uint64_t bytes) {
    if (!m_supported || m_fd < 0 || bytes == 0) return;
    int result = 0;
    do {
        result = ::fallocate(m_fd, 0, static_cast<off_t>(offset), static_cast<off_t>(bytes));
    } while (result != 0 && errno == EINTR);
    if (result == 0) return;
    const int error = errno;
    if (error == EOPNOTSUPP || error == ENOSYS) {  // e.g. some network file systems: write and hope
        m_supported = false;
        return;
    }
    throw InputError(m_path + ": cannot reserve " + std::to_string(bytes) + " bytes at byte " +
                     std::to_string(offset) + " (" + std::strerror(error) + ")");
}

}  // namespace collidescope::recorder
