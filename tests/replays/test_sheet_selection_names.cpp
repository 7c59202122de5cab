// --sheet-frames' names (k_sheet_selection_names): each selection once, in declaration order.

#include "support/option_tables.hpp"

#include "collidescope/replays/options.hpp"

#include <gtest/gtest.h>

namespace collidescope::replays {
namespace {

TEST(SheetSelectionNames, TableIsComplete) {
    testing::expect_complete_table(k_sheet_selection_names);
    EXPECT_EQ(option_name_list(k_sheet_selection_names), "every, collisions or slowest");
}

}  // namespace
}  // namespace collidescope::replays
