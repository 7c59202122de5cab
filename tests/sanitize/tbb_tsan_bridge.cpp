// Makes TBB's synchronisation visible to ThreadSanitizer (docs/how-to/sanitizers.md). Linked first
// into every executable of the thread-sanitizer build (COLLIDESCOPE_SANITIZE=thread).
//
// Debian's libtbb is not built with -fsanitize=thread, so TSan cannot see how TBB hands a task
// from the thread that spawns it to the thread that steals it, how a finished task signals the
// thread waiting for it, or how its allocators hand memory freed by one thread to another:
// every parallel_for body would look like a race with the code around the loop, and every
// task object like a race with the one that used its memory before. Instead of suppressing
// those reports (which would also hide real races in our loop bodies), this library tells TSan
// about each hand-over, at the points TBB itself exposes:
//
// 1. TBB reports its synchronisation to Intel's ITT tool API (as used by Intel Inspector): the
//    library notifies sync_releasing when it publishes tasks and sync_acquired when a thief
//    takes them, and the headers, compiled with TBB_USE_PROFILING_TOOLS=2 by this build, add
//    releasing on spawn and on a task's completion and acquired after a wait. libtbb's ITT
//    loader dlopen()s the collector named by INTEL_LIBITTNOTIFY64 and, for the groups named by
//    INTEL_ITTNOTIFY_GROUPS, looks up __itt_sync_* by name. This library is that collector: it
//    forwards releasing to __tsan_release and acquired to __tsan_acquire on the same address.
// 2. TBB's task and cache-aligned allocators recycle memory between threads through atomics
//    TSan cannot see. We interpose their entry points (our definitions come before libtbb's in
//    the lookup order) and, around the real call found with dlsym(RTLD_NEXT), release the block
//    when it is freed and acquire it when it is handed out again, as malloc and free do.
// 3. A wait ends when libtbb sees the wait context's counter reach zero, through an acquire
//    load TSan cannot see; the task that brought it to zero decremented it (an instrumented
//    atomic in the headers) after its ITT "releasing". We interpose the two waits and, after
//    the real one returns, load the counter again with acquire in instrumented code: the
//    ordering libtbb relies on, now visible (without it, the next wait context built on the
//    same stack slot looks like a race with that decrement).
//
// Races in our code, and races between our code and TBB's headers, are still reported.

#include <oneapi/tbb/cache_aligned_allocator.h>
#include <oneapi/tbb/detail/_small_object_pool.h>
#include <oneapi/tbb/detail/_task.h>

#include <sanitizer/tsan_interface.h>

#include <dlfcn.h>

#include <atomic>
#include <cstdint>
#include <cstdio>
#include <cstdlib>

#define BRIDGE_EXPORT __attribute__((visibility("default")))

extern "C" {

// ITT collector entry points (API version 1: the loader fills the sync group by these names).
BRIDGE_EXPORT const char* __itt_api_version() { return "collidescope tbb-tsan bridge 1"; }
BRIDGE_EXPORT void __itt_sync_releasing(void* address) { __tsan_release(address); }
BRIDGE_EXPORT void __itt_sync_acquired(void* address) { __tsan_acquire(address); }
// prepare (about to spin) and cancel (gave up spinning) order nothing.
BRIDGE_EXPORT void __itt_sync_prepare(void*) {}
BRIDGE_EXPORT void __itt_sync_cancel(void*) {}

}  // extern "C"

namespace {

// Before main, and so before TBB's lazy ITT initialisation: name ourselves as the collector,
// for the sync group only. A value already set (e.g. by a user's profiler) is kept.
__attribute__((constructor)) void register_collector() {
    Dl_info self{};
    if (dladdr(reinterpret_cast<void*>(&__itt_sync_releasing), &self) == 0 || self.dli_fname == nullptr) {
        std::fprintf(stderr, "tbb_tsan_bridge: cannot find its own path; TBB stays invisible to TSan\n");
        return;
    }
    setenv("INTEL_LIBITTNOTIFY64", self.dli_fname, 0);
    setenv("INTEL_ITTNOTIFY_GROUPS", "sync", 0);
}

template <typename Function>
Function* next_definition(const char* mangled_name) {
    void* found = dlsym(RTLD_NEXT, mangled_name);
    if (found == nullptr) {
        std::fprintf(stderr, "tbb_tsan_bridge: %s not found after the bridge\n", mangled_name);
        std::abort();
    }
    return reinterpret_cast<Function*>(found);
}

// wait_context keeps its counter private: std::uint64_t m_version_and_traits, then
// std::atomic<std::uint64_t> m_ref_count (oneTBB 2021, _task.h). The asserts stop the build if
// that layout changes.
void acquire_completion(tbb::detail::d1::wait_context& wait) {
    static_assert(sizeof(tbb::detail::d1::wait_context) == 2 * sizeof(std::uint64_t));
    static_assert(sizeof(std::atomic<std::uint64_t>) == sizeof(std::uint64_t));
    auto* counter = reinterpret_cast<std::atomic<std::uint64_t>*>(reinterpret_cast<char*>(&wait) + sizeof(std::uint64_t));
    (void)counter->load(std::memory_order_acquire);
}

}  // namespace

namespace tbb::detail::r1 {

BRIDGE_EXPORT void wait(d1::wait_context& wait_ctx, d1::task_group_context& ctx) {
    using Real = void(d1::wait_context&, d1::task_group_context&);
    static Real* real = next_definition<Real>("_ZN3tbb6detail2r14waitERNS0_2d112wait_contextERNS2_18task_group_contextE");
    real(wait_ctx, ctx);
    acquire_completion(wait_ctx);
}

BRIDGE_EXPORT void execute_and_wait(d1::task& task, d1::task_group_context& task_ctx, d1::wait_context& wait_ctx,
                                    d1::task_group_context& wait_group) {
    using Real = void(d1::task&, d1::task_group_context&, d1::wait_context&, d1::task_group_context&);
    static Real* real = next_definition<Real>(
        "_ZN3tbb6detail2r116execute_and_waitERNS0_2d14taskERNS2_18task_group_contextERNS2_12wait_contextES6_");
    real(task, task_ctx, wait_ctx, wait_group);
    acquire_completion(wait_ctx);
}

using d1::execution_data;
using d1::small_object_pool;

BRIDGE_EXPORT void* allocate(small_object_pool*& pool, std::size_t bytes, const execution_data& ed) {
    using Real = void*(small_object_pool*&, std::size_t, const execution_data&);
    static Real* real = next_definition<Real>("_ZN3tbb6detail2r18allocateERPNS0_2d117small_object_poolEmRKNS2_14execution_dataE");
    void* block = real(pool, bytes, ed);
    __tsan_acquire(block);
    return block;
}

BRIDGE_EXPORT void* allocate(small_object_pool*& pool, std::size_t bytes) {
    using Real = void*(small_object_pool*&, std::size_t);
    static Real* real = next_definition<Real>("_ZN3tbb6detail2r18allocateERPNS0_2d117small_object_poolEm");
    void* block = real(pool, bytes);
    __tsan_acquire(block);
    return block;
}

BRIDGE_EXPORT void deallocate(small_object_pool& pool, void* block, std::size_t bytes, const execution_data& ed) {
    using Real = void(small_object_pool&, void*, std::size_t, const execution_data&);
    static Real* real = next_definition<Real>("_ZN3tbb6detail2r110deallocateERNS0_2d117small_object_poolEPvmRKNS2_14execution_dataE");
    __tsan_release(block);
    real(pool, block, bytes, ed);
}

BRIDGE_EXPORT void deallocate(small_object_pool& pool, void* block, std::size_t bytes) {
    using Real = void(small_object_pool&, void*, std::size_t);
    static Real* real = next_definition<Real>("_ZN3tbb6detail2r110deallocateERNS0_2d117small_object_poolEPvm");
    __tsan_release(block);
    real(pool, block, bytes);
}

BRIDGE_EXPORT void* cache_aligned_allocate(std::size_t bytes) {
    using Real = void*(std::size_t);
    static Real* real = next_definition<Real>("_ZN3tbb6detail2r122cache_aligned_allocateEm");
    void* block = real(bytes);
    __tsan_acquire(block);
    return block;
}

BRIDGE_EXPORT void cache_aligned_deallocate(void* block) {
    using Real = void(void*);
    static Real* real = next_definition<Real>("_ZN3tbb6detail2r124cache_aligned_deallocateEPv");
    __tsan_release(block);
    real(block);
}

}  // namespace tbb::detail::r1
