#include "ui/inspector_list.hpp"

#include <algorithm>
#include <string_view>
#include <unordered_map>

#include "base/log.hpp"
#include "base/words.hpp"
#include "ui/ui_style.hpp"

namespace fx {

std::vector<TextureListEntry> listTextures(const FrameReport& frame) {
    // Each producer by name, the first pass of that name as FrameReport::findPass gives it: a search
    // per texture made this list quadratic in the frame's size.
    std::unordered_map<std::string_view, const PassRecord*> passByName;
    passByName.reserve(frame.passes.size());
    for (const PassRecord& p : frame.passes) passByName.emplace(p.name, &p);
    std::vector<TextureListEntry> entries;
    entries.reserve(frame.textures.size());
    for (const TextureRecord& t : frame.textures) {
        TextureListEntry e;
        e.texture = &t;
        if (!t.producer.empty()) {
            auto producer = passByName.find(t.producer);
            e.producer = producer == passByName.end() ? nullptr : producer->second;
        }
        e.presented = t.origin == TextureOrigin::PresentedOutput;
        e.made = t.origin == TextureOrigin::Transient ? t.allocated : (!e.producer || e.producer->executed);
        entries.push_back(e);
    }
    return entries;
}

std::string describeSizeAndFormat(const TextureRecord& t) {
    return cat(t.spec.width, "x", t.spec.height, " ", toString(t.spec.format));
}

std::string describeMipsAndBytes(const TextureRecord& t) {
    char bytes[32];
    return cat(t.spec.mipLevels, t.spec.mipLevels == 1 ? " mip, " : " mips, ",
               ui_style::byteSizeText(t.bytes, bytes, sizeof bytes));
}

std::string describeTexture(const TextureRecord& t) {
    return cat(describeSizeAndFormat(t), ", ", describeMipsAndBytes(t));
}

std::optional<std::string> TextureList::draw(const FrameReport& frame, const ThumbnailCache& thumbnails,
                                             const std::string& selected, std::uint64_t frameIndex) {
    std::optional<std::string> clicked;
    ImGui::SetNextItemWidth(-1);
    filter_.Draw("##filter", 0.0f);
    if (!filter_.IsActive()) {
        // ImGuiTextFilter has no hint text: draw one over the empty box.
        ImVec2 min = ImGui::GetItemRectMin();
        ImGui::GetWindowDrawList()->AddText(ImVec2(min.x + 6, min.y + 3), IM_COL32(120, 120, 120, 255),
                                            say("list.filter").c_str());
    }
    const float rowHeight =
        std::max(float(kThumbnailHeight) + 4.0f, 4.0f * ImGui::GetTextLineHeightWithSpacing());
    if (!ImGui::BeginTable("textures", 2,
                           ImGuiTableFlags_RowBg | ImGuiTableFlags_ScrollY | ImGuiTableFlags_BordersInnerH)) {
        return clicked;
    }
    ImGui::TableSetupColumn("thumbnail", ImGuiTableColumnFlags_WidthFixed, float(kThumbnailWidth));
    ImGui::TableSetupColumn("texture", ImGuiTableColumnFlags_WidthStretch);
    for (const TextureListEntry& e : listTextures(frame)) {
        const TextureRecord& t = *e.texture;
        if (!filter_.PassFilter(t.name.c_str())) continue;
        ImGui::PushID(t.name.c_str());
        ImGui::TableNextRow(0, rowHeight);
        ImGui::TableNextColumn();
        const bool isSelected = t.name == selected;
        const ImVec2 cell = ImGui::GetCursorScreenPos();
        if (ImGui::Selectable("##row", isSelected,
                              ImGuiSelectableFlags_SpanAllColumns | ImGuiSelectableFlags_AllowItemOverlap,
                              ImVec2(0, rowHeight - 2.0f))) {
            clicked = t.name;
        }
        const bool hovered = ImGui::IsItemHovered();
        ImDrawList* draw = ImGui::GetWindowDrawList();
        const ThumbnailCache::Thumbnail* thumb = thumbnails.find(t.name);
        const float top = cell.y + (rowHeight - float(kThumbnailHeight)) / 2.0f - 2.0f;
        ImVec2 box0(cell.x, top), box1(cell.x + kThumbnailWidth, top + kThumbnailHeight);
        if (thumb && !e.presented) {
            ImVec2 p0(box0.x + (kThumbnailWidth - thumb->width) / 2.0f,
                      box0.y + (kThumbnailHeight - thumb->height) / 2.0f);
            ImVec2 p1(p0.x + thumb->width, p0.y + thumb->height);
            // An old thumbnail (the texture was not alive this frame) or one of a texture not made is dimmed.
            bool fresh = thumb->frame == frameIndex;
            ImU32 tint = !e.made ? IM_COL32(110, 110, 110, 255)
                         : fresh ? IM_COL32_WHITE
                                 : IM_COL32(200, 200, 200, 255);
            draw->AddImage(thumb->surface.id(), p0, p1, DisplaySurface::uvTopLeft(),
                           DisplaySurface::uvBottomRight(), tint);
        } else {
            draw->AddRectFilled(box0, box1, IM_COL32(28, 28, 32, 255));
            const std::string screen = say("list.screen");
            const char* note = e.presented ? screen.c_str() : e.made ? "..." : "-";
            ImVec2 ns = ImGui::CalcTextSize(note);
            draw->AddText(
                ImVec2(box0.x + (kThumbnailWidth - ns.x) / 2, box0.y + (kThumbnailHeight - ns.y) / 2),
                IM_COL32(120, 120, 120, 255), note);
        }

        ImGui::TableNextColumn();
        if (!e.made) ImGui::PushStyleColor(ImGuiCol_Text, ui_style::kMuted);
        if (isSelected) {
            ImGui::TextColored(ui_style::kHeading, "%s", t.name.c_str());
        } else {
            ImGui::TextUnformatted(t.name.c_str());
        }
        ImGui::TextDisabled("%s", describeSizeAndFormat(t).c_str());
        ImGui::TextDisabled("%s", describeMipsAndBytes(t).c_str());
        if (e.presented) {
            ImGui::TextDisabled("%s", say("list.onScreen").c_str());
        } else if (!e.made) {
            ImGui::TextColored(ui_style::kWarning, "%s",
                               t.reason.empty() ? say("list.notMade").c_str() : t.reason.c_str());
        } else if (e.producer) {
            if (e.producer->timeMs) {
                ImGui::Text("%s: %.3f ms", e.producer->name.c_str(), *e.producer->timeMs);
            } else {
                ImGui::Text("%s", e.producer->name.c_str());
            }
        } else {
            ImGui::TextDisabled("%s", std::string(toString(t.origin)).c_str());
        }
        if (!e.made) ImGui::PopStyleColor();
        if (hovered) {
            ImGui::BeginTooltip();
            ImGui::TextUnformatted(t.name.c_str());
            ImGui::TextDisabled("%s, %s%s%s", describeTexture(t).c_str(),
                                std::string(toString(t.origin)).c_str(), t.inspected ? ", inspected" : "",
                                t.captured ? ", captured" : "");
            if (!t.producer.empty())
                ImGui::TextUnformatted(say("list.writtenBy", {{"pass", t.producer}}).c_str());
            if (!e.made && !t.reason.empty()) ImGui::TextColored(ui_style::kWarning, "%s", t.reason.c_str());
            ImGui::EndTooltip();
        }
        ImGui::PopID();
    }
    ImGui::EndTable();
    return clicked;
}

}  // namespace fx
