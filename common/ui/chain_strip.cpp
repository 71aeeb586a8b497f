#include "ui/chain_strip.hpp"

#include <algorithm>
#include <cmath>

#include "base/log.hpp"
#include "base/words.hpp"
#include "ui/ui_style.hpp"

namespace fx {

int ChainStrip::tileHeight(std::size_t member, float firstHeight) {
    const double halved = double(firstHeight) / double(1ull << std::min<std::size_t>(member, 20));
    return std::max(static_cast<int>(std::lround(std::max(halved, double(firstHeight) / 3.0))), 8);
}

ChainStrip::Interaction ChainStrip::draw(const TextureDisplay& display, const TextureChain& chain,
                                         const SourceLookup& lookup, const ViewSettings& settings,
                                         const std::vector<ProbeSample>& samples,
                                         std::optional<std::size_t> current, float firstHeight) {
    Interaction result;
    tiles_.clear();
    while (surfaces_.size() < chain.members.size()) {
        surfaces_.emplace_back(cat("ui.chain strip tile ", surfaces_.size()));
    }
    // Every member in view: the tiles shrink (to a third of their height at most) until the whole
    // chain fits the width; a chain that still does not fit wraps onto another row.
    const float available = ImGui::GetContentRegionAvail().x;
    auto tileWidth = [&](std::size_t i, float first) {
        const ChainMember& m = chain.members[i];
        const double aspect = m.size.height > 0 ? double(m.size.width) / m.size.height : 1.0;
        const int h = tileHeight(i, first);
        return std::clamp(static_cast<int>(std::lround(h * aspect)), 8, 3 * h);
    };
    auto memberWidth = [&](std::size_t i, float first) {
        const ChainMember& m = chain.members[i];
        const std::string size = cat(m.size.width, "x", m.size.height);
        return std::max({float(tileWidth(i, first)), ImGui::CalcTextSize(m.label.c_str()).x,
                         ImGui::CalcTextSize(size.c_str()).x});
    };
    for (int attempt = 0; attempt < 8; ++attempt) {
        float total = 0.0f;
        for (std::size_t i = 0; i < chain.members.size(); ++i) total += memberWidth(i, firstHeight) + 6.0f;
        if (total <= available || firstHeight <= 24.0f) break;
        firstHeight = std::max(24.0f, firstHeight * 0.85f);
    }
    for (std::size_t i = 0; i < chain.members.size(); ++i) {
        const ChainMember& m = chain.members[i];
        if (i > 0) ui_style::continueRow(memberWidth(i, firstHeight), 6.0f);
        ImGui::BeginGroup();
        ImGui::PushID(int(i));
        const int h = tileHeight(i, firstHeight);
        const int w = tileWidth(i, firstHeight);
        // Tiles stand on a common baseline.
        const float drop = firstHeight - float(h) - ImGui::GetStyle().ItemSpacing.y;
        if (drop > 0.0f) ImGui::Dummy(ImVec2(float(w), drop));
        const ImVec2 p0 = ImGui::GetCursorScreenPos();
        Tile tile{m.label, m.size, w, h, false, p0.x, p0.y};

        const ImVec2 p1(p0.x + float(w), p0.y + float(h));
        ImGui::InvisibleButton("tile", ImVec2(float(w), float(h)));
        ImDrawList* draw = ImGui::GetWindowDrawList();
        TextureSource source = lookup(m.texture);
        ViewSettings memberSettings = settings;
        memberSettings.level = m.level;
        ViewWindow window = ViewWindow::fit(m.size, w, h);
        if (source.alive() && m.level < source.levels()) {
            DisplaySurface& surface = surfaces_[i];
            surface.resize(w, h);
            display.draw(surface, source, memberSettings, window);
            draw->AddImage(surface.id(), p0, p1, DisplaySurface::uvTopLeft(),
                           DisplaySurface::uvBottomRight());
            tile.drawn = true;
        } else {
            draw->AddRectFilled(p0, p1, IM_COL32(30, 30, 34, 255));
            draw->AddText(ImVec2(p0.x + 4, p0.y + 4), IM_COL32(140, 140, 140, 255),
                          say("chain.notAlive").c_str());
        }
        const bool isCurrent = current && *current == i;
        draw->AddRect(p0, p1, isCurrent ? ui_style::packed(ui_style::kHeading) : IM_COL32(80, 80, 90, 255),
                      0.0f, 0, isCurrent ? 2.0f : 1.0f);
        if (ImGui::IsItemClicked(ImGuiMouseButton_Left)) result.clicked = i;
        if (ImGui::IsItemHovered()) {
            result.hoveredMember = i;
            ImVec2 mouse = ImGui::GetIO().MousePos;
            int tx = static_cast<int>(std::floor(window.texelX(mouse.x - p0.x)));
            int ty = static_cast<int>(std::floor(window.texelY(p1.y - mouse.y)));
            if (tx >= 0 && ty >= 0 && tx < m.size.width && ty < m.size.height) {
                result.hovered = PixelProbe::Target{m.level, tx, ty, m.texture};
            }
        }
        // The probed texel's place in this member.
        if (i < samples.size() && samples[i].channels > 0) {
            const ProbeSample& s = samples[i];
            float px = p0.x + float((s.x + 0.5 - window.originX) / window.texelsPerPixel);
            float py = p1.y - float((s.y + 0.5 - window.originY) / window.texelsPerPixel);
            draw->AddCircle(ImVec2(px, py), 4.0f, IM_COL32(0, 0, 0, 255), 12, 2.5f);
            draw->AddCircle(ImVec2(px, py), 4.0f, IM_COL32(255, 255, 255, 255), 12, 1.2f);
        }

        // Labels: which member and its size.
        if (isCurrent) {
            ImGui::TextColored(ui_style::kHeading, "%s", m.label.c_str());
        } else {
            ImGui::TextUnformatted(m.label.c_str());
        }
        ImGui::TextDisabled("%dx%d", m.size.width, m.size.height);
        if (result.hoveredMember == i) {
            ImGui::BeginTooltip();
            ImGui::Text("%s, %dx%d%s", m.label.c_str(), m.size.width, m.size.height,
                        source.alive() ? "" : (" (" + say("chain.notAlive") + ")").c_str());
            if (i < samples.size() && samples[i].channels > 0) {
                const ProbeSample& s = samples[i];
                std::string values;
                for (int c = 0; c < s.channels; ++c)
                    values += (c ? "  " : "") + exactFloatText(s.texel.value[c]);
                ImGui::TextUnformatted(
                    say("chain.probe", {{"x", cat(s.x)}, {"y", cat(s.y)}, {"values", values}}).c_str());
            }
            ImGui::TextDisabled("%s", say("chain.click").c_str());
            ImGui::EndTooltip();
        }
        ImGui::PopID();
        ImGui::EndGroup();
        tiles_.push_back(tile);
    }
    return result;
}

}  // namespace fx
