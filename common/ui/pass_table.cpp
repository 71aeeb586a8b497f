#include "ui/pass_table.hpp"

#include <string>

#include <imgui.h>

#include "base/log.hpp"
#include "ui/ui_style.hpp"

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

    const ImGuiTableFlags flags = ImGuiTableFlags_RowBg | ImGuiTableFlags_BordersInnerV |
                                  ImGuiTableFlags_Resizable | ImGuiTableFlags_ScrollY |
                                  ImGuiTableFlags_SizingStretchProp;
    if (!ImGui::BeginTable("passes", columns, flags)) return;
    ImGui::TableSetupScrollFreeze(0, 1);
    ImGui::TableSetupColumn("#", ImGuiTableColumnFlags_WidthFixed, 18.0f);
    ImGui::TableSetupColumn("pass", ImGuiTableColumnFlags_WidthStretch, 1.6f);
    ImGui::TableSetupColumn(copyMs > 0.0 ? "ms (copies)" : "ms", ImGuiTableColumnFlags_WidthFixed,
                            copyMs > 0.0 ? 104.0f : 52.0f);
    ImGui::TableSetupColumn("share", ImGuiTableColumnFlags_WidthFixed, 64.0f);
    // The cost model in one narrow column (the table shares a column with the lesson's panels).
    ImGui::TableSetupColumn("MB/taps", ImGuiTableColumnFlags_WidthFixed, 62.0f);
    if (!oneMethod) ImGui::TableSetupColumn("timed by", ImGuiTableColumnFlags_WidthStretch, 1.0f);
    ImGui::TableSetupColumn("ran / why not", ImGuiTableColumnFlags_WidthStretch, 1.8f);
    ImGui::TableSetupColumn("state inherited / left", ImGuiTableColumnFlags_WidthStretch, 1.6f);
    ImGui::TableSetupColumn("wrote", ImGuiTableColumnFlags_WidthStretch, 1.4f);
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
        ImGui::PushTextWrapPos(0.0f);
        ImGui::TextUnformatted(p.name.c_str());
        ImGui::PopTextWrapPos();
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
            ImGui::PushTextWrapPos(0.0f);
            ImGui::TextUnformatted(p.timingMethod.c_str());
            ImGui::PopTextWrapPos();
        }
        ImGui::TableNextColumn();
        if (p.executed) {
            ImGui::TextUnformatted("ran");
        } else {
            ImGui::PushTextWrapPos(0.0f);
            std::string status(toString(p.status));
            bool saysStatus = p.reason.rfind(status, 0) == 0;
            ImGui::TextUnformatted(saysStatus || p.reason.empty()
                                       ? (p.reason.empty() ? status : p.reason).c_str()
                                       : cat(status, ": ", p.reason).c_str());
            ImGui::PopTextWrapPos();
        }
        ImGui::TableNextColumn();
        if (!p.stateLeft.empty() || !p.stateInherited.empty()) {
            ImGui::PushStyleColor(ImGuiCol_Text, ui_style::kWarning);
            ImGui::PushTextWrapPos(0.0f);
            // Inherited first: it is what the pass ran with without asking for it.
            for (const std::string& s : p.stateInherited) ImGui::TextUnformatted(s.c_str());
            for (const std::string& s : p.stateLeft) ImGui::TextUnformatted(cat("left ", s).c_str());
            ImGui::PopTextWrapPos();
            ImGui::PopStyleColor();
        }
        ImGui::TableNextColumn();
        for (const TextureUseRecord& w : p.writes) {
            ImGui::TextUnformatted(w.alsoRead ? cat(w.texture, " (+=)").c_str() : w.texture.c_str());
        }
        if (!p.executed) ImGui::PopStyleColor();
        ImGui::PopID();
    }
    ImGui::EndTable();
}

}  // namespace fx
