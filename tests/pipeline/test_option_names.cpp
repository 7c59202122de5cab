// Every enum option's name table (collidescope/option_names.hpp): each enumerator once, in
// declaration order, with a distinct name that reads back to it; and the stats spell the
// recorded policy number through the table.

#include "support/option_tables.hpp"

#include "collidescope/aabb_options.hpp"
#include "collidescope/adaptive_options.hpp"
#include "collidescope/gl_backend.hpp"
#include "collidescope/gpu_cull.hpp"
#include "collidescope/stats.hpp"
#include "collidescope/stats_json.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace collidescope {
namespace {

using testing::expect_complete_table;

TEST(OptionNames, EveryTableIsComplete) {
    expect_complete_table(k_aabb_builder_names);
    expect_complete_table(k_aabb_rebuild_rule_names);
    expect_complete_table(k_aabb_background_names);
    expect_complete_table(k_adaptive_policy_names);
    expect_complete_table(k_gpu_cull_variant_names);
    expect_complete_table(k_gl_backend_names);
}

TEST(OptionNames, NamesAsTheCommandLineSpellsThem) {
    EXPECT_EQ(option_name_list(k_aabb_builder_names), "lbvh or sah");
    EXPECT_EQ(option_name_list(k_aabb_rebuild_rule_names), "quality, thesis or never");
    EXPECT_EQ(option_name_list(k_aabb_background_names), "auto, on or off");
    EXPECT_EQ(option_name_list(k_adaptive_policy_names), "thesis or cost");
    EXPECT_EQ(option_name_list(k_gpu_cull_variant_names), "queries or flags");
    EXPECT_EQ(option_name_list(k_gl_backend_names), "auto, osmesa or egl");
    EXPECT_EQ(option_names(k_gl_backend_names), (std::vector<std::string>{"auto", "osmesa", "egl"}));
}

TEST(OptionNames, StatsSpellTheRecordedPolicyThroughTheTable) {
    for (const OptionName<AdaptivePolicy>& entry : k_adaptive_policy_names) {
        FrameStats stats;
        stats.decision = DecisionInfo{};
        stats.decision->policy = static_cast<std::uint8_t>(entry.value);
        const nlohmann::json json = nlohmann::json::parse(stats_json(stats));
        EXPECT_EQ(json.at("decision").at("policy"), std::string(entry.name));
    }
}

}  // namespace
}  // namespace collidescope
