// bvh::RebuildReason's values are the stats' rebuild bits (collidescope/stats.hpp), and the
// hierarchies and the stats spell each reason alike.

#include "bvh/rebuild_policy.hpp"

#include "collidescope/stats.hpp"

#include <gtest/gtest.h>

#include <cstdint>

namespace collidescope {
namespace {

TEST(RebuildReasons, AreTheStatsBitsWithTheSameNames) {
    const bvh::RebuildReason reasons[] = {bvh::RebuildReason::Initial, bvh::RebuildReason::Topology,
                                          bvh::RebuildReason::Thesis, bvh::RebuildReason::Quality};
    std::uint8_t all = 0;
    for (const bvh::RebuildReason reason : reasons) {
        const auto bit = static_cast<std::uint8_t>(reason);
        EXPECT_EQ(bit & (bit - 1), 0) << "not a single bit: " << int(bit);
        EXPECT_EQ(all & bit, 0) << "bit used twice: " << int(bit);
        all = static_cast<std::uint8_t>(all | bit);
        EXPECT_EQ(rebuild_reason_names(bit), bvh::rebuild_reason_name(reason));
    }
    EXPECT_EQ(rebuild_reason_names(all), "initial,topology,thesis,quality");
}

}  // namespace
}  // namespace collidescope
