#pragma once
// Shared by the join tests (test_join.cpp, test_join_virtual.cpp): a joined recording against
// the recording of the whole range.

#include "recording_helpers.hpp"

#include "collidescope/recorder/reader.hpp"

#include <gtest/gtest.h>

#include <algorithm>

namespace collidescope::testing {

using recorder::Recording;

// Everything but the per-run attributes and the stage times (measured, so they differ between
// runs) is the same in `joined` as in `whole`; the work counts too when `all_counts` (brute
// force: no state carried between frames; a hierarchy's counts differ where a part's first
// frame builds the trees that the whole run only refits).
inline void expect_same_recording(const Recording& joined, const Recording& whole, bool all_counts) {
    ASSERT_EQ(joined.frames_complete(), whole.frames_complete());
    EXPECT_EQ(joined.finished(), whole.finished());
    EXPECT_EQ(joined.frame_indices(), whole.frame_indices());
    EXPECT_EQ(joined.frame_methods(), whole.frame_methods());
    EXPECT_EQ(joined.dataset_paths(), whole.dataset_paths());
    for (const std::string& path : whole.dataset_paths()) {
        EXPECT_EQ(joined.rows_of(path), whole.rows_of(path)) << path;
        EXPECT_EQ(joined.unit_of(path), whole.unit_of(path)) << path;
    }
    testing::expect_complete_rows_equal(joined, whole);
    const auto counts = joined.counts();
    const auto whole_counts = whole.counts();
    ASSERT_EQ(counts.size(), whole_counts.size());
    for (std::size_t c = 0; c < counts.size(); ++c) {
        const bool result = counts[c].name == "triangles" || counts[c].name == "colliding_pairs";
        if (all_counts || result) {
            EXPECT_EQ(counts[c].values, whole_counts[c].values) << counts[c].name;
        }
    }
    ASSERT_EQ(joined.objects().size(), whole.objects().size());
    const std::vector<std::uint32_t> frames = whole.frame_indices();
    for (std::uint32_t k = 0; k < whole.objects().size(); ++k) {
        for (const std::uint32_t frame : frames) {
            const std::size_t t = whole.topology_at(k, frame);
            ASSERT_EQ(joined.topology_at(k, frame), t) << "object " << k << " frame " << frame;
            EXPECT_EQ(joined.triangles(k, t), whole.triangles(k, t)) << "object " << k << " frame " << frame;
        }
    }
    for (const auto& [name, value] : whole.metadata()) {
        if (name == "created" || name == "hardware_threads") continue;
        const auto joined_metadata = joined.metadata();
        const auto match = std::find_if(joined_metadata.begin(), joined_metadata.end(),
                                        [&](const auto& entry) { return entry.first == name; });
        ASSERT_NE(match, joined_metadata.end()) << name;
        EXPECT_EQ(match->second, value) << name;
    }
}

}  // namespace collidescope::testing
