// LD_PRELOAD library for the crash tests: the process raises SIGKILL on itself at its
// KILL_AT-th write to a file descriptor above 2 (pwrite, pwrite64 or write), before that write
// happens. The first KILL_AT - 1 writes are in the page cache, as after a real SIGKILL, and
// none after; so a sweep over KILL_AT leaves every state the file can be left in.
// KILL_COUNT_OUT=FILE: at exit, write the number of writes counted to FILE (0 = never kill).

#include <dlfcn.h>
#include <signal.h>
#include <sys/types.h>

#include <atomic>
#include <cstdio>
#include <cstdlib>

namespace {

std::atomic<long> g_writes{0};

long kill_at() {
    static const long at = [] {
        const char* text = std::getenv("KILL_AT");
        return text != nullptr ? std::atol(text) : 0L;
    }();
    return at;
}

void count_write(int fd) {
    if (fd <= 2) return;
    const long k = g_writes.fetch_add(1) + 1;
    if (kill_at() > 0 && k == kill_at()) raise(SIGKILL);
}

template <class Function>
Function next(const char* name) {
    return reinterpret_cast<Function>(dlsym(RTLD_NEXT, name));
}

struct ReportAtExit {
    ~ReportAtExit() {
        const char* path = std::getenv("KILL_COUNT_OUT");
        if (path == nullptr) return;
        if (std::FILE* out = std::fopen(path, "w")) {
            std::fprintf(out, "%ld\n", g_writes.load());
            std::fclose(out);
        }
    }
} g_report;

}  // namespace

extern "C" {

ssize_t pwrite(int fd, const void* buffer, size_t count, off_t offset) {
    using Pwrite = ssize_t (*)(int, const void*, size_t, off_t);
    static const Pwrite real = next<Pwrite>("pwrite");
    count_write(fd);
    return real(fd, buffer, count, offset);
}

ssize_t pwrite64(int fd, const void* buffer, size_t count, off_t offset) {
    using Pwrite = ssize_t (*)(int, const void*, size_t, off_t);
    static const Pwrite real = next<Pwrite>("pwrite64");
    count_write(fd);
    return real(fd, buffer, count, offset);
}

ssize_t write(int fd, const void* buffer, size_t count) {
    using Write = ssize_t (*)(int, const void*, size_t);
    static const Write real = next<Write>("write");
    count_write(fd);
    return real(fd, buffer, count);
}

}  // extern "C"
