#pragma once
// Small pictures of the frame's textures for the inspector's list. A texture exists only in frames
// where something keeps it (see Inspector::wantedTextures), so a thumbnail is redrawn whenever its
// texture is alive and otherwise keeps the last picture, marked as old in the list.
#include <map>
#include <set>
#include <string>

#include "ui/texture_display.hpp"

namespace fx {

class ThumbnailCache {
public:
    struct Thumbnail {
        DisplaySurface surface;
        int width = 0, height = 0;  // the picture inside the surface, fitted to the texture's aspect
        std::uint64_t frame = 0;    // the frame it was drawn in
    };

    // Draws a thumbnail of level 0 into a box of maxWidth x maxHeight when the texture is alive.
    void refresh(const TextureDisplay& display, const TextureSource& source, const ViewSettings& settings,
                 int maxWidth, int maxHeight, std::uint64_t frame);
    const Thumbnail* find(const std::string& name) const;
    // Drops the thumbnails of textures the frame no longer has.
    void keepOnly(const std::set<std::string>& names);

private:
    std::map<std::string, Thumbnail> thumbnails_;
};

}  // namespace fx
