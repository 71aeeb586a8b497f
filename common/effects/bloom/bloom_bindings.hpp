#pragma once
// The bloom passes' uniform locations, from the file their shaders include
// (shaders/effects/bloom/bloom_bindings.glsl).
namespace fx::glsl {
#include "shaders/effects/bloom/bloom_bindings.glsl"
}  // namespace fx::glsl
