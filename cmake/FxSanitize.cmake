# FXLAB_SANITIZE=ON builds everything with AddressSanitizer and UndefinedBehaviorSanitizer: a read past a
# buffer, a use after free, a leak or undefined behaviour (signed overflow, a misaligned load, a bad
# shift) stops the test that caused it with a report. `./fxlab test --sanitize` configures such a build
# in build-sanitize/ with clang (the normal build is GCC's, so CI compiles the code with both compilers,
# warnings as errors in each) and runs the unit, gl and smoke tests with tests/sanitize/lsan.supp.
#
# -O1 and no -g: a report still names the functions of its stack (from the frame pointers and the
# symbol table), and the build is about twice as fast. Chasing a report to its line wants -g: configure
# build-sanitize/ again with CMAKE_CXX_FLAGS=-g.
option(FXLAB_SANITIZE "Build with AddressSanitizer and UndefinedBehaviorSanitizer" OFF)
if(FXLAB_SANITIZE)
  set(fx_sanitize_flags -fsanitize=address,undefined -fno-sanitize-recover=undefined -fno-omit-frame-pointer)
  # GCC's -Wmaybe-uninitialized reports false positives inside libstdc++'s <regex> once the sanitizers
  # instrument it (a known GCC problem); the normal build keeps the warning, so nothing goes unchecked.
  add_compile_options(${fx_sanitize_flags} -O1 $<$<CXX_COMPILER_ID:GNU>:-Wno-maybe-uninitialized>)
  add_link_options(${fx_sanitize_flags})
endif()
