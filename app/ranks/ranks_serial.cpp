// A build without MPI (Open MPI's packages were not found): every run is serial (ranks.hpp).

#include "ranks/ranks.hpp"

namespace collidescope::app::ranks {

Launch::Launch(int&, char**&) {}
Launch::~Launch() = default;
int Launch::finish(int code) { return code; }
bool parallel() { return false; }
bool leader() { return true; }
void when_done(std::function<int()>) {}
void summary_line(std::vector<double>, std::function<std::string(const std::vector<double>&)>, bool) {}
FrameRange block(FrameRange range) { return range; }
std::string text_output(const std::string& target) { return target; }
std::string recording_output(const std::string& target, RecordingJoin) { return target; }
std::uint32_t at_frame(std::uint32_t frame) { return frame; }
std::string error_prefix() { return ""; }

}  // namespace collidescope::app::ranks
