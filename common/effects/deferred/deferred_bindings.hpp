#pragma once
// The deferred passes' uniform locations and buffer bindings, from the file their shaders include
// (shaders/effects/deferred/deferred_bindings.glsl).
namespace fx::glsl {
#include "shaders/effects/deferred/deferred_bindings.glsl"
}  // namespace fx::glsl
