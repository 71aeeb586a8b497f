#include "ui/thumbnail_cache.hpp"

#include <algorithm>
#include <cmath>

namespace fx {

void ThumbnailCache::refresh(const TextureDisplay& display, const TextureSource& source,
                             const ViewSettings& settings, int maxWidth, int maxHeight, std::uint64_t frame) {
    if (!source.alive() || !display.ok()) return;
    const Size2D size = source.levelSize(0);
    if (size.empty()) return;
    double scale = std::min(double(maxWidth) / size.width, double(maxHeight) / size.height);
    int w = std::clamp(static_cast<int>(std::lround(size.width * scale)), 1, maxWidth);
    int h = std::clamp(static_cast<int>(std::lround(size.height * scale)), 1, maxHeight);
    auto [it, added] =
        thumbnails_.try_emplace(source.name, Thumbnail{DisplaySurface("ui.thumbnail " + source.name)});
    Thumbnail& t = it->second;
    t.surface.resize(w, h);
    t.width = w;
    t.height = h;
    t.frame = frame;
    ViewSettings s = settings;
    s.level = 0;
    display.draw(t.surface, source, s, ViewWindow::fit(size, w, h));
}

const ThumbnailCache::Thumbnail* ThumbnailCache::find(const std::string& name) const {
    auto it = thumbnails_.find(name);
    return it == thumbnails_.end() ? nullptr : &it->second;
}

void ThumbnailCache::keepOnly(const std::set<std::string>& names) {
    std::erase_if(thumbnails_, [&](const auto& entry) { return !names.contains(entry.first); });
}

}  // namespace fx
