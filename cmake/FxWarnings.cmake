# Warnings are errors on our own code; third-party headers come in as SYSTEM and are not checked.
# The option comes first: a generator expression reads the variable when the line is processed.
option(FXLAB_WERROR "Treat warnings in fxlab's own code as errors" ON)
add_library(fx_warnings INTERFACE)
target_compile_options(fx_warnings INTERFACE
  -Wall -Wextra -Wpedantic -Wshadow -Wnon-virtual-dtor -Wcast-align -Wunused
  -Woverloaded-virtual -Wnull-dereference -Wimplicit-fallthrough
  $<$<BOOL:${FXLAB_WERROR}>:-Werror>)
