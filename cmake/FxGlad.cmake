# glad's loader is generated at configure time from the Khronos XML that python3-glad carries
# (--reproducible: nothing is fetched). GL 4.5 core with KHR_debug, and EGL 1.5 with the platform
# extensions the headless context needs. Nothing generated is committed.
find_program(GLAD_EXECUTABLE glad REQUIRED)

set(FX_GLAD_DIR "${CMAKE_BINARY_DIR}/glad")
set(FX_GLAD_ARGS
  --api "gl:core=4.5,egl=1.5"
  --extensions "GL_KHR_debug,EGL_EXT_platform_base,EGL_EXT_platform_device,EGL_MESA_platform_surfaceless,EGL_EXT_device_base,EGL_EXT_device_enumeration,EGL_EXT_device_query,EGL_KHR_surfaceless_context,EGL_KHR_create_context"
  --out-path "${FX_GLAD_DIR}" --reproducible --quiet
  c --loader)
string(SHA1 FX_GLAD_STAMP "${FX_GLAD_ARGS}")
if(NOT EXISTS "${FX_GLAD_DIR}/src/gl.c" OR NOT "${FX_GLAD_STAMP}" STREQUAL "${FX_GLAD_LAST_STAMP}")
  message(STATUS "Generating the glad loader into ${FX_GLAD_DIR}")
  execute_process(COMMAND "${GLAD_EXECUTABLE}" ${FX_GLAD_ARGS}
                  RESULT_VARIABLE glad_result OUTPUT_VARIABLE glad_out ERROR_VARIABLE glad_out)
  if(NOT glad_result EQUAL 0)
    message(FATAL_ERROR "glad failed (${glad_result}):\n${glad_out}")
  endif()
  set(FX_GLAD_LAST_STAMP "${FX_GLAD_STAMP}" CACHE INTERNAL "arguments of the last glad run")
endif()

# Windows has no EGL (its headless context is a hidden window): GL's loader only.
if(WIN32)
  add_library(fx_glad STATIC "${FX_GLAD_DIR}/src/gl.c")
else()
  add_library(fx_glad STATIC "${FX_GLAD_DIR}/src/gl.c" "${FX_GLAD_DIR}/src/egl.c")
endif()
target_include_directories(fx_glad SYSTEM PUBLIC "${FX_GLAD_DIR}/include")
target_link_libraries(fx_glad PUBLIC ${CMAKE_DL_LIBS})
set_target_properties(fx_glad PROPERTIES POSITION_INDEPENDENT_CODE ON)
