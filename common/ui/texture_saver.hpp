#pragma once
// Saving what the inspector shows: the level as it looks (PNG, through the view's range, exposure,
// channels and transform, at one pixel per texel) or as the exact stored floats (PFM). Both
// writers are atomic, so a file is complete or absent.
#include <filesystem>
#include <string_view>

#include "base/result.hpp"
#include "ui/texture_display.hpp"

namespace fx {

// <dir>/<name>-mip<level><suffix>, with characters a file name should not hold replaced by '_'
// ("bloom.down[3]" -> "bloom.down_3_-mip0.png").
std::filesystem::path inspectorFilePath(const std::filesystem::path& dir, std::string_view textureName,
                                        int level, std::string_view suffix);

// The level through the view settings (no zoom, no grid) as an 8-bit RGBA PNG.
Status saveViewPng(const TextureDisplay& display, const TextureSource& source, const ViewSettings& settings,
                   const std::filesystem::path& path);

// The level's stored values as floats. PFM holds 1 or 3 channels: a 4-channel texture's alpha goes
// to a second file beside it (<stem>.alpha.pfm), so nothing stored is lost.
Status saveExactPfm(const TextureSource& source, int level, const std::filesystem::path& path);

}  // namespace fx
