#include "ui/pass_table.hpp"

#include <algorithm>
#include <string>

#include <imgui.h>

#include "base/log.hpp"
#include "ui/ui_style.hpp"
#include "ui/word_wrap.hpp"

namespace fx {

double totalPassMs(const FrameReport& frame) {
    double total = 0.0;
    for (const PassRecord& p : frame.passes) {
        if (p.executed) total += p.timeMs.value_or(0.0);
    }
    return total;
}

void drawPassTable(const FrameReport& frame, double copyMs) {
    const double total = totalPassMs(frame);
    int ran = 0;
    for (const PassRecord& p : frame.passes) ran += p.executed ? 1 : 0;
    // One timing method for every pass is said once; a column only when they differ.
    std::string method;
    bool oneMethod = true;
    for (const PassRecord& p : frame.passes) {
        if (!p.executed || p.timingMethod.empty()) continue;
        if (method.empty()) method = p.timingMethod;
        oneMethod = oneMethod && p.timingMethod == method;
    }
    if (oneMethod && !method.empty()) {
        ImGui::TextWrapped("%d of %d passes ran in %.3f ms, timed by %s", ran, int(frame.passes.size()),
                           total, method.c_str());
    } else {
        ImGui::TextWrapped("%d of %d passes ran in %.3f ms", ran, int(frame.passes.size()), total);
    }
    char live[32], peak[32], inUse[32];
    ImGui::TextWrapped(
        "textures: %s live (%d), %s peak", ui_style::byteSizeText(frame.pool.liveBytes, live, sizeof live),
        int(frame.pool.liveTextures), ui_style::byteSizeText(frame.pool.peakBytes, peak, sizeof peak));
    if (ImGui::IsItemHovered()) {
        ImGui::SetTooltip(
            "live: allocated by the texture pool now (in use or waiting for reuse)\n"
            "in use: %s held by this frame\npeak: the most ever allocated at once\n"
            "(textures the overlay keeps alive to show them count too)",
            ui_style::byteSizeText(frame.pool.inUseBytes, inUse, sizeof inUse));
    }
    const PassTraffic traffic = frame.modelledTraffic();
    ImGui::TextWrapped("modelled memory traffic (MB/taps): %s a frame at 1920x1080, %.1f taps a pixel",
                       megabytesText(traffic.total()).c_str(), frame.tapsPerOutputPixel());
    if (ImGui::IsItemHovered()) {
        ImGui::SetTooltip(
            "what a GPU would move through memory (render/pass_traffic.hpp): every texture a pass\n"
            "samples read once, every texture it writes written once, at 1920x1080 whatever the\n"
            "window's size; taps: texture lookups per pixel written, over the whole output");
    }
    for (const std::string& e : frame.errors)
        ImGui::TextColored(ui_style::kError, "graph error: %s", e.c_str());
    const int columns = oneMethod ? 8 : 9;

    // The frame window is a narrow column: every column keeps a width its header fits in, the pass
    // (and its number) stay in place, and the columns to the right scroll sideways. Each pass is one
    // line, so a 1280x720 window shows many: a cell wider than its column is cut with "..." and shows
    // the whole text on hover (columns can be dragged wider). Widths follow the text size.
    const ImGuiTableFlags flags = ImGuiTableFlags_RowBg | ImGuiTableFlags_BordersInnerV |
                                  ImGuiTableFlags_Resizable | ImGuiTableFlags_ScrollY |
                                  ImGuiTableFlags_ScrollX | ImGuiTableFlags_SizingFixedFit;
    if (!ImGui::BeginTable("passes", columns, flags)) return;
    ImGui::TableSetupScrollFreeze(2, 1);
    const float em = ImGui::GetFontSize();
    auto column = [em](const char* header, float ems) {
        const float headerWidth = ImGui::CalcTextSize(header).x;
        ImGui::TableSetupColumn(header, ImGuiTableColumnFlags_WidthFixed, std::max(ems * em, headerWidth));
    };
    column("#", 1.5f);
    column("pass", 10.5f);
    column(copyMs > 0.0 ? "ms (copies)" : "ms", copyMs > 0.0 ? 8.0f : 4.0f);
    column("share", 4.5f);
    column("MB/taps", 5.0f);  // the cost model (a tooltip on each cell says what each number is)
    if (!oneMethod) column("timed by", 8.0f);
    column("ran / why not", 13.0f);
    column("state inherited / left", 13.0f);
    column("wrote", 11.0f);
    ImGui::TableHeadersRow();
    int order = 0;
    for (const PassRecord& p : frame.passes) {
        ImGui::TableNextRow();
        ImGui::PushID(int(p.declaredIndex));
        if (!p.executed) ImGui::PushStyleColor(ImGuiCol_Text, ui_style::kMuted);
        ImGui::TableNextColumn();
        if (p.executed) {
            ImGui::Text("%d", ++order);
        } else {
            ImGui::TextUnformatted("-");
        }
        ImGui::TableNextColumn();
        drawOneLine(p.name);
        ImGui::TableNextColumn();
        if (p.timeMs && copyMs > 0.0) {
            ImGui::Text("%.3f (%.2f)", *p.timeMs, *p.timeMs / copyMs);
        } else if (p.timeMs) {
            ImGui::Text("%.3f", *p.timeMs);
        }
        ImGui::TableNextColumn();
        if (p.executed && p.timeMs && total > 0.0) {
            float share = float(*p.timeMs / total);
            char text[16];
            std::snprintf(text, sizeof text, "%.0f%%", double(share) * 100.0);
            ImGui::PushStyleColor(ImGuiCol_PlotHistogram, ImVec4(0.30f, 0.52f, 0.82f, 1.0f));
            ImGui::ProgressBar(share, ImVec2(-1.0f, ImGui::GetTextLineHeight()), text);
            ImGui::PopStyleColor();
        }
        // The cost model: megabytes read + written at 1920x1080, then the declared taps.
        ImGui::TableNextColumn();
        if (p.status == PassStatus::Runs)
            ImGui::Text("%.1f/%s", double(p.traffic.total()) / 1e6, p.taps ? cat(*p.taps).c_str() : "-");
        if (ImGui::IsItemHovered())
            ImGui::SetTooltip(
                "modelled memory traffic at 1920x1080 (MB) / texture lookups per pixel written");
        if (!oneMethod) {
            ImGui::TableNextColumn();
            drawOneLine(p.timingMethod);
        }
        ImGui::TableNextColumn();
        if (p.executed) {
            ImGui::TextUnformatted("ran");
        } else {
            std::string status(toString(p.status));
            bool saysStatus = p.reason.rfind(status, 0) == 0;
            drawOneLine(saysStatus || p.reason.empty() ? (p.reason.empty() ? status : p.reason)
                                                       : cat(status, ": ", p.reason));
        }
        ImGui::TableNextColumn();
        if (!p.stateLeft.empty() || !p.stateInherited.empty()) {
            // Inherited first: it is what the pass ran with without asking for it.
            std::string state;
            for (const std::string& s : p.stateInherited) state += cat(state.empty() ? "" : "; ", s);
            for (const std::string& s : p.stateLeft) state += cat(state.empty() ? "" : "; ", "left ", s);
            ImGui::PushStyleColor(ImGuiCol_Text, ui_style::kWarning);
            drawOneLine(state);
            ImGui::PopStyleColor();
        }
        ImGui::TableNextColumn();
        std::string wrote;
        for (const TextureUseRecord& w : p.writes)
            wrote += cat(wrote.empty() ? "" : ", ", w.texture, w.alsoRead ? " (+=)" : "");
        drawOneLine(wrote);
        if (!p.executed) ImGui::PopStyleColor();
        ImGui::PopID();
    }
    ImGui::EndTable();
}

}  // namespace fx
