// Built-in options of the address + undefined-behaviour sanitizer build, compiled into every
// executable (tests/sanitize/sanitize.cmake), so that ctest and the app need no environment.
// ASAN_OPTIONS, UBSAN_OPTIONS and LSAN_OPTIONS given at run time still override them.
// docs/how-to/sanitizers.md explains each choice.

extern "C" {

// Every runtime exits 86 on a finding (exitcode; LSan shares ASan's): not 1, which the app
// uses for "collisions found" and `validate` for "invalid", so a test that accepts 1 from a
// child could pass over a memory error (tests/support/sanitizer_report.hpp reads the child's
// stderr too). Leaks are findings (the default on Linux; said here so it stays so). Use-after-return is
// checked too (our code hands spans over caller memory to worker threads), and so is the order
// of dynamic initialisation across files (strict_init_order implies check_initialization_order).
//
// intercept_tls_get_addr=0: GCC 12's runtime (up to GCC 13 and LLVM 16) takes a dynamic TLS
// block for one with a pre-2.25 glibc header whenever its start lies sizeof(that header) past a
// page boundary, and reads the two words before it as an address and a length; a malloc'd
// block lands there by chance, and LeakSanitizer's tracer then dies at exit ("Tracer caught
// signal 11", exit 1) after the test passed. OSMesa's llvmpipe (opened with dlopen, TLS of its
// own) met it in 4 of about 40 GPU processes of the cold CI run of 2026-11-27, never on the
// developer's machine. Without the interceptor LSan does not scan dynamic TLS blocks; what
// OSMesa keeps there is its own (suppressed below), and our code's TLS is static.
__attribute__((visibility("default"))) const char* __asan_default_options() {
    return "exitcode=86:detect_leaks=1:detect_stack_use_after_return=1:strict_init_order=1:"
           "intercept_tls_get_addr=0";
}

// -fno-sanitize-recover=all already stops at the first finding; this names where it came from.
__attribute__((visibility("default"))) const char* __ubsan_default_options() {
    return "exitcode=86:print_stacktrace=1";
}

// Two suppressions. One for Mesa's OSMesa (docs/how-to/sanitizers.md): it keeps a process-wide state
// tracker manager (one 16-byte root) and the framebuffers OSMesaMakeCurrent creates for each
// context (about 160 bytes per context) without ever freeing them, although we destroy every
// context (platform/src/gl_context_osmesa.cpp, RAII). Mesa has no frame pointers, so the leak's
// stack ends inside libOSMesa and the library is the narrowest handle LSan offers. A context
// wrapper we forgot to destroy is still reported: its own allocation is ours.
//
// And one for libhdf5 1.10.8, found by the recording fuzz target (docs/how-to/fuzzing.md): when an object
// header fails its checksum, HDF5 loses the metadata cache block it allocated for it (about
// 200 bytes, under H5C_protect), memory it never hands to us. The regression input
// (tests/fuzz/regressions/recording/hdf5-header-leak.h5.gz) runs in the suite. libhdf5 has no
// frame pointers either, so the library is again the narrowest handle; an HDF5 id we forgot
// to close stays reachable from HDF5's id tables and was never reported as a leak anyway.
__attribute__((visibility("default"))) const char* __lsan_default_suppressions() {
    return "leak:libOSMesa.so\n"
           "leak:libhdf5\n"
           // assimp 5.2 (Debian) loses two objects (1,320 and 1,144 bytes, allocated inside
           // libassimp) when its STL loader throws on a malformed file; we hold only an
           // Assimp::Importer, destroyed normally (ErrorTable "other formats (assimp)").
           "leak:libassimp\n";
}

// Quiet about the suppression when it matched: the end-to-end tests read the app's stderr.
__attribute__((visibility("default"))) const char* __lsan_default_options() {
    return "exitcode=86:print_suppressions=0:intercept_tls_get_addr=0";
}

}  // extern "C"
