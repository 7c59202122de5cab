#pragma once
/// Joining recordings of contiguous frame ranges of one session (`record --frames A:B` on each
/// node of a farm, or the part files of `mpirun ... record`) into one recording that reads
/// exactly as a serial run's (`collidescope join`, docs/mpi.md).
///
/// The join is generic over the schema: every group, dataset and attribute of the parts is
/// carried over, whatever this build knows of it. Datasets under /frames have one row per
/// frame and are concatenated; a dataset whose name ends in `offsets` holds CSR offsets and is
/// concatenated with each part's entries shifted by the rows before it; every other extensible
/// dataset (a flat array) is concatenated. A part starts with the topology in force at its
/// first frame; when it equals the previous part's last one it is not repeated, as a serial
/// run would not repeat it. Chunks are copied raw (H5Dread_chunk / H5Dwrite_chunk, no
/// decompression) wherever a part's rows start on a chunk boundary of the output.

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace collidescope::recorder {

struct JoinOptions {
    /// Accept parts that did not finish (a killed rank or node): their complete frames are
    /// joined, and the output, like them, is not marked finished (validate --allow-incomplete).
    bool allow_incomplete = false;
};

struct JoinSummary {
    std::uint64_t parts = 0;
    std::uint64_t frames = 0;
    std::uint64_t raw_chunks = 0;        ///< chunks copied without decoding
    std::uint64_t raw_bytes = 0;         ///< their stored bytes
    std::uint64_t rewritten_rows = 0;    ///< rows decoded and encoded again (not lined up with the chunks)
    bool complete = true;                ///< marked finished (every part was)
};

/// Joins `parts` (any order: they are sorted by first frame) into `output`, written as
/// `output`.partial and renamed when complete (removed on failure). Throws InputError, one
/// line naming the file(s), when a part is unreadable, when parts come from different scenes,
/// methods, options, builds or layouts, when their frame ranges overlap or leave a gap, or when
/// a part is incomplete and `options.allow_incomplete` is false.
JoinSummary join_recordings(const std::vector<std::filesystem::path>& parts, const std::filesystem::path& output,
                            const JoinOptions& options = {});

}  // namespace collidescope::recorder
