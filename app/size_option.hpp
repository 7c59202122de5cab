#pragma once
// Sizes on the command line (`--budget 100M`) and in messages ("1.2 MiB").

#include <cstdint>
#include <string>

namespace collidescope::app {

/// Parses "123", "64K", "100M", "2G" (K/M/G = powers of 1024, an optional trailing "B" or
/// "iB"). Throws InputError naming `option` on bad syntax or zero.
std::uint64_t parse_size(const std::string& text, const std::string& option);

/// "812 B", "12.3 KiB", "4.5 MiB", "1.2 GiB".
std::string format_size(std::uint64_t bytes);

}  // namespace collidescope::app
