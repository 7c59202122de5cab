#pragma once
// Checks of an enum option's name table (collidescope/option_names.hpp), shared by the tests
// of the engine's tables and the replayer's.

#include "collidescope/option_names.hpp"

#include <gtest/gtest.h>

#include <set>
#include <string>
#include <string_view>

namespace collidescope::testing {

/// Values 0, 1, ... in table order (so the table lists the enumerators as declared, and a
/// recorded number is the enumerator's value), names distinct, non-empty and read back.
template <class Enum, std::size_t N>
void expect_complete_table(const OptionNames<Enum, N>& table) {
    std::set<std::string_view> names;
    for (std::size_t i = 0; i < N; ++i) {
        const OptionName<Enum>& entry = table[i];
        SCOPED_TRACE(std::string(entry.name));
        EXPECT_EQ(static_cast<std::size_t>(entry.value), i);
        EXPECT_FALSE(entry.name.empty());
        EXPECT_TRUE(names.insert(entry.name).second) << "the name appears twice";
        EXPECT_EQ(option_name(table, entry.value), entry.name);
        ASSERT_TRUE(option_value(table, entry.name).has_value());
        EXPECT_EQ(*option_value(table, entry.name), entry.value);
    }
    EXPECT_FALSE(option_value(table, "").has_value());
    EXPECT_FALSE(option_value(table, "no-such-name").has_value());
}

}  // namespace collidescope::testing
