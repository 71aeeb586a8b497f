# Warnings are errors on our own code; third-party headers come in as SYSTEM and are not checked.
# The option comes first: a generator expression reads the variable when the line is processed.
option(FXLAB_WERROR "Treat warnings in fxlab's own code as errors" ON)
add_library(fx_warnings INTERFACE)
# Per compiler: GCC and clang (Linux, mingw-w64) take the same flags; MSVC its own (untested here), with
# /utf-8 so the Japanese in the sources is read as it is written.
if(MSVC)
  target_compile_options(fx_warnings INTERFACE /W4 /permissive- /utf-8 /Zc:__cplusplus
    $<$<BOOL:${FXLAB_WERROR}>:/WX>)
else()
  target_compile_options(fx_warnings INTERFACE
    -Wall -Wextra -Wpedantic -Wshadow -Wnon-virtual-dtor -Wcast-align -Wunused
    -Woverloaded-virtual -Wnull-dereference -Wimplicit-fallthrough
    $<$<BOOL:${FXLAB_WERROR}>:-Werror>)
endif()
