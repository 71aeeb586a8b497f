// The Japanese font on Linux: Debian's IPA Gothic (fonts-ipafont-gothic), unless FXLAB_JAPANESE_FONT
// names another.
#include <cstdlib>

#include "ui/overlay_fonts.hpp"

namespace fx {

std::filesystem::path japaneseFontFile() {
    if (const char* file = std::getenv("FXLAB_JAPANESE_FONT"); file && *file) return file;
    return "/usr/share/fonts/opentype/ipafont-gothic/ipag.ttf";
}

}  // namespace fx
