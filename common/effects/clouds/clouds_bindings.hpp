#pragma once
// The cloud passes' uniform locations, from the file their shaders include
// (shaders/effects/clouds/clouds_bindings.glsl).
namespace fx::glsl {
#include "shaders/effects/clouds/clouds_bindings.glsl"
}  // namespace fx::glsl
