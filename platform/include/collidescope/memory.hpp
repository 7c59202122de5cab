#pragma once
/// The process's allocator, tuned for frame loops (docs/explanation/architecture.md, "Memory between
/// frames"). A frame frees and allocates the same large buffers again (a rebuilt tree, its
/// sort keys, the candidates); glibc's malloc gives freed memory at the top of its heap back
/// to the system past a threshold and serves blocks of some megabytes from fresh mappings, so
/// each frame paid its page faults again: on the project's 2-core VM, 70 % of data set D's
/// rebuild time at 2 threads (`bench_embree_cgal_peers --scene D --self off`).

namespace collidescope {

/// Asks the C library's allocator to keep freed memory for reuse: blocks below 32 MiB come
/// from the heap, and the heap is never trimmed, so the process keeps its peak footprint
/// (a process-wide setting: the `collidescope` command and the benchmarks call it first
/// thing; a program embedding the engine may, or not). The engine's own large arrays (trees,
/// build memory, candidate buffers: docs/explanation/architecture.md) are kept too, without the 256 MiB
/// limit they have otherwise. The C library part does nothing on a C library other than
/// glibc. Returns true when glibc's settings were taken.
bool keep_freed_memory();

}  // namespace collidescope
