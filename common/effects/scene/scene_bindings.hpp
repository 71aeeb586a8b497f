#pragma once
// The lit scene shaders' uniform locations and texture and buffer bindings, read from the very file
// the shaders include (shaders/common/scene_bindings.glsl): written once, for GLSL and C++ alike.
// unit.bindings (tests/bindings/check_bindings.py) fails on a location or binding written as a number
// on either side.
namespace fx::glsl {
#include "shaders/common/scene_bindings.glsl"
}  // namespace fx::glsl
