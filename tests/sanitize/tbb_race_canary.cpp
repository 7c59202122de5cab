// The thread-sanitizer build's own check (tests/sanitize/sanitize.cmake): the TBB bridge must
// remove TBB's false reports without hiding real races in loop bodies.
//   tbb_race_canary clean  - a parallel_for and a parallel_reduce over data written before the
//                            loop and read after it: must run without any report;
//   tbb_race_canary race   - the same loop adding into one shared variable without
//                            synchronisation: TSan must report the race in the loop body.

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_reduce.h>

#include <cstdio>
#include <cstring>
#include <functional>
#include <vector>

namespace {

long clean_loops(std::size_t size) {
    std::vector<long> input(size);
    for (std::size_t i = 0; i < size; ++i) input[i] = long(i % 7);  // written before the loop
    std::vector<long> doubled(size);
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, size, 256), [&](const tbb::blocked_range<std::size_t>& range) {
        for (std::size_t i = range.begin(); i != range.end(); ++i) doubled[i] = 2 * input[i];
    });
    const long total = tbb::parallel_reduce(
        tbb::blocked_range<std::size_t>(0, size, 256), 0L,
        [&](const tbb::blocked_range<std::size_t>& range, long sum) {
            for (std::size_t i = range.begin(); i != range.end(); ++i) sum += doubled[i];
            return sum;
        },
        std::plus<long>());
    long check = 0;
    for (const long value : doubled) check += value;  // read after the loop
    return total == check ? total : -1;
}

long racy_loop(std::size_t size) {
    std::vector<long> input(size, 1);
    long sum = 0;
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, size, 256), [&](const tbb::blocked_range<std::size_t>& range) {
        for (std::size_t i = range.begin(); i != range.end(); ++i) sum += input[i];  // the planted race
    });
    return sum;
}

}  // namespace

int main(int argc, char** argv) {
    if (argc != 2 || (std::strcmp(argv[1], "clean") != 0 && std::strcmp(argv[1], "race") != 0)) {
        std::fprintf(stderr, "usage: tbb_race_canary clean|race\n");
        return 2;
    }
    const bool race = std::strcmp(argv[1], "race") == 0;
    long result = 0;
    for (int round = 0; round < 20; ++round) result = race ? racy_loop(100000) : clean_loops(100000);
    std::printf("%s: %ld\n", argv[1], result);
    return result < 0 ? 1 : 0;
}
