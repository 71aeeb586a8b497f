#include "ui/texture_saver.hpp"

#include <algorithm>

#include "base/log.hpp"
#include "gl/readback.hpp"
#include "image/pfm_file.hpp"
#include "image/png_file.hpp"

namespace fx {

std::filesystem::path inspectorFilePath(const std::filesystem::path& dir, std::string_view textureName,
                                        int level, std::string_view suffix) {
    std::string safe(textureName);
    for (char& c : safe) {
        bool keep = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '.' ||
                    c == '-' || c == '_';
        if (!keep) c = '_';
    }
    if (safe.empty()) safe = "texture";
    return dir / cat(safe, "-mip", level, suffix);
}

Status saveViewPng(const TextureDisplay& display, const TextureSource& source, const ViewSettings& settings,
                   const std::filesystem::path& path) {
    if (!source.alive()) return Error{cat("cannot save '", source.name, "': it is not alive this frame")};
    if (!display.ok()) return Error{cat("cannot save '", source.name, "': ", display.error())};
    const int level = std::clamp(settings.level, 0, source.levels() - 1);
    const Size2D size = source.levelSize(level);
    DisplaySurface surface("ui.save png");
    surface.resize(size.width, size.height);
    ViewWindow oneToOne;  // origin 0, one texel per pixel
    display.draw(surface, source, settings, oneToOne);
    ByteImage image = gl::readFramebufferRgba8(surface.framebuffer(), size.width, size.height);
    return writePng(path, image);
}

Status saveExactPfm(const TextureSource& source, int level, const std::filesystem::path& path) {
    if (!source.alive()) return Error{cat("cannot save '", source.name, "': it is not alive this frame")};
    level = std::clamp(level, 0, source.levels() - 1);
    FloatImage image = gl::readTexture(source.native, source.spec, level);
    if (auto written = writePfm(path, image); !written) return written;
    if (image.channels == 4) {
        FloatImage alpha = makeFloatImage(image.width, image.height, 1);
        for (std::size_t t = 0; t < image.texelCount(); ++t) alpha.texels[t] = image.texels[t * 4 + 3];
        auto alphaPath = path;
        alphaPath.replace_extension(".alpha.pfm");
        if (auto written = writePfm(alphaPath, alpha); !written) return written;
    }
    return Status::success();
}

}  // namespace fx
