#include "ui/view_controls.hpp"

#include <algorithm>
#include <cmath>

#include "base/log.hpp"
#include "base/words.hpp"
#include "gl/gl_formats.hpp"
#include "image/plot_axis.hpp"
#include "ui/pixel_probe.hpp"
#include "ui/ui_style.hpp"

namespace fx {
namespace {

bool channelToggle(const char* label, bool& on, const ImVec4& colour) {
    ImGui::PushStyleColor(ImGuiCol_Button,
                          on ? ImVec4(colour.x * 0.55f, colour.y * 0.55f, colour.z * 0.55f, 1.0f)
                             : ImVec4(0.16f, 0.16f, 0.18f, 1.0f));
    ImGui::PushStyleColor(ImGuiCol_ButtonHovered,
                          ImVec4(colour.x * 0.7f, colour.y * 0.7f, colour.z * 0.7f, 1.0f));
    ImGui::PushStyleColor(ImGuiCol_Text, on ? ImVec4(1, 1, 1, 1) : ui_style::kMuted);
    bool pressed = ImGui::Button(label, ImVec2(24, 0));
    ImGui::PopStyleColor(3);
    if (pressed) on = !on;
    return pressed;
}

void countSwatch(const ImVec4& colour, const char* what, long long count) {
    ImVec2 p = ImGui::GetCursorScreenPos();
    float side = ImGui::GetTextLineHeight() - 2.0f;
    ImGui::GetWindowDrawList()->AddRectFilled(ImVec2(p.x, p.y + 1), ImVec2(p.x + side, p.y + 1 + side),
                                              ui_style::packed(colour), 2.0f);
    ImGui::Dummy(ImVec2(side, side));
    ImGui::SameLine(0.0f, 4.0f);
    if (count > 0) {
        ImGui::Text("%s %lld", what, count);
    } else {
        ImGui::TextDisabled("%s 0", what);
    }
}

}  // namespace

bool autoFitRange(ViewSettings& s, const TextureAnalysis& a) {
    float low = 0.0f, high = 1.0f;
    if (!a.rangeOf(s.channels, low, high)) return false;
    if (high <= low) high = low + std::max(std::abs(low) * 1e-3f, 1e-6f);
    s.rangeLow = low;
    s.rangeHigh = high;
    return true;
}

void drawViewControls(ViewSettings& s, const TextureSource& source, const TextureAnalysis* analysis) {
    const bool depth = isDepth(source.spec.format);
    const int channels = readbackChannelCount(source.spec.format);

    // Level, channels, transform, exposure; then the range. Items flow onto a new row when the
    // inspector is narrow.
    bool first = true;
    auto next = [&](float width, float spacing = -1.0f) {
        if (!first) ui_style::continueRow(width, spacing);
        first = false;
    };
    if (source.levels() > 1) {
        next(150.0f);
        ImGui::SetNextItemWidth(110);
        ImGui::SliderInt((say("view.mip") + "###mip").c_str(), &s.level, 0, source.levels() - 1);
    }
    if (!depth && channels > 1) {
        static const char* names[4] = {"R", "G", "B", "A"};
        next(float(channels) * 26.0f, 14.0f);
        for (int c = 0; c < channels; ++c) {
            if (c > 0) ImGui::SameLine(0.0f, 2.0f);
            ImGui::PushID(c);
            channelToggle(names[c], s.channels[std::size_t(c)], ui_style::channelColour(c));
            if (ImGui::IsItemHovered()) {
                ImGui::SetTooltip("%s", say(c == 3 ? "view.alphaHelp" : "view.channelHelp").c_str());
            }
            ImGui::PopID();
        }
    }
    next(150.0f, 14.0f);
    ImGui::SetNextItemWidth(150);
    if (ImGui::BeginCombo("##transform", toString(s.transform).data())) {
        for (int t = 0; t < kDisplayTransformCount; ++t) {
            auto choice = static_cast<DisplayTransform>(t);
            if (ImGui::Selectable(toString(choice).data(), choice == s.transform)) s.transform = choice;
        }
        ImGui::EndCombo();
    }
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", say("view.transformHelp").c_str());
    next(110.0f);
    ImGui::SetNextItemWidth(90);
    ImGui::DragFloat("EV", &s.exposureStops, 0.05f, -20.0f, 20.0f, "%+.2f");
    if (ImGui::IsItemHovered()) {
        ImGui::SetTooltip("%s", say("view.exposureHelp").c_str());
    }

    // The range.
    ImGui::SetNextItemWidth(200);
    float speed = std::max(std::abs(s.rangeHigh - s.rangeLow) * 0.005f, 1e-5f);
    ImGui::DragFloatRange2((say("view.range") + "###range").c_str(), &s.rangeLow, &s.rangeHigh, speed, 0.0f,
                           0.0f, "%.4g", "%.4g");
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", say("view.rangeHelp").c_str());
    ui_style::continueRow(70.0f);
    if (ImGui::Button((say("view.autoFit") + "###auto-fit").c_str()) && analysis) autoFitRange(s, *analysis);
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("%s",
                          say(depth && s.linearDepth ? "view.autoFitDepthHelp" : "view.autoFitHelp").c_str());
    ui_style::continueRow(40.0f);
    if (ImGui::Button("0..1")) {
        s.rangeLow = 0.0f;
        s.rangeHigh = 1.0f;
        s.exposureStops = 0.0f;
    }
    if (depth) {
        ui_style::continueRow(110.0f, 12.0f);
        if (ImGui::Checkbox((say("view.linearDepth") + "###linear depth").c_str(), &s.linearDepth))
            s.autoFitPending = true;
        if (ImGui::IsItemHovered()) {
            ImGui::SetTooltip(
                "%s", say("view.linearDepthHelp", {{"near", cat(s.cameraNear)}, {"far", cat(s.cameraFar)}})
                          .c_str());
        }
    }

    // The highlight and its counts.
    ImGui::Checkbox((say("view.mark") + "###mark").c_str(), &s.highlightSpecial);
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", say("view.markHelp").c_str());
    if (analysis) {
        ImGui::SameLine();
        countSwatch(ui_style::kNan, "NaN", static_cast<long long>(analysis->nanTexels));
        ui_style::continueRow(60.0f, 12.0f);
        countSwatch(ui_style::kInf, "Inf", static_cast<long long>(analysis->infTexels));
        ui_style::continueRow(90.0f, 12.0f);
        countSwatch(ui_style::kNegative, say("view.negative").c_str(),
                    static_cast<long long>(analysis->negativeTexels));
        ui_style::continueRow(50.0f, 12.0f);
        ImGui::TextDisabled("%s", say("view.texels").c_str());
    } else {
        ImGui::SameLine();
        ImGui::TextDisabled("%s", say("view.counting").c_str());
    }
}

void drawHistogram(const TextureAnalysis& a, ViewSettings& s, ImVec2 size) {
    const ValueHistogram& h = a.histogram;
    ImDrawList* draw = ImGui::GetWindowDrawList();
    const ImVec2 p0 = ImGui::GetCursorScreenPos();
    const ImVec2 p1(p0.x + size.x, p0.y + size.y);
    ImGui::InvisibleButton("histogram", size);
    draw->AddRectFilled(p0, p1, IM_COL32(20, 20, 24, 255), 3.0f);

    // Positions along the histogram's own axis (linear or logarithmic), clamped to the frame.
    auto xOf = [&](double v) {
        return p0.x + 4.0f + float(std::clamp(h.fraction(v), 0.0, 1.0)) * (size.x - 8.0f);
    };
    auto valueAt = [&](float x) {
        double f = std::clamp(double(x - p0.x - 4.0f) / double(size.x - 8.0f), 0.0, 1.0);
        return float(h.logarithmic ? h.low * std::pow(double(h.high) / h.low, f)
                                   : h.low + f * (double(h.high) - h.low));
    };
    if (ImGui::IsItemActive()) {
        // Drag across the histogram to choose a range.
        ImGuiIO& io = ImGui::GetIO();
        float a0 = valueAt(io.MouseClickedPos[0].x), a1 = valueAt(io.MousePos.x);
        if (std::abs(io.MousePos.x - io.MouseClickedPos[0].x) > 3.0f) {
            s.rangeLow = std::min(a0, a1);
            s.rangeHigh = std::max(a0, a1);
        }
    }

    const float base = p1.y - 3.0f, top = p0.y + 3.0f;
    const double sqrtPeak = std::sqrt(double(std::max<std::uint32_t>(h.peak, 1)));
    for (int c = 0; c < h.channels && c < 4; ++c) {
        if (!s.channels[std::size_t(c)] && h.channels > 1) continue;
        const auto& counts = h.counts[std::size_t(c)];
        const int bins = int(counts.size());
        ImVec4 colour = h.channels == 1 ? ImVec4(0.85f, 0.85f, 0.85f, 1.0f) : ui_style::channelColour(c);
        for (int b = 0; b < bins; ++b) {
            if (counts[std::size_t(b)] == 0) continue;
            float x0 = p0.x + 4.0f + float(b) / float(bins) * (size.x - 8.0f);
            float x1 = std::max(p0.x + 4.0f + float(b + 1) / float(bins) * (size.x - 8.0f), x0 + 1.0f);
            float y = base - float(std::sqrt(double(counts[std::size_t(b)])) / sqrtPeak) * (base - top);
            draw->AddRectFilled(ImVec2(x0, y), ImVec2(x1, base), ui_style::packed(colour, 0.45f));
        }
    }
    // The range: black point and white point.
    const ImU32 rangeColour = IM_COL32(255, 255, 255, 200);
    draw->AddLine(ImVec2(xOf(s.rangeLow), top), ImVec2(xOf(s.rangeLow), base), rangeColour, 1.5f);
    draw->AddLine(ImVec2(xOf(s.rangeHigh), top), ImVec2(xOf(s.rangeHigh), base), rangeColour, 1.5f);
    std::string lowText = (h.logarithmic ? say("view.logFrom") + " " : "") + formatValue(h.low);
    std::string highText = formatValue(h.high);
    draw->AddText(ImVec2(p0.x + 5, p0.y + 2), IM_COL32(170, 170, 170, 255), lowText.c_str());
    ImVec2 hs = ImGui::CalcTextSize(highText.c_str());
    draw->AddText(ImVec2(p1.x - hs.x - 5, p0.y + 2), IM_COL32(170, 170, 170, 255), highText.c_str());
    if (ImGui::IsItemHovered()) {
        std::string text = say(a.linearDepth ? "view.histogramDepth" : "view.histogram",
                               {{"low", exactFloatText(h.low)}, {"high", exactFloatText(h.high)}});
        if (a.farPlaneTexels > 0) text += "\n" + say("view.farPlane", {{"count", cat(a.farPlaneTexels)}});
        text += "\n" + say("view.dragRange");
        ImGui::SetTooltip("%s", text.c_str());
    }
}

}  // namespace fx
