#pragma once
// The inspector window: the list of the frame's textures on the left; on the right the selected
// texture large (zoom, pan, channels, range, exposure, view transform, depth linearised, NaN / Inf /
// negative marks, histogram), the pixel probe, and the strip of its whole chain. Save as PNG or PFM.
//
// A texture exists only in frames where something keeps it, so what the inspector shows it asks
// for (wantedTextures): the runner marks those names inspected before the next frame runs, which
// keeps them and the passes that make them alive. Selecting a texture therefore shows it from the
// next frame on.
#include <cstdint>
#include <filesystem>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include <imgui.h>

#include "render/frame_graph.hpp"
#include "ui/chain_strip.hpp"
#include "ui/inspector_list.hpp"
#include "ui/pixel_probe.hpp"
#include "ui/texture_analysis.hpp"
#include "ui/texture_chain.hpp"
#include "ui/texture_display.hpp"
#include "ui/texture_view.hpp"
#include "ui/thumbnail_cache.hpp"

namespace fx {

struct InspectorFrame {
    const FrameGraph* graph = nullptr;  // its inspected textures still held
    const FrameReport* report = nullptr;
    float cameraNear = 0.1f, cameraFar = 100.0f;
    double deltaSeconds = 1.0 / 60.0;
};

class Inspector {
public:
    Inspector();

    // Draws the window at `position` and `size` (the layout's place for it, open or collapsed);
    // returns its size after the user's drag of an edge.
    ImVec2 draw(const InspectorFrame& frame, ImVec2 position, ImVec2 size);

    // The selected texture, the members of its named chain, and two more a frame in turn so that
    // every thumbnail stays fresh. Those two are only textures the last frame made without being
    // asked, so keeping them a little longer never brings back a culled pass. Nothing while the
    // window is closed: the frame is then untouched. Call once a frame, before the frame is built.
    std::vector<std::string> wantedTextures() const;

    // --- For tests, tools and pictures (the same things a user does with the mouse) ---
    void setOpen(bool open);
    bool open() const { return visible_; }
    void select(const std::string& name);
    const std::string& selected() const { return selected_; }
    // The view settings kept for a texture (created with defaults for its format).
    ViewSettings& settingsFor(const std::string& name, const TextureSpec& spec);
    ZoomableView& view() { return view_; }
    PixelProbe& probe() { return probe_; }
    const ChainStrip& strip() const { return strip_; }
    const TextureChain& chain() const { return chain_; }
    const TextureAnalysis* analysis() const { return analyser_.valid() ? &analyser_.analysis() : nullptr; }
    const ProbeSample& probeSample() const { return probeSample_; }
    const std::vector<ProbeSample>& chainSamples() const { return chainSamples_; }
    const TextureDisplay& display() const { return display_; }

    // Finds the next texel of the selected texture's shown level that holds a NaN or an infinity
    // (after the pinned one, in reading order), pins the probe there and zooms the view onto it: at fit
    // zoom one bad texel is one screen pixel or less. Runs at the next draw; the status says the result.
    void findNextSpecial() { findSpecialAsked_ = true; }

    void setSaveFolder(std::filesystem::path folder) { saveFolder_ = std::move(folder); }
    const std::string& status() const { return status_; }

private:
    TextureSource lookup(const std::string& name) const;
    // Saves the selected texture's level as shown (PNG) or as stored (PFM): the path or the reason.
    // Only during draw, while the frame's textures are held.
    Result<std::filesystem::path> saveSelected(bool exactFloats);
    void drawDetail(const InspectorFrame& frame);
    void drawSaveButtons();
    void findSpecial(const TextureSource& source, const ViewSettings& settings);
    void drawChainProbe(float height);
    void refreshThumbnails(const InspectorFrame& frame);

    TextureDisplay display_;
    TextureList list_;
    ThumbnailCache thumbnails_;
    ZoomableView view_;
    ChainStrip strip_;
    PixelProbe probe_;
    TextureAnalyser analyser_;
    TextureChain chain_;
    ProbeSample probeSample_;
    std::vector<ProbeSample> chainSamples_;
    std::optional<PixelProbe::Target> hovered_;  // from the last frame's view or strip

    struct Kept {
        TextureFormat format = TextureFormat::RGBA8;
        ViewSettings settings;
    };
    std::map<std::string, Kept> settings_;
    std::string selected_;
    const FrameGraph* graph_ = nullptr;    // valid during draw only
    std::vector<std::string> candidates_;  // made in the last frame without being asked for
    mutable std::set<std::string> asked_;  // what the last wantedTextures() asked for
    mutable std::size_t nextThumbnail_ = 0;
    std::uint64_t frameIndex_ = 0;
    bool visible_ = false;
    std::optional<bool> requestOpen_;
    bool findSpecialAsked_ = false;
    std::filesystem::path saveFolder_ = "out/inspector";
    std::string status_;
};

}  // namespace fx
