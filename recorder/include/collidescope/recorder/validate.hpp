#pragma once
/// Invariants of a recording (what `collidescope validate` checks): schema version (on open),
/// units on every dataset, every per-frame dataset as long as the others, monotone frame
/// numbers, CSR offsets starting at 0, non-decreasing and within their flat arrays, pairs
/// canonical, sorted and naming existing triangles, counts matching the arrays they count,
/// positions one frame of the topology in force (or dropped), topologies from increasing
/// frames with vertex indices in range, known methods, finite non-negative times.

#include <cstddef>
#include <string>
#include <vector>

namespace collidescope::recorder {

class Recording;  // reader.hpp

struct ValidationReport {
    std::vector<std::string> problems;  ///< one line each, naming dataset and frame
    std::size_t problems_omitted = 0;   ///< beyond the first `max_problems`
    bool finished = false;              ///< the writer closed the file cleanly
    std::uint64_t frames_complete = 0;
};

/// Checks every invariant over the complete frames. Reads that fail (a corrupt file) throw
/// InputError; broken invariants are reported, not thrown.
ValidationReport validate_recording(const Recording& recording, std::size_t max_problems = 50);

}  // namespace collidescope::recorder
