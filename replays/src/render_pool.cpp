// Render threads, each with its own GL context.

#include "render_pool.hpp"

#include "collidescope/error.hpp"

#include <algorithm>
#include <atomic>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

namespace collidescope::replays {

RenderThread make_render_thread(GlBackend gl, int width, int height, float font_size) {
    RenderThread thread;
    try {
        thread.context = gl::make_gl_context(gl);
    } catch (const UnavailableError& error) {
        throw UnavailableError(std::string("replay: no offscreen GL context (") + error.what() + ")");
    }
    thread.renderer = std::make_unique<MeshRenderer>(width, height);
    thread.overlay = std::make_unique<Overlay>(width, height, font_size);
    return thread;
}

int render_threads(int threads, std::uint64_t count) {
    const int wanted = threads > 0 ? threads : int(std::max(1u, std::thread::hardware_concurrency()));
    return int(std::clamp<std::uint64_t>(std::uint64_t(wanted), 1, std::max<std::uint64_t>(count, 1)));
}

std::string run_parallel(GlBackend gl, int threads, std::uint64_t count, int width, int height,
                         const std::function<void(RenderThread&, std::uint64_t)>& job) {
    std::atomic<std::uint64_t> next{0};
    std::atomic<bool> failed{false};
    std::exception_ptr first_error;
    std::mutex error_lock;
    std::string renderer;
    auto work = [&] {
        try {
            RenderThread thread = make_render_thread(gl, width, height);
            {
                const std::lock_guard<std::mutex> guard(error_lock);
                renderer = thread.context->renderer();
            }
            for (std::uint64_t i = next++; i < count && !failed; i = next++) job(thread, i);
        } catch (...) {
            const std::lock_guard<std::mutex> guard(error_lock);
            if (!first_error) first_error = std::current_exception();
            failed = true;
        }
    };
    const int n = render_threads(threads, count);
    std::vector<std::thread> pool;
    for (int t = 1; t < n; ++t) pool.emplace_back(work);
    work();
    for (std::thread& thread : pool) thread.join();
    if (first_error) std::rethrow_exception(first_error);
    return renderer;
}

}  // namespace collidescope::replays
