#pragma once
// The GL context behind the GPU cull: the platform library's (collidescope/gl_context.hpp), which
// the replayer renders through too.

#include "collidescope/gl_context.hpp"

namespace collidescope::gpucull {

using gl::GlContext;
using gl::make_current_for_cleanup;

/// The cull's context: make_gl_context(backend), its failure reason prefixed with
/// "GPU cull unavailable: " (what `--method gpu` prints before exiting 2).
std::unique_ptr<GlContext> make_cull_context(GlBackend backend);

}  // namespace collidescope::gpucull
