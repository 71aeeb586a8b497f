#include "ui/overlay.hpp"

#include <algorithm>

#include <imgui.h>
#include <imgui_impl_glfw.h>
#include <imgui_impl_opengl3.h>

#include "base/log.hpp"
#include "gl/gl.hpp"
#include "gl/object.hpp"
#include "ui/gl_state_scope.hpp"
#include "ui/lesson_panel.hpp"
#include "ui/pass_table.hpp"
#include "ui/ui_style.hpp"

namespace fx {
namespace {

// Where the windows start (the user moves them after): the lesson top left, the frame under it,
// the inspector on the right.
struct Layout {
    ImVec2 lessonPos, lessonSize, framePos, frameSize, inspectorPos, inspectorSize;
};

Layout layoutFor(int width, int height) {
    const float w = float(width), h = float(height), m = 8.0f;
    Layout l;
    l.lessonPos = {m, m};
    l.lessonSize = {std::min(370.0f, w - 2 * m),
                    std::clamp(h * 0.56f, std::min(200.0f, h - 2 * m), h - 2 * m)};
    const float frameTop = l.lessonPos.y + l.lessonSize.y + m;
    l.framePos = {m, frameTop};
    l.frameSize = {std::clamp(w * 0.5f, std::min(360.0f, w - 2 * m), 640.0f),
                   std::max(h - frameTop - m, 120.0f)};
    // Right of the frame window when there is room; never over the lesson window.
    const float lessonRight = l.lessonPos.x + l.lessonSize.x + m;
    const float inspectorLeft = std::min(
        std::max(lessonRight, std::min(l.framePos.x + l.frameSize.x + m, w - m - 600.0f)), w - m - 200.0f);
    l.inspectorPos = {std::max(inspectorLeft, m), m};
    l.inspectorSize = {std::min(w - l.inspectorPos.x - m, 1100.0f), h - 2 * m};
    return l;
}

}  // namespace

Overlay::Overlay(GLFWwindow* window) : window_(window), started_(startImGui(window)) {
    if (started_.renderer) inspector_ = std::make_unique<Inspector>();
}

Overlay::~Overlay() {
    inspector_.reset();  // its GL objects go while the context is current
    stopImGui(started_);
}

bool Overlay::wantsKeyboard() const {
    return ImGui::GetIO().WantCaptureKeyboard;
}
bool Overlay::wantsMouse() const {
    return ImGui::GetIO().WantCaptureMouse;
}

std::vector<std::string> Overlay::wantedTextures() const {
    return inspector_ ? inspector_->wantedTextures() : std::vector<std::string>{};
}

void Overlay::showFramePanel(bool open, bool costTab) {
    requestFrameOpen_ = open;
    requestCostTab_ = costTab;
}

void Overlay::prepareFonts(const OverlayModel& m) {
    // Between frames: the atlas holds the glyphs of every step's text (so stepping needs no reload).
    fontsForRevision_ = m.textRevision;
    std::vector<std::string_view> texts;
    for (const LessonStep& s : m.steps) {
        texts.push_back(s.title);
        texts.push_back(s.text);
        texts.push_back(s.note);
    }
    texts.push_back(m.textError);
    if (Status loaded = fonts_.prepare(texts); !loaded) {
        log::error(loaded.error());
        fontError_ = loaded.error();
        if (m.language != "en" && m.setLanguage) {
            fontError_ += "; showing the English text";
            m.setLanguage("en");
        }
    } else {
        fontError_.clear();
    }
}

void Overlay::draw(const OverlayModel& m, int width, int height, double deltaSeconds) {
    if (!ok() || width <= 0 || height <= 0) return;
    // A sweep renders frames of its own: it runs before this frame's ImGui frame starts, with the
    // runner's framebuffer and viewport put back afterwards.
    if (cost_.measurePending()) {
        GlStateScope keep;
        cost_.runPending(m.measureKnobs);
    }
    if (m.textRevision != fontsForRevision_) prepareFonts(m);
    ImGuiIO& io = ImGui::GetIO();
    ImGui_ImplOpenGL3_NewFrame();
    if (!fontTextureLabelled_ && io.Fonts->TexID) {
        // The backend makes the font texture in its first NewFrame; overlay_fonts labels later ones.
        gl::labelObject(GL_TEXTURE, GLuint(reinterpret_cast<std::uintptr_t>(io.Fonts->TexID)),
                        "ui.font_atlas");
        fontTextureLabelled_ = true;
    }
    if (window_) {
        ImGui_ImplGlfw_NewFrame();
    } else {
        io.DisplaySize = ImVec2(float(width), float(height));
        io.DeltaTime = deltaSeconds > 0 ? float(deltaSeconds) : 1.0f / 60.0f;
    }
    ImGui::NewFrame();
    const Layout layout = layoutFor(width, height);
    {
        // The inspector draws its pictures into its own targets while the windows are laid out.
        GlStateScope keep;

        ImGui::SetNextWindowPos(layout.lessonPos, ImGuiCond_FirstUseEver);
        ImGui::SetNextWindowSize(layout.lessonSize, ImGuiCond_FirstUseEver);
        ImGui::Begin(m.title.empty() ? "fxlab" : m.title.c_str());
        drawLessonWindowContents(m);
        if (!fontError_.empty()) ImGui::TextColored(ui_style::kWarning, "%s", fontError_.c_str());
        ImGui::End();

        ImGui::SetNextWindowPos(layout.framePos, ImGuiCond_FirstUseEver);
        ImGui::SetNextWindowSize(layout.frameSize, ImGuiCond_FirstUseEver);
        if (requestFrameOpen_) ImGui::SetNextWindowCollapsed(!*requestFrameOpen_, ImGuiCond_Always);
        if (ImGui::Begin("Frame: passes and cost") && ImGui::BeginTabBar("frame tabs")) {
            const bool selectCost = requestFrameOpen_ && requestCostTab_;
            if (ImGui::BeginTabItem("Passes")) {
                if (m.frame) {
                    // In copies too, once the cost panel has measured a copy at this size.
                    const auto& sweep = cost_.result();
                    const bool sameSize = sweep && sweep->width == m.frame->outputSize.width &&
                                          sweep->height == m.frame->outputSize.height;
                    drawPassTable(*m.frame, sameSize ? sweep->copyMs : 0.0);
                } else {
                    ImGui::TextDisabled("no frame yet");
                }
                ImGui::EndTabItem();
            }
            if (ImGui::BeginTabItem("Cost of quality", nullptr,
                                    selectCost ? ImGuiTabItemFlags_SetSelected : 0)) {
                cost_.draw(m.measureKnobs);
                ImGui::EndTabItem();
            }
            ImGui::EndTabBar();
        }
        requestFrameOpen_.reset();
        ImGui::End();

        InspectorFrame frame{m.graph, m.frame, m.cameraNear, m.cameraFar, deltaSeconds};
        inspector_->draw(frame, layout.inspectorPos, layout.inspectorSize);
    }
    ImGui::Render();
    ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
}

}  // namespace fx
