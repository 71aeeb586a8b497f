#include "ui/inspector.hpp"

#include <algorithm>
#include <set>
#include <utility>

#include "base/log.hpp"
#include "base/words.hpp"
#include "ui/texture_saver.hpp"
#include "ui/ui_style.hpp"
#include "ui/view_controls.hpp"

namespace fx {
namespace {

constexpr std::size_t kThumbnailsPerFrame = 2;  // textures kept alive in turn to refresh thumbnails
constexpr float kListWidth = 250.0f;
constexpr float kStripTileHeight = 64.0f;
// The least a strip's first tile gets: its 1x1 level a visible square, the picture in it readable.
constexpr float kLeastStripTileHeight = 40.0f;

// The probe's lines: the texel and its values, and the chain's table (a header and up to 4 rows).
float probeHeightFor(std::size_t chainRows, bool hasStrip, float line) {
    return 2.0f * line + (hasStrip ? float(chainRows + 1) * line + 10.0f : 0.0f);
}

}  // namespace

Inspector::Inspector() = default;

void Inspector::setOpen(bool open) {
    requestOpen_ = open;
    visible_ = open;
}

void Inspector::select(const std::string& name) {
    if (name == selected_) return;
    selected_ = name;
    probe_.unpin();
    hovered_.reset();
    analyser_.invalidate();
    view_.fit();
}

ViewSettings& Inspector::settingsFor(const std::string& name, const TextureSpec& spec) {
    auto it = settings_.find(name);
    if (it == settings_.end() || it->second.format != spec.format) {
        it = settings_.insert_or_assign(name, Kept{spec.format, defaultViewSettings(spec)}).first;
    }
    ViewSettings& s = it->second.settings;
    s.level = std::clamp(s.level, 0, std::max(spec.mipLevels, 1) - 1);
    return s;
}

TextureSource Inspector::lookup(const std::string& name) const {
    if (!graph_) return {};
    auto handle = graph_->findTexture(name);
    if (!handle) return {};
    return textureSource(graph_->texture(*handle));
}

std::vector<std::string> Inspector::wantedTextures() const {
    std::vector<std::string> names;
    if (!visible_) {
        asked_.clear();
        return names;
    }
    auto add = [&](const std::string& name) {
        if (!name.empty() && std::find(names.begin(), names.end(), name) == names.end())
            names.push_back(name);
    };
    add(selected_);
    if (chain_.kind == TextureChain::Kind::Named) {
        for (const ChainMember& m : chain_.members) add(m.texture);
    }
    for (std::size_t i = 0; i < std::min(kThumbnailsPerFrame, candidates_.size()); ++i) {
        add(candidates_[nextThumbnail_++ % candidates_.size()]);
    }
    asked_ = std::set<std::string>(names.begin(), names.end());
    return names;
}

void Inspector::refreshThumbnails(const InspectorFrame& frame) {
    std::set<std::string> names;
    candidates_.clear();
    bool fittedOne = false;
    for (const TextureListEntry& e : listTextures(*frame.report)) {
        const TextureRecord& t = *e.texture;
        names.insert(t.name);
        if (e.presented) continue;
        if (t.origin == TextureOrigin::Transient && t.allocated && !asked_.contains(t.name)) {
            candidates_.push_back(t.name);
        }
        TextureSource source = lookup(t.name);
        if (!source.alive()) continue;
        ViewSettings& s = settingsFor(t.name, source.spec);
        s.cameraNear = frame.cameraNear;
        s.cameraFar = frame.cameraFar;
        // Depth needs its range before a thumbnail says anything; one texture a frame is read back
        // for that, once per texture: the fitted range is kept, and a texture with nothing to fit
        // (all one value, all NaN) keeps the default range instead of being read back every frame
        // (which cost a 1920x1080 frame several times its passes: docs/bench.md).
        if (s.autoFitPending && !fittedOne && t.name != selected_) {
            TextureAnalysis a = analyseImage(gl::readTexture(source.native, source.spec, 0),
                                             showsLinearDepth(s, source.spec), s.cameraNear, s.cameraFar, 8);
            autoFitRange(s, a);
            s.autoFitPending = false;
            fittedOne = true;
        }
        thumbnails_.refresh(display_, source, s, TextureList::kThumbnailWidth, TextureList::kThumbnailHeight,
                            frameIndex_);
    }
    thumbnails_.keepOnly(names);
}

ImVec2 Inspector::draw(const InspectorFrame& frame, ImVec2 position, ImVec2 size) {
    graph_ = frame.graph;
    ImGui::SetNextWindowPos(position, ImGuiCond_Always);
    ImGui::SetNextWindowSize(size, ImGuiCond_Always);
    if (requestOpen_) {
        ImGui::SetNextWindowCollapsed(!*requestOpen_, ImGuiCond_Always);
        requestOpen_.reset();
    } else {
        ImGui::SetNextWindowCollapsed(true, ImGuiCond_FirstUseEver);
    }
    visible_ =
        ImGui::Begin((say("inspector.title") + "###inspector").c_str(), nullptr, ImGuiWindowFlags_NoMove);
    const ImVec2 shown = ImGui::GetWindowSize();
    if (!visible_) {
        ImGui::End();
        graph_ = nullptr;
        return shown;
    }
    ++frameIndex_;
    if (!frame.report) {
        ImGui::TextDisabled("%s", say("frame.none").c_str());
        ImGui::End();
        graph_ = nullptr;
        return shown;
    }
    refreshThumbnails(frame);

    const float listWidth = std::min(kListWidth, std::max(160.0f, ImGui::GetContentRegionAvail().x * 0.36f));
    ImGui::BeginChild("list", ImVec2(listWidth, 0), false);
    if (auto clicked = list_.draw(*frame.report, thumbnails_, selected_, frameIndex_)) select(*clicked);
    ImGui::EndChild();
    ImGui::SameLine();
    ImGui::BeginChild("detail", ImVec2(0, 0), false, ImGuiWindowFlags_NoScrollWithMouse);
    drawDetail(frame);
    ImGui::EndChild();
    ImGui::End();
    graph_ = nullptr;
    return shown;
}

Result<std::filesystem::path> Inspector::saveSelected(bool exactFloats) {
    TextureSource source = lookup(selected_);
    if (selected_.empty()) return Error{"no texture selected"};
    ViewSettings& s = settingsFor(selected_, source.spec);
    auto path = inspectorFilePath(saveFolder_, selected_, s.level, exactFloats ? ".pfm" : ".png");
    Status saved = exactFloats ? saveExactPfm(source, s.level, path) : saveViewPng(display_, source, s, path);
    if (!saved) return Error{saved.error()};
    return path;
}

void Inspector::drawDetail(const InspectorFrame& frame) {
    if (!display_.ok()) {
        ImGui::TextColored(ui_style::kError, "%s", say("inspector.viewShaderFailed").c_str());
        ImGui::TextWrapped("%s", display_.error().c_str());
        return;
    }
    const TextureRecord* record = selected_.empty() ? nullptr : frame.report->findTexture(selected_);
    if (!record) {
        chain_ = {};
        const WordArgs texture{{"texture", selected_}};
        ImGui::TextDisabled(
            "%s", say(selected_.empty() ? "inspector.select" : "inspector.notInFrame", texture).c_str());
        ImGui::PushTextWrapPos(0.0f);
        ImGui::TextDisabled("%s", say("inspector.howTo").c_str());
        ImGui::PopTextWrapPos();
        return;
    }
    chain_ = findChain(*frame.report, selected_);
    TextureSource source = lookup(selected_);

    // Header: name and facts.
    ImGui::TextColored(ui_style::kHeading, "%s", selected_.c_str());
    ImGui::SameLine();
    ImGui::TextDisabled("%s", describeTexture(*record).c_str());
    if (!source.alive()) {
        ImGui::PushTextWrapPos(0.0f);
        if (record->origin == TextureOrigin::PresentedOutput) {
            ImGui::TextDisabled("%s", say("inspector.presented").c_str());
        } else if (!record->reason.empty()) {
            ImGui::TextColored(ui_style::kWarning, "%s",
                               say("inspector.notMade", {{"reason", record->reason}}).c_str());
        } else {
            ImGui::TextDisabled("%s", say("inspector.notAlive").c_str());
        }
        ImGui::PopTextWrapPos();
        return;
    }

    ViewSettings& s = settingsFor(selected_, source.spec);
    s.cameraNear = frame.cameraNear;
    s.cameraFar = frame.cameraFar;
    if (analyser_.update(source, s, frame.deltaSeconds) && s.autoFitPending) {
        autoFitRange(s, analyser_.analysis());
        s.autoFitPending = false;
    }
    drawViewControls(s, source, analysis());
    ui_style::continueRow(170.0f, 16.0f);
    if (ImGui::Button((say("inspector.findSpecial") + "###find special").c_str())) findSpecialAsked_ = true;
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", say("inspector.findSpecialHelp").c_str());
    if (std::exchange(findSpecialAsked_, false)) findSpecial(source, s);
    ImGui::SameLine();
    drawSaveButtons();
    if (const TextureAnalysis* a = analysis())
        drawHistogram(*a, s, ImVec2(ImGui::GetContentRegionAvail().x, 44.0f));

    // The rest of the height: the view, the probe, the strip.
    const float line = ImGui::GetTextLineHeightWithSpacing();
    const bool hasStrip = chain_.kind != TextureChain::Kind::None;
    // In a short inspector (the default one: the lower part of a 720-line window) the chain's probe
    // table shows two members (it scrolls) and the large view gives up height before the strip's tiles
    // go below a readable size: the whole chain stays on the screen, its labels and sizes included
    // ("inspect bloom mip textures live" at the default layout).
    const bool shortInspector = ImGui::GetContentRegionAvail().y < 20.0f * line;
    const std::size_t chainRows =
        hasStrip ? std::min<std::size_t>(chain_.members.size(), shortInspector ? 2 : 4) : 0;
    // The strip's heading, each tile's label and size, the spacing between them and the scrollbar.
    const float stripText = 4.0f * line + ImGui::GetStyle().ScrollbarSize;
    const float leastView = shortInspector ? 40.0f : 64.0f;
    const float tileHeight =
        hasStrip ? std::clamp(ImGui::GetContentRegionAvail().y - probeHeightFor(chainRows, hasStrip, line) -
                                  leastView - stripText,
                              kLeastStripTileHeight, kStripTileHeight)
                 : 0.0f;
    const float stripHeight = hasStrip ? tileHeight + stripText : 0.0f;
    const float probeHeight = probeHeightFor(chainRows, hasStrip, line);
    ImVec2 avail = ImGui::GetContentRegionAvail();
    ImVec2 viewSize(avail.x, std::max(avail.y - stripHeight - probeHeight, leastView));

    std::optional<PixelProbe::Target> target = probe_.target(hovered_);
    auto inView = [&](const PixelProbe::Target& t) { return t.texture.empty() || t.texture == selected_; };
    std::optional<PixelProbe::Target> mark;
    if (target && inView(*target)) mark = target;
    ZoomableView::Interaction viewed = view_.draw(display_, source, s, viewSize, mark);
    hovered_ = viewed.hovered;
    if (viewed.pinRequested) {
        if (probe_.pinned()) {
            probe_.unpin();
        } else {
            probe_.pin(*viewed.hovered);
        }
    }

    // The probe: exact values read back from the texture (not from the picture above).
    target = probe_.target(hovered_);
    probeSample_ = {};
    chainSamples_.clear();
    TextureSource anchor = source;
    if (target) {
        if (!inView(*target)) anchor = lookup(target->texture);
        probeSample_ = probeTexel(anchor, target->level, target->x, target->y);
        probeSample_.label = inView(*target) ? selected_ : target->texture;
        if (hasStrip) {
            chainSamples_ = probeChain(
                chain_, [this](const std::string& n) { return lookup(n); }, target->x, target->y,
                anchor.levelSize(target->level));
        }
    }
    PixelProbe::draw(probeSample_, anchor, showsLinearDepth(s, anchor.spec), s.cameraNear, s.cameraFar,
                     probe_.pinned());
    if (target && !inView(*target)) {
        ImGui::SameLine();
        ImGui::TextDisabled("in %s", target->texture.c_str());
    }
    if (hasStrip) drawChainProbe(float(chainRows + 1) * line + 4.0f);

    if (hasStrip) {
        ImGui::TextDisabled("%s: click one to view it", chain_.title.c_str());
        ImGui::BeginChild("strip", ImVec2(0, 0), false, ImGuiWindowFlags_HorizontalScrollbar);
        std::optional<std::size_t> current;
        for (std::size_t i = 0; i < chain_.members.size(); ++i) {
            const ChainMember& m = chain_.members[i];
            if (m.texture == selected_ && (chain_.kind == TextureChain::Kind::Named || m.level == s.level))
                current = i;
        }
        ChainStrip::Interaction stripped = strip_.draw(
            display_, chain_, [this](const std::string& n) { return lookup(n); }, s, chainSamples_, current,
            tileHeight);
        if (stripped.hovered) hovered_ = stripped.hovered;
        if (stripped.clicked) {
            const ChainMember& m = chain_.members[*stripped.clicked];
            if (chain_.kind == TextureChain::Kind::MipLevels) {
                s.level = m.level;
            } else {
                select(m.texture);
            }
        }
        ImGui::EndChild();
    }
}

void Inspector::findSpecial(const TextureSource& source, const ViewSettings& s) {
    const int level = std::clamp(s.level, 0, source.levels() - 1);
    // Searching from the pinned texel goes on to the next one each time.
    int afterX = -1, afterY = -1;
    if (auto pinned = probe_.target(std::nullopt);
        pinned && pinned->texture.empty() && pinned->level == level) {
        afterX = pinned->x;
        afterY = pinned->y;
    }
    std::int64_t count = 0;
    auto found = nextSpecialTexel(gl::readTexture(source.native, source.spec, level), afterX, afterY, &count);
    if (!found) {
        status_ = say("inspector.noSpecial", {{"texture", selected_}, {"level", cat(level)}});
        return;
    }
    probe_.pin({level, found->x, found->y, {}});
    const Size2D size = source.levelSize(level);
    // About 24 screen pixels per texel of this level, centred on it.
    const double levelScale = double(source.levelSize(0).width) / std::max(size.width, 1);
    view_.setZoom(24.0 / levelScale, (found->x + 0.5) / size.width, (found->y + 0.5) / size.height);
    status_ = say(count == 1 ? "inspector.specialOne" : "inspector.specialMany",
                  {{"x", cat(found->x)}, {"y", cat(found->y)}, {"level", cat(level)}, {"count", cat(count)}});
    log::info("inspector: ", status_);
}

void Inspector::drawSaveButtons() {
    for (bool exact : {false, true}) {
        if (exact) ImGui::SameLine();
        if (ImGui::Button(
                (say(exact ? "inspector.savePfm" : "inspector.savePng") + (exact ? "###pfm" : "###png"))
                    .c_str())) {
            auto saved = saveSelected(exact);
            if (saved)
                status_ = say("notice.presetSaved", {{"file", saved->string()}});
            else
                status_ = saved.error();
            log::info(status_);
        }
        if (ImGui::IsItemHovered()) {
            ImGui::SetTooltip("%s", say(exact ? "inspector.savePfmHelp" : "inspector.savePngHelp",
                                        {{"folder", saveFolder_.string()}})
                                        .c_str());
        }
    }
    if (!status_.empty()) {
        ui_style::continueRow(ImGui::CalcTextSize(status_.c_str()).x);
        ImGui::TextDisabled("%s", status_.c_str());
    }
}

void Inspector::drawChainProbe(float height) {
    // The same place in every member of the chain, exactly as stored.
    const ImGuiTableFlags flags = ImGuiTableFlags_RowBg | ImGuiTableFlags_ScrollY |
                                  ImGuiTableFlags_SizingStretchProp | ImGuiTableFlags_BordersInnerV;
    if (!ImGui::BeginTable("chain probe", 6, flags, ImVec2(0, height))) return;
    ImGui::TableSetupScrollFreeze(0, 1);
    // The names in full ("bloom.down[3]", never "bloom.dow"): the first column is as wide as the longest.
    float nameWidth = ImGui::CalcTextSize("same place in").x;
    for (const ChainMember& m : chain_.members)
        nameWidth = std::max(nameWidth, ImGui::CalcTextSize(m.label.c_str()).x);
    ImGui::TableSetupColumn("same place in", ImGuiTableColumnFlags_WidthFixed, nameWidth);
    ImGui::TableSetupColumn("texel", ImGuiTableColumnFlags_WidthStretch, 0.9f);
    for (const char* c : {"R", "G", "B", "A"})
        ImGui::TableSetupColumn(c, ImGuiTableColumnFlags_WidthStretch, 1.0f);
    ImGui::TableHeadersRow();
    for (std::size_t i = 0; i < chain_.members.size(); ++i) {
        const ChainMember& m = chain_.members[i];
        ImGui::TableNextRow();
        ImGui::TableNextColumn();
        ImGui::TextUnformatted(m.label.c_str());
        const ProbeSample* sample =
            i < chainSamples_.size() && chainSamples_[i].channels > 0 ? &chainSamples_[i] : nullptr;
        ImGui::TableNextColumn();
        if (!sample) {
            ImGui::TextDisabled("-");
            continue;
        }
        ImGui::Text("%d, %d", sample->x, sample->y);
        for (int c = 0; c < 4; ++c) {
            ImGui::TableNextColumn();
            if (c < sample->channels) ImGui::TextUnformatted(exactFloatText(sample->texel.value[c]).c_str());
        }
    }
    ImGui::EndTable();
}

}  // namespace fx
