#include "ui/overlay.hpp"

#include <imgui.h>
#include <imgui_impl_glfw.h>
#include <imgui_impl_opengl3.h>

#include "base/log.hpp"

namespace fx {

Overlay::Overlay(GLFWwindow* window) : window_(window) {
    IMGUI_CHECKVERSION();
    ImGui::CreateContext();
    ImGuiIO& io = ImGui::GetIO();
    io.IniFilename = nullptr;  // no imgui.ini beside the user's files
    ImGui::StyleColorsDark();
    ImGui::GetStyle().WindowRounding = 4.0f;
    if (window_ && !ImGui_ImplGlfw_InitForOpenGL(window_, true)) {
        log::error("the overlay could not attach to the window");
        return;
    }
    ok_ = ImGui_ImplOpenGL3_Init("#version 450 core");
    if (!ok_) log::error("the overlay's OpenGL renderer could not start");
}

Overlay::~Overlay() {
    if (ok_) ImGui_ImplOpenGL3_Shutdown();
    if (window_) ImGui_ImplGlfw_Shutdown();
    ImGui::DestroyContext();
}

bool Overlay::wantsKeyboard() const { return ImGui::GetIO().WantCaptureKeyboard; }
bool Overlay::wantsMouse() const { return ImGui::GetIO().WantCaptureMouse; }

namespace {

void drawParams(ParamSet& params) {
    for (const Param& p : params.all()) {
        ImGui::PushID(p.name.c_str());
        switch (p.type) {
            case ParamType::Float: ImGui::SliderFloat(p.name.c_str(), p.floatValue, float(p.min), float(p.max)); break;
            case ParamType::Int: ImGui::SliderInt(p.name.c_str(), p.intValue, int(p.min), int(p.max)); break;
            case ParamType::Bool: ImGui::Checkbox(p.name.c_str(), p.boolValue); break;
            case ParamType::Choice: {
                const char* current = p.choices.empty() ? "" : p.choices[std::size_t(*p.intValue)].c_str();
                if (ImGui::BeginCombo(p.name.c_str(), current)) {
                    for (std::size_t i = 0; i < p.choices.size(); ++i) {
                        if (ImGui::Selectable(p.choices[i].c_str(), int(i) == *p.intValue)) *p.intValue = int(i);
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

void drawPasses(const FrameReport& frame) {
    if (!ImGui::BeginTable("passes", 4, ImGuiTableFlags_RowBg | ImGuiTableFlags_SizingStretchProp)) return;
    ImGui::TableSetupColumn("pass");
    ImGui::TableSetupColumn("ms");
    ImGui::TableSetupColumn("status");
    ImGui::TableSetupColumn("left behind");
    ImGui::TableHeadersRow();
    for (const PassRecord& p : frame.passes) {
        ImGui::TableNextRow();
        ImGui::TableNextColumn();
        if (!p.executed) ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(0.55f, 0.55f, 0.55f, 1.0f));
        ImGui::TextUnformatted(p.name.c_str());
        ImGui::TableNextColumn();
        if (p.timeMs) ImGui::Text("%.3f", *p.timeMs);
        ImGui::TableNextColumn();
        ImGui::TextUnformatted(p.executed ? "ran" : p.reason.c_str());
        ImGui::TableNextColumn();
        std::string left;
        for (auto& s : p.stateLeft) left += (left.empty() ? "" : "; ") + s;
        ImGui::TextUnformatted(left.c_str());
        if (!p.executed) ImGui::PopStyleColor();
    }
    ImGui::EndTable();
}

}  // namespace

void Overlay::draw(const OverlayModel& m, int width, int height, double deltaSeconds) {
    if (!ok_ || width <= 0 || height <= 0) return;
    ImGuiIO& io = ImGui::GetIO();
    ImGui_ImplOpenGL3_NewFrame();
    if (window_) {
        ImGui_ImplGlfw_NewFrame();
    } else {
        io.DisplaySize = ImVec2(float(width), float(height));
        io.DeltaTime = deltaSeconds > 0 ? float(deltaSeconds) : 1.0f / 60.0f;
    }
    ImGui::NewFrame();

    ImGui::SetNextWindowPos(ImVec2(8, 8), ImGuiCond_FirstUseEver);
    ImGui::SetNextWindowSize(ImVec2(420, 0), ImGuiCond_FirstUseEver);
    ImGui::Begin(m.title.c_str());
    if (m.step && !m.steps.empty()) {
        int& step = *m.step;
        ImGui::Text("Step %d of %d", step + 1, int(m.steps.size()));
        ImGui::SameLine();
        if (ImGui::ArrowButton("prev", ImGuiDir_Left) && step > 0) --step;
        ImGui::SameLine();
        if (ImGui::ArrowButton("next", ImGuiDir_Right) && step + 1 < int(m.steps.size())) ++step;
        const OverlayStep& s = m.steps[std::size_t(step)];
        ImGui::TextColored(ImVec4(1.0f, 0.85f, 0.4f, 1.0f), "%s", s.title.c_str());
        ImGui::PushTextWrapPos(0.0f);
        ImGui::TextUnformatted(s.text.c_str());
        ImGui::PopTextWrapPos();
    }
    if (!m.shaderErrors.empty()) {
        ImGui::Separator();
        ImGui::TextColored(ImVec4(1.0f, 0.35f, 0.35f, 1.0f), "Shader errors (the last good program keeps running):");
        for (auto& e : m.shaderErrors) ImGui::TextWrapped("%s", e.c_str());
    }
    if (m.params && !m.params->all().empty() && ImGui::CollapsingHeader("Parameters", ImGuiTreeNodeFlags_DefaultOpen)) {
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
    if (m.frame && ImGui::CollapsingHeader("Passes", ImGuiTreeNodeFlags_DefaultOpen)) {
        ImGui::Text("frame %.2f ms, timing: %s", m.frameMs, m.timing.c_str());
        drawPasses(*m.frame);
        ImGui::Text("textures: %.2f MiB live, %.2f MiB peak", double(m.frame->pool.liveBytes) / 1048576.0,
                    double(m.frame->pool.peakBytes) / 1048576.0);
    }
    ImGui::Separator();
    ImGui::TextDisabled("%s", m.renderer.c_str());
    if (m.glErrors > 0) ImGui::TextColored(ImVec4(1, 0.3f, 0.3f, 1), "GL errors: %lld", static_cast<long long>(m.glErrors));
    if (m.glExpectedErrors > 0) {
        ImGui::TextColored(ImVec4(1, 0.7f, 0.3f, 1), "GL errors this step shows on purpose: %lld",
                           static_cast<long long>(m.glExpectedErrors));
    }
    if (!m.status.empty()) ImGui::TextDisabled("%s", m.status.c_str());
    ImGui::TextDisabled("F1 overlay  F5 reload  F12 screenshot  arrows: steps");
    ImGui::End();

    ImGui::Render();
    ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
}

}  // namespace fx
