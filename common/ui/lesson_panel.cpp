#include "ui/lesson_panel.hpp"

#include <algorithm>
#include <cstdio>
#include <string>

#include <imgui.h>

#include "base/log.hpp"
#include "base/words.hpp"
#include "ui/markdown_view.hpp"
#include "ui/ui_style.hpp"
#include "ui/word_wrap.hpp"

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

// Right-click on a parameter: keep its value in every step, or let it belong to this step again.
void pinMenu(ParamSet& params, const Param& p) {
    if (!ImGui::BeginPopupContextItem("pin")) return;
    bool pinned = p.pinned;
    if (ImGui::MenuItem(say("param.pinMenu").c_str(), nullptr, &pinned)) params.setPinned(p, pinned);
    ImGui::EndPopup();
}

void drawParam(ParamSet& params, const Param& p) {
    ImGui::PushID(p.name.c_str());
    if (drawParamWidget(p)) params.markEdited(p);
    bool hovered = ImGui::IsItemHovered();
    pinMenu(params, p);
    // Where the value came from, beside it: a teacher sees at once what the scene set, and which values
    // were changed here (they belong to this step: ParamSet::changeStep) or are kept in every step.
    ParamSource source = p.source();
    ImGui::SameLine();
    std::string tag = p.pinned                         ? say("param.pinnedTag")
                      : source == ParamSource::overlay ? say("param.changedTag")
                                                       : cat("[", sourceWords(source), "]");
    if (source == ParamSource::lessonDefault && !p.pinned) {
        ImGui::TextDisabled("%s", tag.c_str());
    } else {
        ImGui::TextColored(ui_style::kHeading, "%s", tag.c_str());
    }
    hovered = hovered || ImGui::IsItemHovered();
    pinMenu(params, p);
    if (hovered) {
        const WordArgs args{{"source", sourceWords(source)}, {"setting", p.sceneSetting}};
        std::string from = say(source == ParamSource::scene ? "param.fromScene" : "param.from", args);
        if (!p.sceneSetting.empty() && source != ParamSource::scene) from += say("param.sceneStarts", args);
        ImGui::SetTooltip("%s\n(%s%s)\n%s\n%s", p.help().c_str(), p.shownRangeText().c_str(),
                          p.knob ? say("param.knob").c_str() : "", from.c_str(),
                          say("param.stepNote").c_str());
    }
    ImGui::PopID();
}

}  // namespace

void drawParams(ParamSet& params, int step) {
    // Every name and its source tag fit beside the widgets ("grid_size [default]" was cut at the
    // column's edge): the widgets give up width for the widest, down to half the column.
    float widest = 0.0f;
    for (const Param& p : params.all())
        widest = std::max(widest, ImGui::CalcTextSize(p.name.c_str()).x +
                                      ImGui::CalcTextSize(cat("[", toString(p.source()), "]").c_str()).x);
    const ImGuiStyle& style = ImGui::GetStyle();
    const float labels = widest + 2.0f * style.ItemInnerSpacing.x + style.ItemSpacing.x +
                         ImGui::GetTreeNodeToLabelSpacing();  // the folded ones are indented
    ImGui::PushItemWidth(
        std::max(ImGui::GetContentRegionAvail().x - labels, 0.5f * ImGui::GetContentRegionAvail().x));
    // The step's own parameters first; those that act only in other steps folded underneath, so a
    // step's panel shows what changes its picture and the rest stays one click away.
    std::vector<const Param*> others;
    for (const Param& p : params.all()) {
        if (p.actsIn(step))
            drawParam(params, p);
        else
            others.push_back(&p);
    }
    if (!others.empty() &&
        ImGui::TreeNode("other steps", "%s",
                        say("panel.otherSteps", {{"count", cat(others.size())}}).c_str())) {
        for (const Param* p : others) drawParam(params, *p);
        ImGui::TreePop();
    }
    ImGui::PopItemWidth();
}

namespace {

// The step's text scrolls in a region of its own, so the parameters under it stay in reach: as tall
// as the text was last frame, at most about half the window. Each step has its own region, opened at
// the top of its text whenever the step is (`opened`).
void drawStepText(const std::string& text, int step, bool opened) {
    if (text.empty()) return;
    ImGui::PushID(step);
    ImGuiStorage* storage = ImGui::GetStateStorage();
    const ImGuiID key = ImGui::GetID("step text height");
    const float wanted = storage->GetFloat(key, 8.0f * ImGui::GetTextLineHeightWithSpacing());
    const float most =
        std::max(ImGui::GetWindowHeight() * 0.5f, 6.0f * ImGui::GetTextLineHeightWithSpacing());
    ImGui::BeginChild("step text", ImVec2(0.0f, std::min(wanted, most)), false);
    if (opened) ImGui::SetScrollY(0.0f);
    drawMarkdown(text);
    storage->SetFloat(key, ImGui::GetCursorPosY() + ImGui::GetStyle().WindowPadding.y);
    ImGui::EndChild();
    ImGui::PopID();
}

// The lesson's own pages beside the steps (the chapter's pitfalls, hard cases and other exercises),
// folded under the step's text: one node a page, its text as the steps' is drawn.
void drawLessonPages(const OverlayModel& m) {
    if (m.pages.empty()) return;
    const std::string label = say("panel.pages");
    if (!ImGui::CollapsingHeader(cat(label, " (", m.pages.size(), ")###lesson pages").c_str())) return;
    for (std::size_t i = 0; i < m.pages.size(); ++i) {
        const LessonStep& page = m.pages[i];
        ImGui::PushID(int(i));
        if (ImGui::TreeNode("page", "%s", page.title.c_str())) {
            if (!page.note.empty()) ImGui::TextDisabled("%s", page.note.c_str());
            drawMarkdown(page.text);
            ImGui::TreePop();
        }
        ImGui::PopID();
    }
}

// What the teacher just did and what holds now (a notice, the paused clock, the compare view, the
// picture's scale), in a strip of fixed height under the step's row: notices come and go with the
// automatic scale and a teacher's keys, and nothing under them may move while a click is on its way.
// More than fits scrolls inside the strip.
void drawNotices(const OverlayModel& m) {
    const float height = 3.0f * ImGui::GetTextLineHeightWithSpacing() + ImGui::GetStyle().WindowPadding.y;
    ImGui::BeginChild("notices", ImVec2(0.0f, height), false);
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
    ImGui::EndChild();
}

// The step's row: its number, the arrows and the text's languages.
void drawStepRow(const OverlayModel& m) {
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
}

void drawStepBody(const OverlayModel& m, bool opened);

}  // namespace

void drawLessonWindowContents(const OverlayModel& m) {
    // The step's row and the notices hold still at the top; the rest scrolls under them, and a step
    // change opens it at the step's title.
    const bool hasSteps = m.step && !m.steps.empty();
    if (hasSteps) {
        drawStepRow(m);
        drawNotices(m);
    }
    ImGui::BeginChild("step body", ImVec2(0.0f, 0.0f), false);
    ImGuiStorage* storage = ImGui::GetStateStorage();
    const ImGuiID shownKey = ImGui::GetID("step shown");
    const int shown = hasSteps ? *m.step : -1;
    const bool opened = storage->GetInt(shownKey, -1) != shown;
    if (opened) {
        ImGui::SetScrollY(0.0f);
        storage->SetInt(shownKey, shown);
    }
    drawStepBody(m, opened);
    ImGui::EndChild();
}

namespace {

void drawStepBody(const OverlayModel& m, bool opened) {
    if (m.step && !m.steps.empty()) {
        const int step = *m.step;
        const LessonStep& s = m.steps[std::size_t(step)];
        ImGui::PushTextWrapPos(0.0f);
        ImGui::PushStyleColor(ImGuiCol_Text, ui_style::kHeading);
        drawWrappedText(s.title);  // Japanese titles too: no lone "る" or "8" on the last line
        ImGui::PopStyleColor();
        if (!s.note.empty()) ImGui::TextDisabled("%s", s.note.c_str());
        ImGui::PopTextWrapPos();
        drawStepText(s.text, step, opened);
        drawLessonPages(m);
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

}  // namespace

}  // namespace fx
