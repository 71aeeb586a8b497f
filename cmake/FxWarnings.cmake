# Warnings are errors on our own code; third-party headers come in as SYSTEM and are not checked.
add_library(fx_warnings INTERFACE)
target_compile_options(fx_warnings INTERFACE
  -Wall -Wextra -Wpedantic -Wshadow -Wnon-virtual-dtor -Wcast-align -Wunused
  -Woverloaded-virtual -Wnull-dereference -Wimplicit-fallthrough
  $<$<BOOL:${FXLAB_WERROR}>:-Werror>)
option(FXLAB_WERROR "Treat warnings in fxlab's own code as errors" ON)
