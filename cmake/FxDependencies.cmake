# Every third-party piece comes from Debian's packages (see ./fxlab setup for the package names).
# The Windows cross-build (cmake/windows/) builds the same pieces from Debian's sources instead.
# Visual Studio takes them from vcpkg (vcpkg.json; untested here).
if(WIN32 AND CMAKE_CROSSCOMPILING)
  include(FxWindowsDependencies)
  return()
elseif(MSVC)
  include(FxVcpkgDependencies)
  return()
endif()
find_package(PkgConfig REQUIRED)
find_package(Threads REQUIRED)
find_package(glfw3 3.3 REQUIRED)
find_package(glm REQUIRED)
find_package(nlohmann_json 3.10 REQUIRED)
find_package(TinyGLTF REQUIRED)
find_package(GTest REQUIRED)
pkg_check_modules(IMGUI REQUIRED IMPORTED_TARGET imgui)
pkg_check_modules(STB REQUIRED IMPORTED_TARGET stb)
# The lesson text's markdown (md4c: CommonMark with GitHub's tables) and its line breaking (ICU's
# line BreakIterator, Unicode's rules with the Japanese ones).
pkg_check_modules(MD4C REQUIRED IMPORTED_TARGET md4c)
pkg_check_modules(ICU REQUIRED IMPORTED_TARGET icu-uc)

# Dear ImGui's Debian build is a static library with the GLFW and OpenGL3 backends inside; its
# headers live in /usr/include/imgui (backends in /usr/include/imgui/backends).
find_path(FX_IMGUI_BACKENDS_DIR imgui_impl_glfw.h PATH_SUFFIXES imgui/backends REQUIRED)
add_library(fx_imgui INTERFACE)
target_link_libraries(fx_imgui INTERFACE PkgConfig::IMGUI glfw ${CMAKE_DL_LIBS})
target_include_directories(fx_imgui SYSTEM INTERFACE ${IMGUI_INCLUDE_DIRS} ${FX_IMGUI_BACKENDS_DIR})
