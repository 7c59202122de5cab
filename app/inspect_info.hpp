#pragma once
// What `collidescope inspect` reports about a recording (inspect_info.cpp).

#include "collidescope/recorder/reader.hpp"

#include <nlohmann/json.hpp>

namespace collidescope::app {

/// Frames, objects, methods, decisions, pairs, time per stage and file size by group of
/// `rec`, as inspect prints them. Throws InputError when the file cannot be read.
nlohmann::ordered_json inspect_info(const recorder::Recording& rec);

}  // namespace collidescope::app
