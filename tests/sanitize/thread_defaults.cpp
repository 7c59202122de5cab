// Built-in options and suppressions of the thread-sanitizer build, compiled into every
// executable (tests/sanitize/sanitize.cmake), so that ctest and the app need no environment.
// TSAN_OPTIONS given at run time still adds to or overrides them. docs/how-to/sanitizers.md explains
// each suppression (Mesa's llvmpipe, and libtbb's own libc calls); TBB's synchronisation
// needs none (the bridge, tbb_tsan_bridge.cpp, makes it visible), and none names our own code.

extern "C" {

__attribute__((visibility("default"))) const char* __tsan_default_options() {
    // 86, as in the address build (address_defaults.cpp), not TSan's own 66.
    return "exitcode=86:second_deadlock_stack=1";
}

__attribute__((visibility("default"))) const char* __tsan_default_suppressions() {
    return
        // Mesa's llvmpipe (inside libOSMesa) runs its own rasteriser threads and orders them
        // with futexes and atomics in uninstrumented code; only the pthread and libc calls it
        // makes are intercepted, so TSan saw them as races among themselves (a mutex destroyed
        // by the GL thread "racing" its lock on a rasteriser thread, every frame of the GPU
        // methods). called_from_lib makes TSan ignore the interceptors Mesa calls; Mesa's own
        // memory accesses were never checked, and our code's accesses still are.
        "called_from_lib:libOSMesa.so\n"
        // The EGL backend (--gl egl) runs the same llvmpipe from Mesa's DRI driver
        // (swrast_dri.so and its hard links, dlopened by libEGL_mesa): same reason. Added with
        // the EGL backend by analogy; no TSan run has exercised it yet (docs/how-to/sanitizers.md).
        "called_from_lib:_dri.so\n"
        // LLVM, which llvmpipe uses to compile its shaders, is uninstrumented too, and its
        // object loader holds more than 64 mutexes at once: TSan's deadlock detector stops the
        // process with "CHECK failed: sanitizer_deadlock_detector.h:67" (seen in
        // HybridAndAdaptive.RandomScenesWithAndWithoutSelfCollision), and the mutex it takes in
        // DynamicLibrary::getPermanentLibrary on each replay render thread looked like a race
        // between those threads. Same mechanism, same reason.
        "called_from_lib:libLLVM\n"
        // libtbb's own libc calls: an external thread's first parallel algorithm (the
        // background rebuild's worker, a std::async thread, sorting Morton codes in the LBVH
        // build) makes libtbb memcmp one of its global buffers, and at exit a TBB worker
        // frees that buffer with delete[] inside libtbb; both accesses are libtbb's, ordered
        // by its uninstrumented atomics, and TSan saw only the intercepted memcmp and delete[]
        // (about 1 run in 12 of SmallPreset/BuiltinScenes.MatchesBruteOnEveryFrame/4, after the
        // test had passed). libtbb's plain accesses were never checked; the loop bodies and
        // TBB's inline header code stay instrumented, and the bridge still orders them.
        // "libtbb.so" does not match libtbbmalloc.
        "called_from_lib:libtbb.so\n"
        // LLVM's JIT registers each compiled shader's unwind tables with libgcc_s
        // (__register_frame_info_bases), whose object_mutex TSan then saw locked twice and
        // ordered against our overlay's mutex (replay render threads, Replay.* tests); the
        // unlock it pairs with is not seen on the JIT's path. Only that function's mutex
        // reports are suppressed.
        "mutex:__register_frame_info_bases\n"
        "deadlock:__register_frame_info_bases\n";
}

}  // extern "C"
