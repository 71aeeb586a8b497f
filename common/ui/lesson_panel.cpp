#include "ui/lesson_panel.hpp"

#include <algorithm>
#include <string>

#include <imgui.h>

#include "ui/markdown_view.hpp"
#include "ui/ui_style.hpp"

namespace fx {

void drawParams(ParamSet& params) {
    for (const Param& p : params.all()) {
        ImGui::PushID(p.name.c_str());
        switch (p.type) {
            case ParamType::Float:
                ImGui::SliderFloat(p.name.c_str(), p.floatValue, float(p.min), float(p.max));
                break;
            case ParamType::Int:
                ImGui::SliderInt(p.name.c_str(), p.intValue, int(p.min), int(p.max));
                break;
            case ParamType::Bool:
                ImGui::Checkbox(p.name.c_str(), p.boolValue);
                break;
            case ParamType::Choice: {
                const char* current = p.choices.empty() ? "" : p.choices[std::size_t(*p.intValue)].c_str();
                if (ImGui::BeginCombo(p.name.c_str(), current)) {
                    for (std::size_t i = 0; i < p.choices.size(); ++i) {
                        if (ImGui::Selectable(p.choices[i].c_str(), int(i) == *p.intValue))
                            *p.intValue = int(i);
                    }
                    ImGui::EndCombo();
                }
                break;
            }
        }
        if (ImGui::IsItemHovered() && !p.description.empty()) {
            ImGui::SetTooltip("%s\n(%s%s)", p.description.c_str(), p.rangeText().c_str(),
                              p.knob ? "; a quality knob" : "");
        }
        ImGui::PopID();
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
    const float most = std::max(ImGui::GetWindowHeight() * 0.5f, 6.0f * ImGui::GetTextLineHeightWithSpacing());
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
        ImGui::TextColored(ui_style::kError, "Lesson text (the steps show what was read before, or titles only):");
        ImGui::PushTextWrapPos(0.0f);
        ImGui::TextUnformatted(m.textError.c_str());
        ImGui::PopTextWrapPos();
    }
    if (!m.shaderErrors.empty()) {
        ImGui::Separator();
        ImGui::TextColored(ui_style::kError, "Shader errors (the last good program keeps running):");
        for (auto& e : m.shaderErrors) ImGui::TextWrapped("%s", e.c_str());
    }
    if (m.params && !m.params->all().empty() &&
        ImGui::CollapsingHeader("Parameters", ImGuiTreeNodeFlags_DefaultOpen)) {
        drawParams(*m.params);
        if (ImGui::Button("Reset")) m.params->resetAll();
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
    if (m.glErrors > 0)
        ImGui::TextColored(ui_style::kError, "GL errors: %lld", static_cast<long long>(m.glErrors));
    if (m.glExpectedErrors > 0) {
        ImGui::TextColored(ui_style::kWarning, "GL errors this step shows on purpose: %lld",
                           static_cast<long long>(m.glExpectedErrors));
    }
    if (!m.status.empty()) ImGui::TextDisabled("%s", m.status.c_str());
    ImGui::TextDisabled("F1 overlay  F5 reload  F12 screenshot  arrows: steps");
}

}  // namespace fx
