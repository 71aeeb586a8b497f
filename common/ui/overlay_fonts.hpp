#pragma once
// The overlay's font: Dear ImGui's built-in font (ASCII and Latin-1), with the glyphs the lesson's
// text needs beyond it (Japanese, "≈") merged in from IPA Gothic (Debian: fonts-ipafont-gothic).
// Only the characters the text really uses are loaded, so the atlas stays small: lesson 06's
// Japanese needs a few hundred glyphs, not the 20000 of GetGlyphRangesJapanese(). The atlas may change
// only between ImGui frames, and the OpenGL3 backend's font texture is made again after it does.
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "base/result.hpp"

namespace fx {

// FXLAB_JAPANESE_FONT in the environment, else the system's (Linux: Debian's IPA Gothic; Windows: MS Gothic
// or Yu Gothic, else the IPA Gothic the zip carries: japanese_font_posix.cpp, japanese_font_win.cpp).
std::filesystem::path japaneseFontFile();

// The code points above U+00FF in `texts` (the built-in font has everything below), sorted, once each.
std::vector<char32_t> codePointsBeyondLatin1(const std::vector<std::string_view>& texts);

class OverlayFonts {
public:
    // Call between frames (before ImGui::NewFrame) with every string the overlay will show. Rebuilds
    // the atlas when the set of characters changed; an error (the font file is missing) leaves the
    // atlas as it was.
    // `scale` is the text scale (1 = Dear ImGui's 13-pixel font): the glyphs are rasterised at that
    // size, so large text on a projector stays sharp.
    Status prepare(const std::vector<std::string_view>& texts, float scale = 1.0f);
    // Of the code points asked for last: how many the atlas has and how many the font lacks.
    int loadedGlyphs() const { return loaded_; }
    int missingGlyphs() const { return missing_; }

private:
    std::vector<char32_t> merged_;        // what the atlas was built for
    float scale_ = 0.0f;                  // and at which text scale
    std::vector<unsigned short> ranges_;  // ImWchar pairs, alive while the atlas uses them
    int loaded_ = 0, missing_ = 0;
};

}  // namespace fx
