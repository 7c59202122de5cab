#pragma once
// A command-line option whose value is one of an engine option's names
// (collidescope/option_names.hpp): the names, the check and the help's default come from the
// option's one table.

#include "collidescope/option_names.hpp"

#include <CLI/CLI.hpp>

#include <string>

namespace collidescope::app {

/// Adds `flag` to `command`: it accepts exactly `table`'s names and sets `value` (which must
/// outlive parsing) to the named enumerator; the help shows `value`'s name as the default.
template <class Enum, std::size_t N>
CLI::Option* add_named_option(CLI::App& command, const std::string& flag, Enum& value,
                              const OptionNames<Enum, N>& table, const std::string& help) {
    return command
        .add_option_function<std::string>(
            flag, [&value, &table](const std::string& name) { value = *option_value(table, name); }, help)
        ->check(CLI::IsMember(option_names(table)))
        ->default_str(std::string(option_name(table, value)));
}

}  // namespace collidescope::app
