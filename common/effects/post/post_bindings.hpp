#pragma once
// The post passes' uniform locations, from the file their shaders include
// (shaders/effects/post/post_bindings.glsl).
namespace fx::glsl {
#include "shaders/effects/post/post_bindings.glsl"
}  // namespace fx::glsl
