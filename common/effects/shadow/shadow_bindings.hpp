#pragma once
// The shadow passes' own uniform locations, from the file their shaders include
// (shaders/effects/shadow/shadow_bindings.glsl).
namespace fx::glsl {
#include "shaders/effects/shadow/shadow_bindings.glsl"
}  // namespace fx::glsl
