# FXLAB_FUZZ=ON: a build of the parsers' libFuzzer targets only (tests/fuzz/, docs/reliability.md), with
# clang's -fsanitize=fuzzer,address,undefined: every object gets the coverage instrumentation libFuzzer
# steers by and the address and undefined-behaviour checks; only the libraries the targets link are
# built (`cmake --build build-fuzz --target fuzz_targets`). `./fxlab fuzz` configures it in build-fuzz/
# with Debian's clang (and FXLAB_WERROR=OFF: checking clang's warnings is the sanitizer build's job) and
# runs each target for a bounded time.
option(FXLAB_FUZZ "Build only the libFuzzer targets of the parsers (clang)" OFF)
if(FXLAB_FUZZ)
  if(NOT CMAKE_CXX_COMPILER_ID STREQUAL "Clang")
    message(FATAL_ERROR "FXLAB_FUZZ needs clang (libFuzzer): configure with -DCMAKE_CXX_COMPILER=clang++ "
                        "-DCMAKE_C_COMPILER=clang, as ./fxlab fuzz does")
  endif()
  add_compile_options(-fsanitize=fuzzer-no-link,address,undefined -fno-sanitize-recover=undefined
                      -fno-omit-frame-pointer -g -O1)
  add_link_options(-fsanitize=address,undefined)
endif()
