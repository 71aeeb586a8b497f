# The third-party pieces for Visual Studio 2022 through vcpkg's manifest (vcpkg.json, preset
# windows-msvc), under the target names the rest of the tree uses. UNTESTED: no MSVC runs here
# (docs/windows.md); the mingw-w64 build (FxWindowsDependencies.cmake) is the tested Windows one.
find_package(Threads REQUIRED)
find_package(glfw3 CONFIG REQUIRED)
find_package(glm CONFIG REQUIRED)
find_package(nlohmann_json CONFIG REQUIRED)
find_package(imgui CONFIG REQUIRED)
find_package(GTest CONFIG REQUIRED)
find_path(FX_STB_DIR stb_image.h REQUIRED)
find_path(FX_TINYGLTF_DIR tiny_gltf.h REQUIRED)
enable_language(RC)

# fxlab includes <stb/stb_image.h> (Debian's layout); vcpkg puts stb's headers at the top. A folder of
# one-line headers of our own bridges the two.
set(fx_stb_bridge "${CMAKE_BINARY_DIR}/third_party/include/stb")
foreach(header stb_image.h stb_image_write.h stb_rect_pack.h stb_truetype.h stb_easy_font.h)
  file(CONFIGURE OUTPUT "${fx_stb_bridge}/${header}" CONTENT "#pragma once\n#include <${header}>\n")
endforeach()
add_library(fx_header_libraries INTERFACE)
target_include_directories(fx_header_libraries SYSTEM INTERFACE "${CMAKE_BINARY_DIR}/third_party/include"
                           "${FX_STB_DIR}" "${FX_TINYGLTF_DIR}")
target_link_libraries(fx_header_libraries INTERFACE nlohmann_json::nlohmann_json)
add_library(fx_header_library_code STATIC "${CMAKE_CURRENT_LIST_DIR}/windows/header_libraries.cpp")
target_link_libraries(fx_header_library_code PUBLIC fx_header_libraries)
add_library(PkgConfig::STB ALIAS fx_header_library_code)
add_library(TinyGLTF::TinyGLTF ALIAS fx_header_library_code)

add_library(fx_imgui INTERFACE)
target_link_libraries(fx_imgui INTERFACE imgui::imgui glfw)
add_library(PkgConfig::IMGUI ALIAS fx_imgui)
