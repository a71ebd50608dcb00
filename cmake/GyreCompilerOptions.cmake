# LLVM's lld links Gyre's test programs (a static gyre_app with its debug information, over 200 MB
# under the sanitizers) in a fifth of the time GNU ld takes: 1.0 s against 4.8 s for tst_timeline.
find_program(GYRE_LLD ld.lld)
if(GYRE_LLD)
    set(GYRE_USE_LLD_DEFAULT ON)
else()
    set(GYRE_USE_LLD_DEFAULT OFF)
endif()
option(GYRE_USE_LLD "Link with LLVM's lld (Debian's lld package)" ${GYRE_USE_LLD_DEFAULT})

# Warnings and sanitizers for every Gyre target: call gyre_target_options(target) on each.
function(gyre_target_options target)
    target_compile_options(${target} PRIVATE
        -Wall -Wextra -Wpedantic -Wshadow -Wnon-virtual-dtor -Woverloaded-virtual
        -Wcast-align -Wdouble-promotion -Wformat=2 -Wimplicit-fallthrough)
    # GCC 12 at -O3 warns falsely about std::string concatenation (GCC bug 105329).
    if(CMAKE_CXX_COMPILER_ID STREQUAL "GNU" AND CMAKE_CXX_COMPILER_VERSION VERSION_LESS 13)
        target_compile_options(${target} PRIVATE -Wno-restrict)
    endif()
    if(GYRE_WERROR)
        target_compile_options(${target} PRIVATE -Werror)
    endif()
    if(GYRE_USE_LLD)
        target_link_options(${target} PRIVATE -fuse-ld=lld)
    endif()
    if(GYRE_SANITIZE)
        target_compile_options(${target} PRIVATE -fsanitize=address,undefined -fno-omit-frame-pointer
                                                 -fno-sanitize-recover=undefined)
        target_link_options(${target} PRIVATE -fsanitize=address,undefined)
        # Under AddressSanitizer Eigen stops trusting malloc's 16-byte alignment and switches to its
        # own offset allocator; Debian's Ceres, built without the sanitizer, frees Eigen storage with
        # plain free(), so both sides must agree. glibc's and ASan's malloc align to 16 bytes.
        target_compile_definitions(${target} PRIVATE EIGEN_MALLOC_ALREADY_ALIGNED=1)
    endif()
    # Coverage feedback for libFuzzer in all code; only the harnesses link its runtime and main().
    if(GYRE_FUZZ)
        target_compile_options(${target} PRIVATE -fsanitize=fuzzer-no-link)
    endif()
endfunction()
