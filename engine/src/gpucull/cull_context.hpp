#pragma once
// The GL context behind the GPU cull: declared in the public header, since the replayer renders
// through the same interface (collidescope/gl_context.hpp).

#include "collidescope/gl_context.hpp"

namespace collidescope::gpucull {

/// The cull's context: make_gl_context(backend), its failure reason prefixed with
/// "GPU cull unavailable: " (what `--method gpu` prints before exiting 2).
std::unique_ptr<GlContext> make_cull_context(GlBackend backend);

/// Makes `context` current before its GL objects are deleted (in a destructor: a failure,
/// which would leave the objects to the context's own destruction, is not thrown).
void make_current_for_cleanup(GlContext& context) noexcept;

}  // namespace collidescope::gpucull
