#pragma once
/// Name tables of the engine's enum options (aabb_options.hpp, adaptive_options.hpp,
/// gpu_cull.hpp, gl_backend.hpp): each option's names are written once, in its table, and the
/// command line, the embedding API, the stats and the replayer's overlay all read them there.

#include <array>
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace collidescope {

/// One name of an enum option and the value it stands for.
template <class Enum>
struct OptionName {
    std::string_view name;
    Enum value;
};

/// An option's table: every enumerator once, in declaration order (tests/pipeline checks each).
template <class Enum, std::size_t N>
using OptionNames = std::array<OptionName<Enum>, N>;

/// The name of `value` in `table`; empty when the table lacks it (the tests make sure none does).
template <class Enum, std::size_t N>
constexpr std::string_view option_name(const OptionNames<Enum, N>& table, Enum value) {
    for (const OptionName<Enum>& entry : table) {
        if (entry.value == value) return entry.name;
    }
    return {};
}

/// The value named `name` in `table`, or nothing.
template <class Enum, std::size_t N>
constexpr std::optional<Enum> option_value(const OptionNames<Enum, N>& table, std::string_view name) {
    for (const OptionName<Enum>& entry : table) {
        if (entry.name == name) return entry.value;
    }
    return std::nullopt;
}

/// The names in table order (what a command-line option accepts).
template <class Enum, std::size_t N>
std::vector<std::string> option_names(const OptionNames<Enum, N>& table) {
    std::vector<std::string> names;
    for (const OptionName<Enum>& entry : table) names.emplace_back(entry.name);
    return names;
}

/// The names for a message: "a, b or c".
template <class Enum, std::size_t N>
std::string option_name_list(const OptionNames<Enum, N>& table) {
    std::string list;
    for (std::size_t i = 0; i < N; ++i) {
        if (i > 0) list += i + 1 == N ? " or " : ", ";
        list += table[i].name;
    }
    return list;
}

}  // namespace collidescope
