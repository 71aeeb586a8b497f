#include "ui/lesson_panel.hpp"

#include <algorithm>
#include <string>

#include <imgui.h>

#include "base/log.hpp"
#include "ui/markdown_view.hpp"
#include "ui/ui_style.hpp"
#include "ui/word_wrap.hpp"

namespace fx {

namespace {

// The value's widget; true when the user changed it this frame.
bool drawParamWidget(const Param& p) {
    switch (p.type) {
        // The slider's span (a setting's may be narrower than its range: the values a lesson is shown
        // with); Ctrl+click types any value.
        case ParamType::Float:
            return ImGui::SliderFloat(p.name.c_str(), p.floatValue, float(p.sliderMin), float(p.sliderMax),
                                      p.sliderFormat().c_str());
        case ParamType::Int:
            return ImGui::SliderInt(p.name.c_str(), p.intValue, int(p.sliderMin), int(p.sliderMax),
                                    p.sliderFormat().c_str());
        case ParamType::Bool:
            return ImGui::Checkbox(p.name.c_str(), p.boolValue);
        case ParamType::Choice: {
            bool changed = false;
            const char* current = p.choices.empty() ? "" : p.choices[std::size_t(*p.intValue)].c_str();
            if (ImGui::BeginCombo(p.name.c_str(), current)) {
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
    if (ImGui::MenuItem("keep this value in every step", nullptr, &pinned)) params.setPinned(p, pinned);
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
    std::string tag = p.pinned                         ? "[kept in every step]"
                      : source == ParamSource::overlay ? "[changed in this step]"
                                                       : cat("[", toString(source), "]");
    if (source == ParamSource::lessonDefault && !p.pinned) {
        ImGui::TextDisabled("%s", tag.c_str());
    } else {
        ImGui::TextColored(ui_style::kHeading, "%s", tag.c_str());
    }
    hovered = hovered || ImGui::IsItemHovered();
    pinMenu(params, p);
    if (hovered) {
        std::string from = cat("from: ", toString(source));
        if (source == ParamSource::scene) from += cat(" (", p.sceneSetting, ")");
        if (!p.sceneSetting.empty() && source != ParamSource::scene)
            from += cat("; the scene setting ", p.sceneSetting, " starts it when the scene has one");
        ImGui::SetTooltip("%s\n(%s%s)\n%s\n%s", p.description.c_str(), p.rangeText().c_str(),
                          p.knob ? "; a quality knob" : "", from.c_str(),
                          "A change belongs to the step it is made in; right-click keeps it in every step.");
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
    if (!others.empty() && ImGui::TreeNode("other steps", "other steps (%d)", int(others.size()))) {
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
    const char* label = m.language == "ja" ? "このレッスンの補足" : "Beside the steps";
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
    ImGui::Text("Step %d of %d", step + 1, int(m.steps.size()));
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
        ImGui::TextColored(ui_style::kError,
                           "Lesson text (the steps show what was read before, or titles only):");
        ImGui::PushTextWrapPos(0.0f);
        ImGui::TextUnformatted(m.textError.c_str());
        ImGui::PopTextWrapPos();
    }
    if (!m.shaderErrors.empty()) {
        ImGui::Separator();
        ImGui::TextColored(ui_style::kError, "Shader errors (the last good program keeps running):");
        for (auto& e : m.shaderErrors) ImGui::TextWrapped("%s", e.c_str());
    }
    const int step = m.step ? *m.step : 0;
    if (m.params && !m.params->all().empty() &&
        ImGui::CollapsingHeader("Parameters", ImGuiTreeNodeFlags_DefaultOpen)) {
        drawParams(*m.params, step);
        if (ImGui::Button("Reset")) m.params->resetAll();
        if (ImGui::IsItemHovered())
            ImGui::SetTooltip(
                "Back to the values the run started with (scene, preset, command line), in every step");
        if (m.onSavePreset) {
            ImGui::SameLine();
            if (ImGui::Button("Save preset")) m.onSavePreset();
        }
        if (m.onLoadPreset) {
            ImGui::SameLine();
            if (ImGui::Button("Load preset")) m.onLoadPreset();
        }
    }
    if (m.lessonPanel && ImGui::CollapsingHeader("Lesson", ImGuiTreeNodeFlags_DefaultOpen)) m.lessonPanel();
    ImGui::Separator();
    ImGui::TextDisabled("%s", m.renderer.c_str());
    if (m.frame) ImGui::TextDisabled("frame %.2f ms, timing: %s", m.frameMs, m.timing.c_str());
    if (!m.clockRate.empty()) {
        ImGui::PushTextWrapPos(0.0f);
        ImGui::TextDisabled("%s", m.clockRate.c_str());
        ImGui::PopTextWrapPos();
    }
    if (m.glErrors > 0)
        ImGui::TextColored(ui_style::kError, "GL errors: %lld", static_cast<long long>(m.glErrors));
    if (m.glExpectedErrors > 0) {
        ImGui::TextColored(ui_style::kWarning, "GL errors this step shows on purpose: %lld",
                           static_cast<long long>(m.glExpectedErrors));
    }
    if (!m.status.empty()) ImGui::TextDisabled("%s", m.status.c_str());
}

}  // namespace

}  // namespace fx
