#include "ui/lesson_panel.hpp"

#include <algorithm>
#include <cstdio>
#include <string>

#include <imgui.h>

#include "base/log.hpp"
#include "base/words.hpp"
#include "ui/markdown_view.hpp"
#include "ui/ui_style.hpp"

namespace fx {

namespace {

// A source's words: "source.default", "source.command_line" ...
std::string sourceWords(ParamSource source) {
    std::string key = cat("source.", toString(source));
    for (char& c : key) {
        if (c == ' ') c = '_';
    }
    return say(key);
}

// The value's widget; true when the user changed it this frame.
bool drawParamWidget(const Param& p) {
    // The shown words: the name as typed on the command line, and beside it the label where the
    // language has one ("閾値 (threshold)"); "##name" keeps the widget's identity in every language.
    const std::string label = p.label();
    const std::string words = label == p.name ? p.name : cat(label, " (", p.name, ")");
    const std::string shown = words + "##" + p.name;
    if (label != p.name) {
        // A label beside the name is longer than the name alone: the widget leaves it, and the source
        // tag after it, the room they need (down to a third of the row for the widget).
        const ImGuiStyle& style = ImGui::GetStyle();
        const std::string tag = cat("[", sourceWords(p.source()), "]");
        const float avail = ImGui::GetContentRegionAvail().x;
        const float text = ImGui::CalcTextSize(words.c_str()).x + ImGui::CalcTextSize(tag.c_str()).x +
                           2.0f * style.ItemInnerSpacing.x + style.ItemSpacing.x;
        ImGui::SetNextItemWidth(std::max(avail - text, avail / 3.0f));
    }
    switch (p.type) {
        // The slider's span (a setting's may be narrower than its range: the values a lesson is shown
        // with); Ctrl+click types any value.
        case ParamType::Float:
            return ImGui::SliderFloat(shown.c_str(), p.floatValue, float(p.sliderMin), float(p.sliderMax),
                                      p.sliderFormat().c_str());
        case ParamType::Int:
            return ImGui::SliderInt(shown.c_str(), p.intValue, int(p.sliderMin), int(p.sliderMax),
                                    p.sliderFormat().c_str());
        case ParamType::Bool:
            return ImGui::Checkbox(shown.c_str(), p.boolValue);
        case ParamType::Choice: {
            bool changed = false;
            const char* current = p.choices.empty() ? "" : p.choices[std::size_t(*p.intValue)].c_str();
            if (ImGui::BeginCombo(shown.c_str(), current)) {
                for (std::size_t i = 0; i < p.choices.size(); ++i) {
                    if (ImGui::Selectable(p.choices[i].c_str(), int(i) == *p.intValue)) {
                        changed = *p.intValue != int(i);
                        *p.intValue = int(i);
                    }
                }
                ImGui::EndCombo();
            }
            return changed;
        }
    }
    return false;
}

void drawParam(ParamSet& params, const Param& p) {
    ImGui::PushID(p.name.c_str());
    if (drawParamWidget(p)) params.markEdited(p);
    bool hovered = ImGui::IsItemHovered();
    // Where the value came from, beside it: a teacher sees at once what the scene set.
    ParamSource source = p.source();
    ImGui::SameLine();
    std::string tag = cat("[", sourceWords(source), "]");
    if (source == ParamSource::lessonDefault) {
        ImGui::TextDisabled("%s", tag.c_str());
    } else {
        ImGui::TextColored(ui_style::kHeading, "%s", tag.c_str());
    }
    hovered = hovered || ImGui::IsItemHovered();
    if (hovered) {
        const WordArgs args{{"source", sourceWords(source)}, {"setting", p.sceneSetting}};
        std::string from = say(source == ParamSource::scene ? "param.fromScene" : "param.from", args);
        if (!p.sceneSetting.empty() && source != ParamSource::scene) from += say("param.sceneStarts", args);
        ImGui::SetTooltip("%s\n(%s%s)\n%s", p.help().c_str(), p.shownRangeText().c_str(),
                          p.knob ? say("param.knob").c_str() : "", from.c_str());
    }
    ImGui::PopID();
}

}  // namespace

void drawParams(ParamSet& params, int step) {
    // The step's own parameters first; those that act only in other steps folded underneath, so a
    // step's panel shows what changes its picture and the rest stays one click away.
    std::vector<const Param*> others;
    for (const Param& p : params.all()) {
        if (p.actsIn(step))
            drawParam(params, p);
        else
            others.push_back(&p);
    }
    if (others.empty()) return;
    if (ImGui::TreeNode("other steps", "%s",
                        say("panel.otherSteps", {{"count", cat(others.size())}}).c_str())) {
        for (const Param* p : others) drawParam(params, *p);
        ImGui::TreePop();
    }
}

namespace {

// The step's text scrolls in a region of its own, so the parameters under it stay in reach: as tall
// as the text was last frame, at most about half the window. Each step has its own region, so a new
// step starts at the top of its text.
void drawStepText(const std::string& text, int step) {
    if (text.empty()) return;
    ImGui::PushID(step);
    ImGuiStorage* storage = ImGui::GetStateStorage();
    const ImGuiID key = ImGui::GetID("step text height");
    const float wanted = storage->GetFloat(key, 8.0f * ImGui::GetTextLineHeightWithSpacing());
    const float most =
        std::max(ImGui::GetWindowHeight() * 0.5f, 6.0f * ImGui::GetTextLineHeightWithSpacing());
    ImGui::BeginChild("step text", ImVec2(0.0f, std::min(wanted, most)), false);
    drawMarkdown(text);
    storage->SetFloat(key, ImGui::GetCursorPosY() + ImGui::GetStyle().WindowPadding.y);
    ImGui::EndChild();
    ImGui::PopID();
}

}  // namespace

void drawLessonWindowContents(const OverlayModel& m) {
    if (m.step && !m.steps.empty()) {
        int& step = *m.step;
        ImGui::TextUnformatted(
            say("panel.stepOf", {{"step", cat(step + 1)}, {"steps", cat(m.steps.size())}}).c_str());
        ImGui::SameLine();
        if (ImGui::ArrowButton("prev", ImGuiDir_Left) && step > 0) --step;
        ImGui::SameLine();
        if (ImGui::ArrowButton("next", ImGuiDir_Right) && step + 1 < int(m.steps.size())) ++step;
        if (m.languages.size() > 1 && m.setLanguage) {
            // The text's language: lesson.md or its translation (--lang on the command line).
            for (const std::string& language : m.languages) {
                ImGui::SameLine();
                if (ImGui::RadioButton(language.c_str(), language == m.language)) m.setLanguage(language);
            }
        }
        // What the teacher just did, confirmed where the eye is; then while the clock stands still, the
        // picture compares or gives way to a slow renderer, the lesson window says so (wrapped).
        if (!m.notice.empty()) {
            ImGui::PushStyleColor(ImGuiCol_Text, ui_style::kNotice);
            ImGui::TextWrapped("%s", m.notice.c_str());
            ImGui::PopStyleColor();
        }
        for (const std::string* line : {&m.clock, &m.compare, &m.pictureScale}) {
            if (line->empty()) continue;
            ImGui::PushStyleColor(ImGuiCol_Text, ui_style::kWarning);
            ImGui::TextWrapped("%s", line->c_str());
            ImGui::PopStyleColor();
        }
        const LessonStep& s = m.steps[std::size_t(step)];
        ImGui::PushTextWrapPos(0.0f);
        ImGui::PushStyleColor(ImGuiCol_Text, ui_style::kHeading);
        ImGui::TextUnformatted(s.title.c_str());
        ImGui::PopStyleColor();
        if (!s.note.empty()) ImGui::TextDisabled("%s", s.note.c_str());
        ImGui::PopTextWrapPos();
        drawStepText(s.text, step);
    }
    if (!m.textError.empty()) {
        ImGui::TextColored(ui_style::kError, "%s", say("panel.textError").c_str());
        ImGui::PushTextWrapPos(0.0f);
        ImGui::TextUnformatted(m.textError.c_str());
        ImGui::PopTextWrapPos();
    }
    if (!m.shaderErrors.empty()) {
        ImGui::Separator();
        ImGui::TextColored(ui_style::kError, "%s", say("panel.shaderErrors").c_str());
        for (auto& e : m.shaderErrors) ImGui::TextWrapped("%s", e.c_str());
    }
    const int step = m.step ? *m.step : 0;
    if (m.params && !m.params->all().empty() &&
        ImGui::CollapsingHeader((say("panel.parameters") + "###parameters").c_str(),
                                ImGuiTreeNodeFlags_DefaultOpen)) {
        drawParams(*m.params, step);
        if (ImGui::Button((say("panel.reset") + "###reset").c_str())) m.params->resetAll();
        if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", say("panel.resetHelp").c_str());
        if (m.onSavePreset) {
            ImGui::SameLine();
            if (ImGui::Button((say("panel.savePreset") + "###save preset").c_str())) m.onSavePreset();
        }
        if (m.onLoadPreset) {
            ImGui::SameLine();
            if (ImGui::Button((say("panel.loadPreset") + "###load preset").c_str())) m.onLoadPreset();
        }
    }
    if (m.lessonPanel && ImGui::CollapsingHeader((say("panel.lesson") + "###lesson panel").c_str(),
                                                 ImGuiTreeNodeFlags_DefaultOpen))
        m.lessonPanel();
    ImGui::Separator();
    ImGui::TextDisabled("%s", m.renderer.c_str());
    if (m.frame) {
        char ms[32];
        std::snprintf(ms, sizeof ms, "%.2f", m.frameMs);
        ImGui::TextDisabled("%s", say("panel.frameMs", {{"ms", ms}, {"timing", m.timing}}).c_str());
    }
    if (!m.clockRate.empty()) {
        ImGui::PushTextWrapPos(0.0f);
        ImGui::TextDisabled("%s", m.clockRate.c_str());
        ImGui::PopTextWrapPos();
    }
    if (m.glErrors > 0)
        ImGui::TextColored(ui_style::kError, "%s",
                           say("panel.glErrors", {{"count", cat(m.glErrors)}}).c_str());
    if (m.glExpectedErrors > 0) {
        ImGui::TextColored(ui_style::kWarning, "%s",
                           say("panel.glExpectedErrors", {{"count", cat(m.glExpectedErrors)}}).c_str());
    }
    if (!m.status.empty()) ImGui::TextDisabled("%s", m.status.c_str());
}

}  // namespace fx
