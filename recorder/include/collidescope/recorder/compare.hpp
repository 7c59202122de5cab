#pragma once
/// Comparing two recordings (what `collidescope compare` reports): frames are matched by scene
/// frame number; per matched frame the pairs only in a and only in b; per stage the median and
/// total milliseconds of each and their ratio b / a.

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace collidescope::recorder {

class Recording;  // reader.hpp

struct FrameDifference {
    std::uint32_t frame = 0;        ///< scene frame number
    std::uint64_t only_a = 0;       ///< pairs in a, not in b
    std::uint64_t only_b = 0;       ///< pairs in b, not in a
};

struct StageComparison {
    std::string stage;
    double median_a = 0, median_b = 0;  ///< ms, over the matched frames
    double total_a = 0, total_b = 0;    ///< ms, over the matched frames
};

struct ComparisonReport {
    std::uint64_t matched_frames = 0;
    std::uint64_t frames_only_a = 0;             ///< frames recorded in a alone
    std::uint64_t frames_only_b = 0;
    std::vector<FrameDifference> differences;    ///< matched frames whose pair sets differ, in order
    std::vector<StageComparison> stages;         ///< stages present in both
    /// Schema 1.4: whether both files have /frames/time, and then the first matched frame
    /// whose times differ (the same frame number sampled at another time: another --fps or
    /// clip) and how many do. Times do not change identical_pairs().
    bool both_timed = false;
    std::optional<std::uint32_t> first_time_difference;
    std::uint64_t time_differences = 0;
    /// Same frames and the same pairs in every frame.
    bool identical_pairs() const { return differences.empty() && frames_only_a == 0 && frames_only_b == 0; }
};

/// Compares the complete frames of a and b. Throws InputError on unreadable data.
ComparisonReport compare_recordings(const Recording& a, const Recording& b);

}  // namespace collidescope::recorder
