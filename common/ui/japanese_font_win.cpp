// The Japanese font on Windows: FXLAB_JAPANESE_FONT if set, else Windows' own MS Gothic (every
// Japanese Windows has it) or Yu Gothic, else the IPA Gothic the zip carries (fonts/ipag.ttf beside
// shaders/), for a Windows without Japanese fonts.
#include <cstdlib>

#include <windows.h>

#include "base/paths.hpp"
#include "ui/overlay_fonts.hpp"

namespace fx {

std::filesystem::path japaneseFontFile() {
    if (const char* file = std::getenv("FXLAB_JAPANESE_FONT"); file && *file) return file;
    std::filesystem::path fonts;
    wchar_t windowsFolder[MAX_PATH];
    if (const UINT n = GetWindowsDirectoryW(windowsFolder, MAX_PATH); n > 0 && n < MAX_PATH)
        fonts = std::filesystem::path(windowsFolder) / "Fonts";
    std::error_code ec;
    for (const char* name : {"msgothic.ttc", "YuGothR.ttc", "YuGothM.ttc"}) {
        if (fonts.empty()) break;
        if (std::filesystem::is_regular_file(fonts / name, ec)) return fonts / name;
    }
    return projectRoot() / "fonts" / "ipag.ttf";
}

}  // namespace fx
