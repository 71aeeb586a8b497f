#include "ui/cost_panel.hpp"

#include <algorithm>
#include <cmath>

#include "base/log.hpp"
#include "image/plot_axis.hpp"
#include "ui/ui_style.hpp"

namespace fx {
namespace {

// The plot's colours on the overlay's dark background.
const ImU32 kBackground = IM_COL32(22, 22, 26, 255);
const ImU32 kGrid = IM_COL32(52, 52, 60, 255);
const ImU32 kInk = IM_COL32(205, 205, 205, 255);
const ImU32 kPoint = IM_COL32(96, 150, 230, 255);
const ImU32 kCurrent = IM_COL32(235, 64, 64, 255);
const ImU32 kFront = IM_COL32(245, 121, 0, 255);

void diamond(ImDrawList* draw, ImVec2 c, float r, ImU32 colour, bool filled) {
    ImVec2 p[4] = {{c.x, c.y - r}, {c.x + r, c.y}, {c.x, c.y + r}, {c.x - r, c.y}};
    if (filled) {
        draw->AddConvexPolyFilled(p, 4, colour);
    } else {
        draw->AddPolyline(p, 4, colour, ImDrawFlags_Closed, 1.5f);
    }
}

}  // namespace

std::vector<std::string> sweptKnobs(const SweepResult& result) {
    std::vector<std::string> knobs;
    for (const SweepPoint& p : result.points) {
        if (std::find(knobs.begin(), knobs.end(), p.knob) == knobs.end()) knobs.push_back(p.knob);
    }
    return knobs;
}

ScatterPlot sweepPlot(const SweepResult& result, const std::string& knob) {
    ScatterPlot plot;
    plot.xLabel = "frame time (ms)";
    plot.yLabel = "RMSE vs reference";
    for (const SweepPoint& p : result.points) {
        if (p.knob == knob) plot.points.push_back({p.value, p.medianMs, p.rmse, p.reference, p.current});
    }
    return plot;
}

void drawScatterPlot(const ScatterPlot& plot, ImVec2 size) {
    const ImVec2 origin = ImGui::GetCursorScreenPos();
    ImDrawList* draw = ImGui::GetWindowDrawList();
    // The y label is drawn inside the frame, so the layout need not make room for it on the left.
    ScatterPlot forLayout = plot;
    forLayout.yLabel.clear();
    const PlotLayout layout = layoutScatterPlot(forLayout, int(size.x), int(size.y));
    auto at = [&](double x, double y) {
        return ImVec2(origin.x + float(layout.pixelX(x)), origin.y + float(layout.pixelY(y)));
    };
    const float left = origin.x + float(layout.left), right = origin.x + float(layout.right);
    const float top = origin.y + float(layout.top), bottom = origin.y + float(layout.bottom);
    const float textHeight = ImGui::GetTextLineHeight();
    // The layout keeps room below the frame for the bench picture's larger font; ImGui's text needs
    // less, so the widget ends under the x label and the notes.
    const float used =
        float(layout.bottom) + 2.0f * textHeight + 16.0f + float(layout.notes.size()) * (textHeight + 2.0f);
    draw->AddRectFilled(origin, ImVec2(origin.x + size.x, origin.y + used), kBackground, 4.0f);

    for (std::size_t i = 0; i < layout.xAxis.ticks.size(); ++i) {
        float x = at(layout.xAxis.ticks[i], layout.yAxis.low).x;
        draw->AddLine(ImVec2(x, top), ImVec2(x, bottom), kGrid);
        const std::string& label = layout.xAxis.tickLabels[i];
        float w = ImGui::CalcTextSize(label.c_str()).x;
        draw->AddText(ImVec2(x - w / 2, bottom + 4), kInk, label.c_str());
    }
    for (std::size_t i = 0; i < layout.yAxis.ticks.size(); ++i) {
        float y = origin.y + float(layout.pixelY(layout.yAxis.ticks[i]));
        draw->AddLine(ImVec2(left, y), ImVec2(right, y), kGrid);
        const std::string& label = layout.yAxis.tickLabels[i];
        float w = ImGui::CalcTextSize(label.c_str()).x;
        draw->AddText(ImVec2(left - w - 6, y - textHeight / 2), kInk, label.c_str());
    }
    draw->AddRect(ImVec2(left, top), ImVec2(right, bottom), kInk);
    float xw = ImGui::CalcTextSize(plot.xLabel.c_str()).x;
    draw->AddText(ImVec2((left + right - xw) / 2, bottom + 6 + textHeight), kInk, plot.xLabel.c_str());
    draw->AddText(ImVec2(left, top - textHeight - 3), kInk, plot.yLabel.c_str());

    // The front, then the points on top of it.
    std::vector<std::size_t> front = paretoFront(plot.points);
    for (std::size_t i = 1; i < front.size(); ++i) {
        const PlotPoint& a = plot.points[front[i - 1]];
        const PlotPoint& b = plot.points[front[i]];
        draw->AddLine(at(a.x, a.y), at(b.x, b.y), kFront, 2.0f);
    }
    const ImVec2 mouse = ImGui::GetIO().MousePos;
    const PlotPoint* hovered = nullptr;
    for (const PlotPoint& p : plot.points) {
        if (!layout.isDrawable(p)) continue;
        ImVec2 c = at(p.x, p.y);
        if (p.isReference) {
            diamond(draw, c, 6.0f, kInk, true);
        } else {
            draw->AddCircleFilled(c, 4.5f, p.isCurrent ? kCurrent : kPoint);
        }
        if (p.isCurrent) draw->AddCircle(c, 9.0f, kCurrent, 20, 2.0f);
        draw->AddText(ImVec2(c.x + 8, c.y - textHeight - 1), p.isCurrent ? kCurrent : kInk, p.label.c_str());
        if (std::abs(mouse.x - c.x) < 7 && std::abs(mouse.y - c.y) < 7) hovered = &p;
    }
    float noteY = bottom + 2.0f * textHeight + 12.0f;
    for (const std::string& note : layout.notes) {
        draw->AddText(ImVec2(origin.x + 6, noteY), IM_COL32(140, 140, 140, 255), note.c_str());
        noteY += textHeight + 2.0f;
    }
    ImGui::Dummy(ImVec2(size.x, used));
    if (hovered) {
        ImGui::SetTooltip("%s%s%s\n%s ms, RMSE %s", hovered->label.c_str(),
                          hovered->isReference ? " (reference)" : "", hovered->isCurrent ? " (in use)" : "",
                          formatValue(hovered->x).c_str(), formatValue(hovered->y).c_str());
    }
}

void CostPanel::setResult(SweepResult result) {
    result_ = std::move(result);
    auto knobs = sweptKnobs(*result_);
    if (std::find(knobs.begin(), knobs.end(), knob_) == knobs.end())
        knob_ = knobs.empty() ? "" : knobs.front();
}

void CostPanel::runPending(const Measure& measure) {
    if (!pending_) return;
    pending_ = false;
    if (measure) setResult(measure());
}

void CostPanel::draw(const Measure& measure) {
    if (!measure) {
        ImGui::TextDisabled("no sweep available");
        ImGui::PushTextWrapPos(0.0f);
        ImGui::TextDisabled(
            "(this app does not provide a measurement; ./fxlab bench sweeps the knobs from the "
            "command line)");
        ImGui::PopTextWrapPos();
        if (!result_) return;
    } else {
        ImGui::BeginDisabled(pending_);
        if (ImGui::Button(pending_ ? "measuring..." : "measure")) pending_ = true;
        ImGui::EndDisabled();
        if (ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled)) {
            ImGui::SetTooltip(
                "render the lesson at every setting of each quality knob (the others at their\n"
                "references), time it, and compare its picture with the reference setting's");
        }
    }
    if (!result_) {
        ImGui::SameLine();
        ImGui::TextDisabled("time against error for each quality setting");
        return;
    }
    const SweepResult& r = *result_;
    if (r.points.empty()) {
        ImGui::TextDisabled("this lesson has no quality knobs");
        return;
    }
    ImGui::SameLine();
    ImGui::TextWrapped("%dx%d, timed by %s; one full-screen copy takes %.3f ms", r.width, r.height,
                       r.timingMethod.c_str(), r.copyMs);
    auto knobs = sweptKnobs(r);
    if (knobs.size() > 1) {
        ImGui::SetNextItemWidth(180);
        if (ImGui::BeginCombo("knob", knob_.c_str())) {
            for (const std::string& k : knobs) {
                if (ImGui::Selectable(k.c_str(), k == knob_)) knob_ = k;
            }
            ImGui::EndCombo();
        }
    } else {
        ImGui::Text("knob: %s", knob_.c_str());
    }
    const float width = std::max(ImGui::GetContentRegionAvail().x, 200.0f);
    drawScatterPlot(sweepPlot(r, knob_), ImVec2(width, std::clamp(width * 0.45f, 200.0f, 320.0f)));

    const ImGuiTableFlags flags =
        ImGuiTableFlags_RowBg | ImGuiTableFlags_BordersInnerV | ImGuiTableFlags_SizingStretchSame;
    if (ImGui::BeginTable("points", 5, flags)) {
        ImGui::TableSetupColumn("setting");
        ImGui::TableSetupColumn("frame ms");
        ImGui::TableSetupColumn("x copy");
        ImGui::TableSetupColumn("RMSE");
        ImGui::TableSetupColumn("PSNR dB");
        ImGui::TableHeadersRow();
        for (const SweepPoint& p : r.points) {
            if (p.knob != knob_) continue;
            ImGui::TableNextRow();
            ImGui::TableNextColumn();
            std::string label =
                p.value + (p.reference ? " (reference)" : "") + (p.current ? " (in use)" : "");
            if (p.current) {
                ImGui::TextColored(ImVec4(0.92f, 0.25f, 0.25f, 1.0f), "%s", label.c_str());
            } else {
                ImGui::TextUnformatted(label.c_str());
            }
            ImGui::TableNextColumn();
            ImGui::Text("%.3f", p.medianMs);
            ImGui::TableNextColumn();
            ImGui::Text("%.2f", p.copyMultiple);
            ImGui::TableNextColumn();
            ImGui::TextUnformatted(formatValue(p.rmse).c_str());
            ImGui::TableNextColumn();
            ImGui::TextUnformatted(p.reference ? "-" : formatValue(p.psnr).c_str());
        }
        ImGui::EndTable();
    }
}

}  // namespace fx
