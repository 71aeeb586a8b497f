#include "ui/cost_panel.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "base/log.hpp"
#include "base/words.hpp"
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
const ImU32 kSpread = IM_COL32(120, 135, 165, 255);

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
    const bool byCopy = result.copyMs > 0;
    const WordArgs frames{{"frames", cat(result.frames)}};
    plot.xLabel = say(byCopy ? "cost.xCopies" : "cost.xMs", frames);
    plot.yLabel = say("cost.yRmse");
    for (const SweepPoint& p : result.points) {
        if (p.knob != knob) continue;
        PlotPoint point{p.value, byCopy ? p.copyMultiple : p.medianMs, p.rmse, p.reference, p.current};
        if (byCopy) point.xLow = p.minMultiple, point.xHigh = p.maxMultiple;
        plot.points.push_back(point);
    }
    return plot;
}

void drawScatterPlot(const ScatterPlot& given, ImVec2 size) {
    const ScatterPlot plot = groupEqualCosts(given);
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

    // Spreads, the front, then the points on top of them.
    std::vector<PlotBox> spreads;
    for (const PlotPoint& p : plot.points) {
        if (!layout.isDrawable(p) || !p.hasSpread()) continue;
        ImVec2 a = at(p.lowX(), p.y), b = at(p.highX(), p.y);
        draw->AddLine(a, b, kSpread, 1.5f);
        draw->AddLine(ImVec2(a.x, a.y - 4), ImVec2(a.x, a.y + 4), kSpread, 1.5f);
        draw->AddLine(ImVec2(b.x, b.y - 4), ImVec2(b.x, b.y + 4), kSpread, 1.5f);
        spreads.push_back({a.x - 1, a.y - 4, b.x + 1, b.y + 4});  // labels keep off the bar too
    }
    std::vector<std::size_t> front = paretoFront(plot.points);
    for (std::size_t i = 1; i < front.size(); ++i) {
        const PlotPoint& a = plot.points[front[i - 1]];
        const PlotPoint& b = plot.points[front[i]];
        draw->AddLine(at(a.x, a.y), at(b.x, b.y), kFront, 2.0f);
    }
    const ImVec2 mouse = ImGui::GetIO().MousePos;
    const PlotPoint* hovered = nullptr;
    std::vector<PlotBox> markers = spreads;
    std::vector<LabelRequest> labels;
    std::vector<const PlotPoint*> labelled;
    for (const PlotPoint& p : plot.points) {
        if (!layout.isDrawable(p)) continue;
        ImVec2 c = at(p.x, p.y);
        if (p.isReference) {
            diamond(draw, c, 6.0f, kInk, true);
        } else {
            draw->AddCircleFilled(c, 4.5f, p.isCurrent ? kCurrent : kPoint);
        }
        if (p.isCurrent) draw->AddCircle(c, 9.0f, kCurrent, 20, 2.0f);
        const float r = p.isCurrent ? 10.0f : 7.0f;
        markers.push_back({c.x - r, c.y - r, c.x + r, c.y + r});
        ImVec2 text = ImGui::CalcTextSize(p.label.c_str());
        labels.push_back({c.x, c.y, r, text.x, text.y});
        labelled.push_back(&p);
        if (std::abs(mouse.x - c.x) < 7 && std::abs(mouse.y - c.y) < 7) hovered = &p;
    }
    // The reference and the current setting choose their spots first; a label with no free spot is
    // left out (hovering shows it, and the table lists every row).
    std::vector<std::size_t> order(labels.size());
    for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
    std::stable_partition(order.begin(), order.end(),
                          [&](std::size_t i) { return labelled[i]->isReference || labelled[i]->isCurrent; });
    std::vector<LabelRequest> ordered;
    for (std::size_t i : order) ordered.push_back(labels[i]);
    const auto placed = placeLabels(ordered, markers, {left, top, right, bottom});
    for (std::size_t k = 0; k < order.size(); ++k) {
        if (!placed[k]) continue;
        const PlotPoint& p = *labelled[order[k]];
        if (auto leader = labelLeader(ordered[k], *placed[k]))
            draw->AddLine(ImVec2(float(leader->x0), float(leader->y0)),
                          ImVec2(float(leader->x1), float(leader->y1)), kGrid + IM_COL32(60, 60, 60, 0),
                          1.0f);
        draw->AddText(ImVec2(float(placed[k]->x0), float(placed[k]->y0)), p.isCurrent ? kCurrent : kInk,
                      p.label.c_str());
    }
    float noteY = bottom + 2.0f * textHeight + 12.0f;
    for (const std::string& note : layout.notes) {
        draw->AddText(ImVec2(origin.x + 6, noteY), IM_COL32(140, 140, 140, 255), note.c_str());
        noteY += textHeight + 2.0f;
    }
    ImGui::Dummy(ImVec2(size.x, used));
    if (hovered) {
        ImGui::SetTooltip("%s%s%s\n%s (%s to %s), RMSE %s", hovered->label.c_str(),
                          hovered->isReference ? " (reference)" : "", hovered->isCurrent ? " (in use)" : "",
                          formatValue(hovered->x).c_str(), formatValue(hovered->lowX()).c_str(),
                          formatValue(hovered->highX()).c_str(), formatValue(hovered->y).c_str());
    }
}

void CostPanel::setResult(SweepResult result) {
    result_ = std::move(result);
    auto knobs = sweptKnobs(*result_);
    if (std::find(knobs.begin(), knobs.end(), knob_) == knobs.end())
        knob_ = knobs.empty() ? "" : knobs.front();
}

void CostPanel::runPending(const Measure& measure) {
    if (pending_) {
        pending_ = false;
        cancelled_.clear();
        running_ = measure ? measure() : nullptr;
        if (!running_) return;
    }
    if (!running_) return;
    // One slice per frame: the app keeps drawing, the bar moves, and Esc is read between slices.
    if (!running_->done()) running_->next();
    if (running_->done()) {
        setResult(running_->result());
        running_.reset();
    }
}

void CostPanel::cancel() {
    if (!running_ && !pending_) return;
    if (running_) {
        SweepProgress p = running_->progress();
        cancelled_ = say("cost.cancelled", {{"done", cat(p.done)}, {"total", cat(p.total)}});
    }
    running_.reset();  // puts the parameters back
    pending_ = false;
}

std::optional<SweepProgress> CostPanel::progress() const {
    if (!running_) return std::nullopt;
    return running_->progress();
}

void CostPanel::draw(const Measure& measure) {
    if (!measure) {
        ImGui::TextDisabled("%s", say("cost.noSweep").c_str());
        ImGui::PushTextWrapPos(0.0f);
        ImGui::TextDisabled("%s", say("cost.noSweepWhy").c_str());
        ImGui::PopTextWrapPos();
        if (!result_) return;
    } else if (measurePending()) {
        // The sweep under way: a bar, what comes next, and a way out.
        SweepProgress p = progress().value_or(SweepProgress{});
        const float fraction = float(p.fraction());
        std::string overlayText = say("cost.progress", {{"done", cat(p.done)}, {"total", cat(p.total)}});
        ImGui::ProgressBar(fraction, ImVec2(220, 0), overlayText.c_str());
        ImGui::SameLine();
        if (ImGui::Button((say("cost.cancel") + "###cancel").c_str()) ||
            ImGui::IsKeyPressed(ImGuiKey_Escape, false))
            cancel();
        ImGui::SameLine();
        if (p.frames > 0)
            ImGui::TextDisabled("%s",
                                say("cost.measuringFrame",
                                    {{"setting", p.next}, {"frame", cat(p.frame)}, {"frames", cat(p.frames)}})
                                    .c_str());
        else
            ImGui::TextDisabled("%s", say("cost.measuring", {{"setting", p.next}}).c_str());
    } else {
        if (ImGui::Button((say("cost.measure") + "###measure").c_str())) pending_ = true;
        if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", say("cost.measureHelp").c_str());
        if (!cancelled_.empty()) {
            ImGui::SameLine();
            ImGui::TextDisabled("%s", cancelled_.c_str());
        }
    }
    if (!result_) {
        ImGui::SameLine();
        ImGui::TextDisabled("%s", say("cost.what").c_str());
        return;
    }
    const SweepResult& r = *result_;
    if (r.points.empty()) {
        ImGui::TextDisabled("%s", say("cost.noKnobs").c_str());
        return;
    }
    ImGui::SameLine();
    char copyMs[32];
    std::snprintf(copyMs, sizeof copyMs, "%.3f", r.copyMs);
    ImGui::TextWrapped(
        "%s", say("cost.timedBy",
                  {{"size", cat(r.width, "x", r.height)}, {"method", r.timingMethod}, {"ms", copyMs}})
                  .c_str());
    auto knobs = sweptKnobs(r);
    if (knobs.size() > 1) {
        ImGui::SetNextItemWidth(180);
        if (ImGui::BeginCombo((say("cost.knob") + "###knob").c_str(), knob_.c_str())) {
            for (const std::string& k : knobs) {
                if (ImGui::Selectable(k.c_str(), k == knob_)) knob_ = k;
            }
            ImGui::EndCombo();
        }
    } else {
        ImGui::Text("%s: %s", say("cost.knob").c_str(), knob_.c_str());
    }
    const float width = std::max(ImGui::GetContentRegionAvail().x, 200.0f);
    drawScatterPlot(sweepPlot(r, knob_), ImVec2(width, std::clamp(width * 0.45f, 200.0f, 320.0f)));

    const ImGuiTableFlags flags =
        ImGuiTableFlags_RowBg | ImGuiTableFlags_BordersInnerV | ImGuiTableFlags_SizingStretchSame;
    if (ImGui::BeginTable("points", 6, flags)) {
        ImGui::TableSetupColumn(say("cost.setting").c_str());
        ImGui::TableSetupColumn(say("cost.frameMs").c_str());
        ImGui::TableSetupColumn(say("cost.xCopy").c_str());
        ImGui::TableSetupColumn(say("cost.minMax").c_str());
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
            ImGui::Text("%.2f-%.2f", p.minMultiple, p.maxMultiple);
            ImGui::TableNextColumn();
            ImGui::TextUnformatted(formatValue(p.rmse).c_str());
            ImGui::TableNextColumn();
            ImGui::TextUnformatted(p.reference ? "-" : formatValue(p.psnr).c_str());
        }
        ImGui::EndTable();
    }
}

}  // namespace fx
