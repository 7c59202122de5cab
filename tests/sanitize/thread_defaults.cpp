// Built-in options and suppressions of the thread-sanitizer build, compiled into every
// executable (tests/sanitize/sanitize.cmake), so that ctest and the app need no environment.
// TSAN_OPTIONS given at run time still adds to or overrides them. docs/sanitizers.md explains
// each suppression; there is one per mechanism TSan cannot see, none for our own code.

extern "C" {

__attribute__((visibility("default"))) const char* __tsan_default_options() {
    return "second_deadlock_stack=1";
}

__attribute__((visibility("default"))) const char* __tsan_default_suppressions() {
    return
        // TBB's wait_context: the thread that finishes the last task decrements the counter
        // (instrumented header code) after its ITT "releasing" notification; the waiting
        // thread sees zero through an acquire load inside uninstrumented libtbb and may then
        // reuse the memory (the next loop's wait_context on the same stack slot). The
        // ordering is real but invisible; the frame only ever touches that counter.
        "race:tbb::detail::d1::wait_context::add_reference\n";
}

}  // extern "C"
