// The sanitizer build's defaults (RADCACHE_SANITIZE, docs/reliability.md), compiled into radcache,
// the tests and the fuzz targets so that every run of them gets them whatever its environment
// ($ASAN_OPTIONS and $UBSAN_OPTIONS still override). Unused outside the sanitizer build.
//
// No leak is suppressed: the whole test suite, PoCL's JIT-compiled kernels included, runs clean
// under LeakSanitizer.
extern "C" {

const char* __asan_default_options() {
    // A failed allocation throws std::bad_alloc, as without the sanitizer (radcache then reports
    // "out of host memory"), instead of aborting.
    return "detect_leaks=1:allocator_may_return_null=1";
}

const char* __ubsan_default_options() { return "print_stacktrace=1:halt_on_error=1"; }
}
