#include "app/capture.hpp"

#include <cstdio>

#include "base/log.hpp"
#include "gl/readback.hpp"
#include "image/pfm_file.hpp"
#include "image/png_file.hpp"
#include "image/view_transform.hpp"

namespace fx {

std::vector<CapturedTexture> readFrameTextures(const FrameGraph& graph) {
    std::vector<CapturedTexture> out;
    for (std::uint32_t i = 0; i < graph.textureCount(); ++i) {
        const TextureView& view = graph.texture(TextureHandle{i});
        if (view.native == 0 || view.origin == TextureOrigin::PresentedOutput) continue;
        CapturedTexture c{view.name, view.spec, gl::readTexture(view.native, view.spec, 0), {}};
        c.stats = computeStats(c.pixels);
        out.push_back(std::move(c));
    }
    return out;
}

std::string captureFileStem(std::string_view name) {
    std::string stem;
    for (char ch : name) {
        bool plain = (ch >= 'a' && ch <= 'z') || (ch >= 'A' && ch <= 'Z') || (ch >= '0' && ch <= '9') ||
                     ch == '.' || ch == '_' || ch == '-';
        if (plain) {
            stem += ch;
        } else if (ch == ']') {
            continue;
        } else if (stem.empty() || stem.back() != '-') {
            stem += '-';
        }
    }
    return stem.empty() ? "texture" : stem;
}

std::filesystem::path nextScreenshotPath(const std::filesystem::path& folder, const std::string& exe,
                                         int step) {
    std::error_code ec;
    for (int n = 1;; ++n) {
        char number[16];
        std::snprintf(number, sizeof number, "%03d", n);
        std::filesystem::path path = folder / cat(exe, "-step", step, "-", number, ".png");
        // Taken by anything, a link included (dangling or not); a folder that cannot be read: the write
        // will say why.
        if (!std::filesystem::exists(std::filesystem::symlink_status(path, ec)) || ec) return path;
    }
}

Status writeCaptures(const std::filesystem::path& dir, const ByteImage& finalImage,
                     const std::vector<CapturedTexture>& textures, bool floats) {
    if (!finalImage.empty()) {
        if (auto s = writePng(dir / "final.png", finalImage); !s) return s;
    }
    for (const CapturedTexture& t : textures) {
        // Linear light is sRGB-encoded for viewing; depth and UNORM data are shown as stored.
        bool floatFormat = isFloat(t.spec.format) && !isDepth(t.spec.format);
        std::string stem = captureFileStem(t.name);
        ByteImage shown =
            toDisplay(t.pixels, floatFormat ? ViewTransform::LinearToSrgb : ViewTransform::Direct);
        if (auto s = writePng(dir / (stem + ".png"), shown); !s) return s;
        if (floats) {
            if (auto s = writePfm(dir / (stem + ".pfm"), t.pixels); !s) return s;
        }
    }
    return Status::success();
}

}  // namespace fx
