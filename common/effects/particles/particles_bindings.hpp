#pragma once
// The particle programs' uniform locations and buffer bindings, from the file their shaders include
// (shaders/effects/particles/particles_bindings.glsl).
namespace fx::glsl {
#include "shaders/effects/particles/particles_bindings.glsl"
}  // namespace fx::glsl
