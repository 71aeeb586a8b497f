#pragma once
// The inspector's list of every texture of the frame, from the graph's report: a thumbnail, the
// name, size, format, mip count and bytes, the pass that wrote it and that pass's time. Textures
// the frame did not make (their pass was culled or switched off) are listed greyed with the reason.
#include <optional>
#include <string>

#include <imgui.h>

#include "render/frame_report.hpp"
#include "ui/thumbnail_cache.hpp"

namespace fx {

struct TextureListEntry {
    const TextureRecord* texture = nullptr;
    const PassRecord* producer = nullptr;  // null for imports nobody writes
    bool made = false;                     // allocated this frame (or imported: always there)
    bool presented = false;                // the window's framebuffer or the headless output
};

// One entry per texture of the frame, in declaration order.
std::vector<TextureListEntry> listTextures(const FrameReport& frame);

// "1280x720 RGBA16F, 11 mips, 4.69 MiB"
std::string describeTexture(const TextureRecord& texture);
// "1280x720 RGBA16F" and "11 mips, 4.69 MiB": the same in two short lines.
std::string describeSizeAndFormat(const TextureRecord& texture);
std::string describeMipsAndBytes(const TextureRecord& texture);

class TextureList {
public:
    // Returns the name of the texture clicked this frame.
    std::optional<std::string> draw(const FrameReport& frame, const ThumbnailCache& thumbnails,
                                    const std::string& selected, std::uint64_t frameIndex);

    ImGuiTextFilter& filter() { return filter_; }
    static constexpr int kThumbnailWidth = 56, kThumbnailHeight = 32;

private:
    ImGuiTextFilter filter_;
};

}  // namespace fx
