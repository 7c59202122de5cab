#pragma once
// A private directory for the entries that must hand the library a file (fuzz/).

#include <cstddef>
#include <filesystem>
#include <span>

namespace collidescope::fuzz {

/// A directory of this process's own, made on first use (under /dev/shm when it exists, so a
/// million small writes stay in memory) and removed at exit.
const std::filesystem::path& scratch_dir();

/// Writes `bytes` to `file`, replacing it; aborts when that fails (the harness is broken).
void write_file(const std::filesystem::path& file, std::span<const std::byte> bytes);

}  // namespace collidescope::fuzz
