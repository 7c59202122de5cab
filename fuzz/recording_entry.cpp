// The recording fuzz entry: the input is a recording's bytes, read the way the three commands
// that take a recording read it: `inspect` (inspect_info, and its JSON), `validate`
// (validate_recording) and `replay` (RecordingData: the series, then each frame's geometry,
// topology and culling state, without rendering). Afterwards no HDF5 object may be left open:
// an id the reader forgot to close on an error path is a leak LeakSanitizer cannot see (HDF5
// keeps it reachable), so the entry aborts on one.

#include "entries.hpp"
#include "scratch.hpp"

#include "inspect_info.hpp"
#include "frame_data.hpp"

#include "collidescope/error.hpp"
#include "collidescope/recorder/reader.hpp"
#include "collidescope/recorder/validate.hpp"

#include <hdf5.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>

namespace collidescope::fuzz {
namespace {

// At most this many frames are loaded per input: the seeds hold a few, and a mutated frame
// count must not turn one input into minutes.
constexpr std::uint64_t k_max_rows = 8;

void inspect(const std::filesystem::path& file) {
    const recorder::Recording recording(file);
    (void)app::inspect_info(recording).dump(2);
}

void validate(const std::filesystem::path& file) {
    const recorder::Recording recording(file);
    (void)recording.version_major();
    (void)recorder::validate_recording(recording);
}

void replay(const std::filesystem::path& file) {
    replays::RecordingData data(file);
    (void)data.object_names();
    (void)data.attribute("scene");
    const std::vector<std::uint64_t> rows = data.rows_in(0, UINT32_MAX);
    const std::vector<std::uint64_t> some(rows.begin(), rows.begin() + std::min<std::size_t>(rows.size(), k_max_rows));
    (void)data.bounds(some);
    for (std::size_t k = 0; k < some.size(); ++k) (void)data.load(some[k], k);
}

// Runs one reader; an InputError is the expected answer to bad input.
template <class Read>
bool reads(Read read, const std::filesystem::path& file) {
    try {
        read(file);
        return true;
    } catch (const InputError&) {
        return false;
    }
}

}  // namespace

Outcome read_recording(std::span<const std::byte> bytes) {
    const std::filesystem::path file = scratch_dir() / "recording.h5";
    write_file(file, bytes);
    const bool inspected = reads(inspect, file);
    const bool validated = reads(validate, file);
    const bool replayed = reads(replay, file);
    if (H5Fget_obj_count(H5F_OBJ_ALL, H5F_OBJ_ALL) != 0) {
        std::fprintf(stderr, "fuzz recording: %lld HDF5 objects left open after reading\n",
                     static_cast<long long>(H5Fget_obj_count(H5F_OBJ_ALL, H5F_OBJ_ALL)));
        std::abort();
    }
    return inspected && validated && replayed ? Outcome::Accepted : Outcome::Rejected;
}

}  // namespace collidescope::fuzz
