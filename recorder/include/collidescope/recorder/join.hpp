#pragma once
/// Joining recordings of contiguous frame ranges of one session (`record --frames A:B` on each
/// node of a farm, or the part files of `mpirun ... record`) into one recording that reads
/// exactly as a serial run's (`collidescope join`, docs/how-to/mpi.md).
///
/// The join is generic over the schema: every group, dataset and attribute of the parts is
/// carried over, whatever this build knows of it. Datasets under /frames have one row per
/// frame and are concatenated; a dataset whose name ends in `offsets` holds CSR offsets and is
/// concatenated with each part's entries shifted by the rows before it; every other extensible
/// dataset (a flat array) is concatenated. A part starts with the topology in force at its
/// first frame; when it equals the previous part's last one it is not repeated, as a serial
/// run would not repeat it. Chunks are copied raw (H5Dread_chunk / H5Dwrite_chunk, no
/// decompression) wherever a part's rows start on a chunk boundary of the output.
///
/// A virtual join (JoinLayout::Virtual) copies nothing large: each big row dataset becomes an
/// HDF5 virtual dataset whose mappings read each part's rows where they are, naming the part
/// files relative to the output's directory. The output is small and fast to write, but the
/// parts are its data: they must stay (and move) with it. Readers check them when they open
/// it (reader.hpp): a missing part is an error, never zeros.

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace collidescope::recorder {

/// How the rows get into the output.
enum class JoinLayout {
    Copy,     ///< every row copied: one self-contained file
    Virtual,  ///< large row datasets map the parts' rows (virtual datasets); the rest copied
};

struct JoinOptions {
    JoinLayout layout = JoinLayout::Copy;
    /// Virtual joins: a dataset is mapped (not copied) when the parts hold at least this many
    /// of its rows each, on average (positions, triangles, pairs of real scenes); smaller
    /// ones (the per-frame datasets) and every CSR offsets dataset (whose values are rebased)
    /// are copied. 0 maps every dataset but the offsets and the fixed-size ones.
    std::uint64_t virtual_min_rows = 4096;
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
    std::uint64_t virtual_datasets = 0;  ///< datasets mapped to the parts' rows (virtual joins)
    std::uint64_t virtual_rows = 0;      ///< their rows
    bool complete = true;                ///< marked finished (every part was)
};

/// Joins `parts` (any order: they are sorted by first frame) into `output`, written as
/// `output`.partial and renamed when complete (removed on failure). Throws InputError, one
/// line naming the file(s), when a part is unreadable, when parts come from different scenes,
/// methods, options, builds or layouts, when their frame ranges overlap or leave a gap, or when
/// a part is incomplete and `options.allow_incomplete` is false, or when a part is itself a
/// virtual join (its mappings name files relative to it: join the parts it maps instead).
JoinSummary join_recordings(const std::vector<std::filesystem::path>& parts, const std::filesystem::path& output,
                            const JoinOptions& options = {});

}  // namespace collidescope::recorder
