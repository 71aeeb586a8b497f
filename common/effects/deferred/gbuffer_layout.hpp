#pragma once
// What a G-buffer holds and in which formats (the Deferred rendering chapter's G-buffer, and what the
// best engines store instead: docs/chapters.md). Every layout has albedo (RGBA8, alpha 1 where a
// surface is) and depth (Depth32F); they differ in the normal and in whether the world position has a
// target of its own:
//
//   compact    normal octahedral in RG16F; position rebuilt from depth         12 bytes a pixel
//   fat        normal RGBA16F, world position RGBA16F (the common fat one)     24 bytes a pixel
//   fat32      normal RGBA32F, world position RGBA32F: the reference           40 bytes a pixel
//   rgba8Raw   normal in RGBA8 without the n*0.5+0.5 remap, position RGBA16F  (the classic bug:
//              every negative component is stored as 0)                        20 bytes a pixel
//
// The octahedral functions are here in C++ too (the shader's are shaders/effects/deferred/octahedral.glsl),
// so tests can encode a normal on the CPU and compare it with what the G-buffer stored.
#include <optional>
#include <string>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "base/texture_format.hpp"

namespace fx {

enum class GBufferLayout { compact = 0, fat = 1, fat32 = 2, rgba8Raw = 3 };

struct GBufferFormats {
    TextureFormat albedo = TextureFormat::RGBA8;
    TextureFormat normal = TextureFormat::RG16F;
    std::optional<TextureFormat> position;  // none: rebuilt from depth
    TextureFormat depth = TextureFormat::Depth32F;
};

GBufferFormats gbufferFormats(GBufferLayout layout);
// Bytes one pixel of the G-buffer takes: every target's texel, depth included.
int gbufferBytesPerPixel(GBufferLayout layout);
// "compact", "fat", "fat32", "rgba8Raw": the parameter's choices.
const char* toString(GBufferLayout layout);
std::vector<std::string> gbufferLayoutNames();

// The value stored for a normal of zero length (outside [-1, 1]^2; decodes to the zero vector).
inline constexpr float kNoNormalCode = 2.0f;
glm::vec2 octahedralEncode(glm::vec3 n);
glm::vec3 octahedralDecode(glm::vec2 e);

// The spacing of representable values near `x` in a half float (fp16 has 10 mantissa bits): 2^(floor(log2
// |x|) - 10) for normal numbers. A world position 1000 m from the origin is stored to 0.5 m.
float halfFloatSpacing(float x);

}  // namespace fx
