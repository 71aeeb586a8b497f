#include "base/texture_format.hpp"

#include <array>

namespace fx {
namespace {

// One row per enum value, in enum order (checked by the unit tests).
// clang-format off
constexpr std::array<TextureFormatInfo, kTextureFormatCount> kFormats{{
    //  name               bytes ch  depth  stencil float  srgb   colour storage
    {"RGBA8",              4,    4,  false, false,  false, false, true,  true},
    {"SRGB8_ALPHA8",       4,    4,  false, false,  false, true,  true,  false},  // no sRGB image load/store
    {"RGBA16F",            8,    4,  false, false,  true,  false, true,  true},
    {"RGBA32F",            16,   4,  false, false,  true,  false, true,  true},
    {"R11F_G11F_B10F",     4,    3,  false, false,  true,  false, true,  true},
    {"RG16F",              4,    2,  false, false,  true,  false, true,  true},
    {"R16F",               2,    1,  false, false,  true,  false, true,  true},
    {"R32F",               4,    1,  false, false,  true,  false, true,  true},
    {"R8",                 1,    1,  false, false,  false, false, true,  true},
    {"RGB32F",             12,   3,  false, false,  true,  false, false, false},
    {"Depth32F",           4,    1,  true,  false,  true,  false, false, false},
    {"Depth24",            4,    1,  true,  false,  false, false, false, false},
    {"Depth24Stencil8",    4,    2,  true,  true,   false, false, false, false},
}};
// clang-format on

}  // namespace

const TextureFormatInfo& formatInfo(TextureFormat format) {
    auto index = static_cast<std::size_t>(format);
    return index < kFormats.size() ? kFormats[index] : kFormats[0];
}

}  // namespace fx
