#pragma once
// The depth-of-field passes' uniform locations, from the file their shaders include
// (shaders/effects/dof/dof_bindings.glsl).
namespace fx::glsl {
#include "shaders/effects/dof/dof_bindings.glsl"
}  // namespace fx::glsl
