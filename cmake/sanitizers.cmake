# Instrumented builds (docs/reliability.md), each in its own build directory:
#   RADCACHE_SANITIZE=address,undefined  the host code and tests under AddressSanitizer (with
#                                        LeakSanitizer) and UndefinedBehaviorSanitizer; any report
#                                        fails the test that caused it
#   RADCACHE_FUZZ=ON                     clang's libFuzzer targets (tests/fuzz/), the host code
#                                        instrumented for coverage, ASan and UBSan; no tests
set(RADCACHE_SANITIZE "" CACHE STRING "sanitizers for the host code, e.g. address,undefined")
option(RADCACHE_FUZZ "build the libFuzzer targets of tests/fuzz (clang only)" OFF)

if(RADCACHE_FUZZ)
    if(NOT CMAKE_CXX_COMPILER_ID STREQUAL "Clang")
        message(FATAL_ERROR "RADCACHE_FUZZ needs clang's libFuzzer: configure with "
                            "-DCMAKE_C_COMPILER=clang -DCMAKE_CXX_COMPILER=clang++ (tools/fuzz.sh)")
    endif()
    if(RADCACHE_SANITIZE STREQUAL "")
        set(RADCACHE_SANITIZE "address,undefined")
    endif()
    add_compile_options(-fsanitize=fuzzer-no-link)
endif()

if(NOT RADCACHE_SANITIZE STREQUAL "")
    add_compile_options(-fsanitize=${RADCACHE_SANITIZE} -fno-sanitize-recover=all
                        -fno-omit-frame-pointer -g)
    add_link_options(-fsanitize=${RADCACHE_SANITIZE})
    # GCC's -Wmaybe-uninitialized misfires on instrumented code (std::regex, std::function): its
    # manual says the sanitizers may cause false positives.
    if(CMAKE_CXX_COMPILER_ID STREQUAL "GNU")
        add_compile_options(-Wno-maybe-uninitialized)
    endif()
endif()
