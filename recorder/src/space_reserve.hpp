#pragma once
// Disk space for the next frame, allocated before HDF5 writes it. On a full disk (or past a
// file size limit) HDF5 fails half-way through a flush: its metadata, small and early in the
// file, gets written while the new chunks do not, and the superblock then records an end of
// file past the real one, so HDF5 refuses to open the file at all (measured: "truncated file:
// eof = 4096000, stored_eof = 4216140"). Reserving the frame's bytes first turns a full disk
// into a clean stop between frames: nothing of the frame was written, every frame before it
// stays readable.

#include <cstdint>
#include <filesystem>
#include <string>

namespace collidescope::recorder {

class SpaceReserve {
public:
    /// Opens `path` (created by HDF5 already) for fallocate. Throws InputError naming it.
    explicit SpaceReserve(const std::filesystem::path& path);
    ~SpaceReserve();
    SpaceReserve(const SpaceReserve&) = delete;
    SpaceReserve& operator=(const SpaceReserve&) = delete;

    /// Allocates bytes [offset, offset + bytes) of the file (extending it). Throws InputError
    /// naming the file, the size and the system's reason (ENOSPC, EFBIG) when it cannot; does
    /// nothing on a file system without fallocate.
    void reserve(std::uint64_t offset, std::uint64_t bytes);
    void close();

private:
    std::string m_path;
    int m_fd = -1;
    bool m_supported = true;
};

}  // namespace collidescope::recorder
