# The third-party pieces of the Windows cross-build (cmake/windows/mingw-w64-x86_64.cmake), from the
# same Debian packages as the Linux build, under the same target names, so that nothing else in the
# tree knows which build it is:
#  - GLFW and Dear ImGui compiled from Debian's source packages (tools/windows/fetch_sources.sh puts
#    them in FXLAB_WINDOWS_SOURCES, default <build>/sources; the versions the Linux build links);
#  - the header-only GLM, nlohmann-json, stb and tinygltf through a folder of links to their -dev
#    packages' headers (never -I/usr/include, which would bring glibc's headers into a Windows build),
#    with stb's and tinygltf's implementations compiled once (cmake/windows/header_libraries.cpp, as
#    Debian's libstb and libtinygltf do on Linux);
#  - GoogleTest from Debian's /usr/src/googletest.
set(FXLAB_WINDOWS_SOURCES "${CMAKE_BINARY_DIR}/sources" CACHE PATH
    "Where tools/windows/fetch_sources.sh unpacked Debian's glfw3 and imgui source packages")
file(GLOB fx_glfw_source LIST_DIRECTORIES true "${FXLAB_WINDOWS_SOURCES}/glfw3-*")
file(GLOB fx_imgui_source LIST_DIRECTORIES true "${FXLAB_WINDOWS_SOURCES}/imgui-*")
list(FILTER fx_glfw_source EXCLUDE REGEX "\\.(tar\\..*|dsc)$")
list(FILTER fx_imgui_source EXCLUDE REGEX "\\.(tar\\..*|dsc)$")
if(NOT fx_glfw_source OR NOT fx_imgui_source)
  message(FATAL_ERROR "No GLFW or Dear ImGui sources in ${FXLAB_WINDOWS_SOURCES}: run tools/windows/fetch_sources.sh ${FXLAB_WINDOWS_SOURCES} first (./fxlab package windows does)")
endif()

find_package(Threads REQUIRED)
enable_language(RC)  # the manifest every .exe carries (cmake/windows/fxlab.rc, added in common/)

# GLFW, static, without its examples, tests and docs.
set(BUILD_SHARED_LIBS OFF)
set(GLFW_BUILD_EXAMPLES OFF CACHE BOOL "" FORCE)
set(GLFW_BUILD_TESTS OFF CACHE BOOL "" FORCE)
set(GLFW_BUILD_DOCS OFF CACHE BOOL "" FORCE)
set(GLFW_INSTALL OFF CACHE BOOL "" FORCE)
add_subdirectory("${fx_glfw_source}" "${CMAKE_BINARY_DIR}/third_party/glfw" EXCLUDE_FROM_ALL SYSTEM)

# The header-only libraries, one link each in a folder of our own.
set(fx_header_links "${CMAKE_BINARY_DIR}/third_party/include")
file(MAKE_DIRECTORY "${fx_header_links}")
foreach(entry glm nlohmann stb tiny_gltf.h)
  if(NOT EXISTS "/usr/include/${entry}")
    message(FATAL_ERROR "/usr/include/${entry} is missing: install libglm-dev nlohmann-json3-dev libstb-dev libtinygltf-dev")
  endif()
  if(NOT EXISTS "${fx_header_links}/${entry}")
    file(CREATE_LINK "/usr/include/${entry}" "${fx_header_links}/${entry}" SYMBOLIC)
  endif()
endforeach()
add_library(fx_header_libraries INTERFACE)
# tinygltf includes <stb_image.h> without the stb/ folder, as Debian's libstb-dev allows on Linux.
target_include_directories(fx_header_libraries SYSTEM INTERFACE "${fx_header_links}" "${fx_header_links}/stb")
add_library(glm::glm ALIAS fx_header_libraries)
add_library(nlohmann_json::nlohmann_json ALIAS fx_header_libraries)

# stb (image, image write, rect pack, truetype: what libstb gives the Linux build) and tinygltf.
add_library(fx_header_library_code STATIC "${CMAKE_CURRENT_LIST_DIR}/windows/header_libraries.cpp")
target_link_libraries(fx_header_library_code PUBLIC fx_header_libraries)
add_library(PkgConfig::STB ALIAS fx_header_library_code)
add_library(TinyGLTF::TinyGLTF ALIAS fx_header_library_code)

# Dear ImGui with the GLFW and OpenGL 3 backends, compiled as Debian's Makefile does (stb's rect pack
# and truetype from libstb-dev, not ImGui's copies).
add_library(fx_imgui STATIC
  "${fx_imgui_source}/imgui.cpp" "${fx_imgui_source}/imgui_draw.cpp" "${fx_imgui_source}/imgui_tables.cpp"
  "${fx_imgui_source}/imgui_widgets.cpp" "${fx_imgui_source}/imgui_demo.cpp"
  "${fx_imgui_source}/misc/cpp/imgui_stdlib.cpp"
  "${fx_imgui_source}/backends/imgui_impl_glfw.cpp" "${fx_imgui_source}/backends/imgui_impl_opengl3.cpp")
target_compile_definitions(fx_imgui PRIVATE
  IMGUI_DISABLE_STB_RECT_PACK_IMPLEMENTATION "IMGUI_STB_RECT_PACK_FILENAME=<stb/stb_rect_pack.h>"
  IMGUI_DISABLE_STB_TRUETYPE_IMPLEMENTATION "IMGUI_STB_TRUETYPE_FILENAME=<stb/stb_truetype.h>")
# The Linux build includes <imgui.h> and <imgui_impl_glfw.h> (Debian's /usr/include/imgui and its
# backends/): the same two folders here.
target_include_directories(fx_imgui SYSTEM PUBLIC "${fx_imgui_source}" "${fx_imgui_source}/backends")
target_link_libraries(fx_imgui PUBLIC glfw fx_header_library_code)
add_library(PkgConfig::IMGUI ALIAS fx_imgui)

# GoogleTest, for the unit tests run under Wine.
set(gtest_force_shared_crt ON CACHE BOOL "" FORCE)
set(INSTALL_GTEST OFF CACHE BOOL "" FORCE)
set(BUILD_GMOCK OFF CACHE BOOL "" FORCE)
add_subdirectory(/usr/src/googletest "${CMAKE_BINARY_DIR}/third_party/googletest" EXCLUDE_FROM_ALL SYSTEM)
# (its CMakeLists names the targets GTest::gtest and GTest::gtest_main itself)
