#pragma once
// The texture formats fxlab uses, and every fact about them, written once: the name printed
// everywhere (reports, the inspector, errors), what the frame graph needs to validate a pass (can it
// be a colour attachment? a depth attachment?), what memory it costs, and how the inspector shows it.
// gl/gl_formats.hpp maps each one to GL's internal format enum; nothing here knows GL.
#include <cstdint>
#include <string_view>

namespace fx {

enum class TextureFormat {
    RGBA8,
    SRGB8_ALPHA8,
    RGBA16F,
    RGBA32F,
    R11F_G11F_B10F,
    RG16F,
    R16F,
    R32F,
    R8,
    RGB32F,  // a valid texture format, but not colour-renderable in core GL: the error case
    Depth32F,
    Depth24,
    Depth24Stencil8,
};

inline constexpr int kTextureFormatCount = static_cast<int>(TextureFormat::Depth24Stencil8) + 1;

struct TextureFormatInfo {
    std::string_view name;  // spelled as in the enum and in GL's internal format ("RGBA16F")
    int bytesPerTexel;      // what one texel costs in memory (Depth24 counts as 4: drivers pad it)
    int channels;           // depth counts as one channel, stencil as another
    bool depth;             // can be a depth attachment
    bool stencil;
    bool floatingPoint;    // stores floats (half, full or packed), not normalised integers
    bool srgb;             // stores sRGB-encoded colour; sampling decodes it to linear light
    bool colorRenderable;  // can be a colour attachment
    bool storage;          // can be bound as an image for load/store (compute)
};

const TextureFormatInfo& formatInfo(TextureFormat format);

inline std::string_view toString(TextureFormat format) {
    return formatInfo(format).name;
}
inline int bytesPerTexel(TextureFormat format) {
    return formatInfo(format).bytesPerTexel;
}
inline int channelCount(TextureFormat format) {
    return formatInfo(format).channels;
}
inline bool isDepth(TextureFormat format) {
    return formatInfo(format).depth;
}
inline bool hasStencil(TextureFormat format) {
    return formatInfo(format).stencil;
}
inline bool isFloat(TextureFormat format) {
    return formatInfo(format).floatingPoint;
}
inline bool isSrgb(TextureFormat format) {
    return formatInfo(format).srgb;
}
// 8-bit unsigned normalised colour channels: a stored value is a whole number of 255ths.
inline bool isUnorm8(TextureFormat format) {
    const TextureFormatInfo& info = formatInfo(format);
    return !info.depth && !info.floatingPoint && info.bytesPerTexel == info.channels;
}
inline bool isColorRenderable(TextureFormat format) {
    return formatInfo(format).colorRenderable;
}
inline bool isStorageCompatible(TextureFormat format) {
    return formatInfo(format).storage;
}

}  // namespace fx
