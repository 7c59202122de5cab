// A child with a planted memory error, for tests/harness/test_sanitizer_report.cpp: the proof
// that a sanitizer report in a child the tests run fails the test that met it, whatever the
// child's exit code.
//   memory_error_canary clean          - exits 0, says nothing on stderr
//   memory_error_canary oob-read       - reads one int past a heap array, then exits 1 (the
//                                        app's "collisions found"): in the address build ASan
//                                        stops it first with its report and exit code 86
//   memory_error_canary signed-overflow - overflows an int, then exits 1 (UBSan: 86)
//   memory_error_canary leak           - loses a heap block, then exits 1 (LSan at exit: 86)
//   memory_error_canary printed-report - prints the opening and closing lines of an ASan
//                                        report (as the address build would) and exits 1: the
//                                        runner's check of stderr, seen in any build

#include <cstdio>
#include <cstring>
#include <memory>

namespace {

// Out of line and through a volatile index, so the compiler can neither fold nor drop the read.
__attribute__((noinline)) int read_at(const int* values, int index) {
    volatile int at = index;
    return values[at];
}

}  // namespace

int main(int argc, char** argv) {
    if (argc == 2 && std::strcmp(argv[1], "clean") == 0) return 0;
    if (argc == 2 && std::strcmp(argv[1], "oob-read") == 0) {
        const auto values = std::make_unique<int[]>(4);
        std::printf("%d\n", read_at(values.get(), 4));
        return 1;
    }
    if (argc == 2 && std::strcmp(argv[1], "signed-overflow") == 0) {
        volatile int large = 2147483647;
        std::printf("%d\n", large + 1);
        return 1;
    }
    if (argc == 2 && std::strcmp(argv[1], "leak") == 0) {
        volatile int* lost = new int[64];
        lost[0] = 1;
        lost = nullptr;
        return 1;
    }
    if (argc == 2 && std::strcmp(argv[1], "printed-report") == 0) {
        std::fprintf(stderr,
                     "==4242==ERROR: AddressSanitizer: heap-buffer-overflow on address 0x602000000020 at pc "
                     "0x55d0c0de bp 0x7ffc sp 0x7ffc\nREAD of size 4 at 0x602000000020 thread T0\n"
                     "SUMMARY: AddressSanitizer: heap-buffer-overflow memory_error_canary.cpp:19 in read_at\n");
        return 1;
    }
    std::fprintf(stderr, "usage: memory_error_canary clean|oob-read|signed-overflow|leak|printed-report\n");
    return 2;
}
