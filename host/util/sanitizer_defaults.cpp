// The sanitizer build's defaults (RADCACHE_SANITIZE, docs/reliability.md), compiled into radcache,
// the tests and the fuzz targets so that every run of them gets them, whatever its environment
// ($ASAN_OPTIONS and $LSAN_OPTIONS still override). Unused outside the sanitizer build.
//
// Leaks are checked in radcache's own code; the suppressed ones are the libraries' own
// process-lifetime allocations, made once and freed by nobody: PoCL's device and its LLVM JIT
// (the compiled kernels), the OpenCL ICD loader's platform list, Embree's and TBB's thread pools,
// OpenImageIO's plugin registry and caches, and the C++ runtime's exception emergency pool.
extern "C" {

const char* __asan_default_options() {
    // PoCL's JIT-compiled kernels run in this process without instrumentation, on their own
    // stacks: container-overflow and stack-use-after-return checks would misfire on them.
    return "detect_leaks=1:detect_stack_use_after_return=0:detect_container_overflow=0:"
           "allocator_may_return_null=1:abort_on_error=0";
}

const char* __lsan_default_suppressions() {
    return "leak:libpocl\n"
           "leak:libLLVM\n"
           "leak:libOpenCL\n"
           "leak:libembree\n"
           "leak:libtbb\n"
           "leak:libOpenImageIO\n"
           "leak:libclang\n";
}

const char* __ubsan_default_options() { return "print_stacktrace=1:halt_on_error=1"; }
}
