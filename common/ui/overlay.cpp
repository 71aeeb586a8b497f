#include "ui/overlay.hpp"

#include <algorithm>
#include <cmath>

#include <imgui.h>
#include <imgui_impl_glfw.h>
#include <imgui_impl_opengl3.h>

#include "base/log.hpp"
#include "base/words.hpp"
#include "gl/debug_output.hpp"
#include "gl/gl.hpp"
#include "gl/object.hpp"
#include "ui/gl_state_scope.hpp"
#include "ui/lesson_panel.hpp"
#include "ui/pass_table.hpp"
#include "ui/ui_style.hpp"

namespace fx {
namespace {

// The docked windows are placed by the layout every frame; the user changes the layout by dragging
// their inner edges (followResize), never by moving them.
// The debug group around Dear ImGui's own GL work (its backend's objects have no labels).
constexpr const char* kImGuiGroup = "overlay (Dear ImGui)";
constexpr ImGuiWindowFlags kDocked = ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoCollapse;

void placeNext(const LayoutRect& r) {
    ImGui::SetNextWindowPos(ImVec2(r.x, r.y), ImGuiCond_Always);
    ImGui::SetNextWindowSize(ImVec2(r.width, r.height), ImGuiCond_Always);
}

// A title bar at a text scale: the font's height and the frame padding above and below it.
float titleBarHeight(float scale) {
    return std::ceil(13.0f * scale + 2.0f * 3.0f * scale);
}

void drawKeys(const OverlayModel& m) {
    if (m.keys.empty()) {
        ImGui::TextDisabled("%s", say("keys.none").c_str());
        return;
    }
    const ImGuiTableFlags flags = ImGuiTableFlags_RowBg | ImGuiTableFlags_SizingFixedFit;
    if (!ImGui::BeginTable("keys", 2, flags)) return;
    ImGui::TableSetupColumn(say("keys.key").c_str(), ImGuiTableColumnFlags_WidthFixed);
    ImGui::TableSetupColumn(say("keys.action").c_str(), ImGuiTableColumnFlags_WidthStretch);
    for (const OverlayKey& k : m.keys) {
        ImGui::TableNextRow();
        ImGui::TableNextColumn();
        ImGui::TextColored(ui_style::kHeading, "%s", k.key.c_str());
        ImGui::TableNextColumn();
        ImGui::TextWrapped("%s", k.action.c_str());
    }
    ImGui::EndTable();
    ImGui::TextDisabled(
        "%s", say("keys.also", {{"exe", m.executable.empty() ? "<lesson>" : m.executable}}).c_str());
}

}  // namespace

Overlay::Overlay(GLFWwindow* window) : window_(window), started_(startImGui(window)) {
    if (window_ && started_.platform) keys_ = std::make_unique<KeyLatch>(window_);
    if (started_.renderer) {
        inspector_ = std::make_unique<Inspector>();
        baseStyle_ = ImGui::GetStyle();
    }
}

Overlay::~Overlay() {
    inspector_.reset();  // its GL objects go while the context is current
    keys_.reset();       // the backend's key callback back before the backend puts the app's back
    stopImGui(started_);
}

bool Overlay::wantsKeyboard() const {
    return ImGui::GetIO().WantCaptureKeyboard;
}
bool Overlay::wantsTextInput() const {
    // As things stand after the last frame's widgets: io.WantTextInput is set at the start of a frame and
    // still says "typing" for the frame after Enter closed the field. (An item held with the mouse
    // counts too: keys pressed while dragging a slider are not the app's either.)
    return ImGui::IsAnyItemActive();
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

PanelLayout Overlay::layout(int width, int height) const {
    const bool inspectorOpen = inspector_ && inspector_->open();
    // The column is never narrower than about 300 pixels at scale 1: a step's text stays readable.
    return computePanelLayout(width, height, shares_, inspectorOpen, titleBarHeight(textScale_),
                              300.0f * textScale_);
}

void Overlay::resetLayout() {
    shares_ = {};
    if (inspector_) inspector_->setOpen(false);
}

void Overlay::prepareFonts(const OverlayModel& m) {
    // Between frames: the atlas holds the glyphs of every step's text and of the lesson's pages (so
    // stepping needs no reload).
    fontsForRevision_ = m.textRevision;
    std::vector<std::string_view> texts;
    for (const std::vector<LessonStep>* list : {&m.steps, &m.pages})
        for (const LessonStep& s : *list) {
            texts.push_back(s.title);
            texts.push_back(s.text);
            texts.push_back(s.note);
        }
    texts.push_back(m.textError);
    texts.insert(texts.end(), m.words.begin(), m.words.end());
    if (Status loaded = fonts_.prepare(texts, textScale_); !loaded) {
        log::error(loaded.error());
        fontError_ = loaded.error();
        if (m.language != "en" && m.setLanguage) {
            fontError_ += say("overlay.fontFallback");
            m.setLanguage("en");
        }
    } else {
        fontError_.clear();
    }
}

void Overlay::applyTextScale() {
    // The style's sizes (padding, spacing, scroll bars) grow with the text.
    ImGui::GetStyle() = baseStyle_;
    ImGui::GetStyle().ScaleAllSizes(textScale_);
    appliedScale_ = textScale_;
}

void Overlay::followResize(const LayoutRect& placed, ImVec2 now, int width, int height, bool lessonWindow) {
    if (!ImGui::IsMouseDown(ImGuiMouseButton_Left)) return;
    const float w = float(width), h = float(height);
    if (std::abs(now.x - placed.width) >= 1.0f && w > 0) shares_.column = now.x / w;
    if (lessonWindow && std::abs(now.y - placed.height) >= 1.0f && h > 0)
        shares_.lesson = now.y / std::max(h - titleBarHeight(textScale_), 1.0f);
    shares_ = clampShares(shares_);
}

void Overlay::drawFrameWindow(const OverlayModel& m, const PanelLayout& layout) {
    placeNext(layout.frame);
    // "###": the window and its tabs keep their identity in every language.
    const std::string title = say("frame.window") + "###frame";
    if (ImGui::Begin(title.c_str(), nullptr, kDocked) && ImGui::BeginTabBar("frame tabs")) {
        const bool selectCost = requestFrameOpen_ && requestCostTab_;
        // The keys come first: a teacher finds every key in one place without looking for it.
        if (ImGui::BeginTabItem((say("frame.keys") + "###keys").c_str())) {
            drawKeys(m);
            ImGui::EndTabItem();
        }
        if (ImGui::BeginTabItem((say("frame.passes") + "###passes").c_str(), nullptr,
                                requestFrameOpen_ && !requestCostTab_ ? ImGuiTabItemFlags_SetSelected : 0)) {
            if (m.frame) {
                // In copies too, once the cost panel has measured a copy at this size.
                const auto& sweep = cost_.result();
                const bool sameSize = sweep && sweep->width == m.frame->outputSize.width &&
                                      sweep->height == m.frame->outputSize.height;
                drawPassTable(*m.frame, sameSize ? sweep->copyMs : 0.0);
            } else {
                ImGui::TextDisabled("%s", say("frame.none").c_str());
            }
            ImGui::EndTabItem();
        }
        if (ImGui::BeginTabItem((say("frame.cost") + "###cost").c_str(), nullptr,
                                selectCost ? ImGuiTabItemFlags_SetSelected : 0)) {
            cost_.draw(m.measureKnobs);
            ImGui::EndTabItem();
        }
        ImGui::EndTabBar();
    }
    requestFrameOpen_.reset();
}

void Overlay::draw(const OverlayModel& m, int width, int height, double deltaSeconds) {
    if (!ok() || width <= 0 || height <= 0) return;
    if (m.textRevision != fontsForRevision_ || textScale_ != appliedScale_) prepareFonts(m);
    if (textScale_ != appliedScale_) applyTextScale();
    ImGuiIO& io = ImGui::GetIO();
    {
        // Dear ImGui's GL backend (Debian's, unchanged) makes its program and buffers in its first
        // NewFrame and a vertex array in every draw, without labels; its group says whose they are
        // (tests/trace/check_gl_names.py allows unlabelled objects only inside it).
        gl::DebugGroup group(kImGuiGroup);
        ImGui_ImplOpenGL3_NewFrame();
    }
    if (!fontTextureLabelled_ && io.Fonts->TexID) {
        // The backend makes the font texture in its first NewFrame; overlay_fonts labels later ones.
        gl::labelObject(GL_TEXTURE, GLuint(reinterpret_cast<std::uintptr_t>(io.Fonts->TexID)),
                        "ui.font_atlas");
        fontTextureLabelled_ = true;
    }
    if (window_) {
        ImGui_ImplGlfw_NewFrame();
        if (keys_) keys_->beforeNewFrame();
    } else {
        io.DisplaySize = ImVec2(float(width), float(height));
        io.DeltaTime = deltaSeconds > 0 ? float(deltaSeconds) : 1.0f / 60.0f;
    }
    ImGui::NewFrame();
    const PanelLayout layout = this->layout(width, height);
    {
        // The inspector draws its pictures into its own targets while the windows are laid out.
        GlStateScope keep;

        placeNext(layout.lesson);
        const std::string lessonTitle = (m.title.empty() ? std::string("fxlab") : m.title) + "###lesson";
        ImGui::Begin(lessonTitle.c_str(), nullptr, kDocked);
        followResize(layout.lesson, ImGui::GetWindowSize(), width, height, true);
        drawLessonWindowContents(m);
        if (!fontError_.empty()) ImGui::TextColored(ui_style::kWarning, "%s", fontError_.c_str());
        ImGui::End();

        drawFrameWindow(m, layout);
        followResize(layout.frame, ImGui::GetWindowSize(), width, height, false);
        ImGui::End();

        InspectorFrame frame{m.graph, m.frame, m.cameraNear, m.cameraFar, deltaSeconds};
        ImVec2 inspectorSize = inspector_->draw(frame, ImVec2(layout.inspector.x, layout.inspector.y),
                                                ImVec2(layout.inspector.width, layout.inspector.height));
        // Dragging the open inspector's top edge moves the line between it and the picture.
        if (inspector_->open() && ImGui::IsMouseDown(ImGuiMouseButton_Left) &&
            std::abs(inspectorSize.y - layout.inspector.height) >= 1.0f) {
            shares_.picture = 1.0f - inspectorSize.y / float(height);
            shares_ = clampShares(shares_);
        }
    }
    labelImGuiObjectsThisFrame();
    ImGui::Render();
    gl::DebugGroup group(kImGuiGroup);
    ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
}

}  // namespace fx
