#include "ui/texture_view.hpp"

#include <algorithm>
#include <cmath>

#include "ui/ui_style.hpp"

namespace fx {
namespace {

constexpr double kMinZoom = 1.0 / 64.0;
constexpr double kMaxZoom = 256.0;
constexpr double kGridFrom = 16.0;  // screen pixels per texel from which texels are outlined

}  // namespace

void ZoomableView::setZoom(double pixelsPerTexel, double centreU, double centreV) {
    zoom_ = std::clamp(pixelsPerTexel, kMinZoom, kMaxZoom);
    centreU_ = centreU;
    centreV_ = centreV;
    fit_ = false;
}

ViewWindow ZoomableView::windowFor(const TextureSource& source, int level, int width, int height) const {
    const Size2D base = source.levelSize(0);
    const Size2D size = source.levelSize(level);
    ViewWindow w;
    w.texelsPerPixel = double(size.width) / double(base.width) / zoom_;
    w.originX = centreU_ * size.width - width / 2.0 * w.texelsPerPixel;
    w.originY = centreV_ * size.height - height / 2.0 * w.texelsPerPixel;
    return w;
}

ZoomableView::Interaction ZoomableView::draw(const TextureDisplay& display, const TextureSource& source,
                                             const ViewSettings& settings, ImVec2 size,
                                             const std::optional<PixelProbe::Target>& mark) {
    Interaction result;
    const int width = std::max(1, static_cast<int>(size.x));
    const int height = std::max(1, static_cast<int>(size.y));
    const int level = std::clamp(settings.level, 0, source.levels() - 1);
    const Size2D base = source.levelSize(0);
    const Size2D levelSize = source.levelSize(level);
    if (fit_ && !base.empty()) {
        zoom_ = std::clamp(std::min(double(width) / base.width, double(height) / base.height), kMinZoom,
                           kMaxZoom);
        centreU_ = centreV_ = 0.5;
    }

    const ImVec2 topLeft = ImGui::GetCursorScreenPos();
    ImGui::InvisibleButton("view", ImVec2(float(width), float(height)),
                           ImGuiButtonFlags_MouseButtonLeft | ImGuiButtonFlags_MouseButtonRight);
    const bool hovered = ImGui::IsItemHovered();
    ImGuiIO& io = ImGui::GetIO();

    // Pan: drag with the left button (screen y grows downwards, texel y upwards).
    if (ImGui::IsItemActive() && ImGui::IsMouseDragging(ImGuiMouseButton_Left, 0.0f)) {
        ViewWindow w = windowFor(source, level, width, height);
        centreU_ -= io.MouseDelta.x * w.texelsPerPixel / levelSize.width;
        centreV_ += io.MouseDelta.y * w.texelsPerPixel / levelSize.height;
        fit_ = false;
    }
    if (hovered && ImGui::IsMouseDoubleClicked(ImGuiMouseButton_Left)) fit_ = true;
    // Zoom about the point under the mouse, which stays where it is.
    if (hovered && io.MouseWheel != 0.0f) {
        ViewWindow before = windowFor(source, level, width, height);
        double px = io.MousePos.x - topLeft.x, py = height - (io.MousePos.y - topLeft.y);
        double tx = before.texelX(px), ty = before.texelY(py);
        zoom_ = std::clamp(zoom_ * std::pow(1.25, double(io.MouseWheel)), kMinZoom, kMaxZoom);
        ViewWindow after = windowFor(source, level, width, height);
        centreU_ = (tx - px * after.texelsPerPixel + width / 2.0 * after.texelsPerPixel) / levelSize.width;
        centreV_ = (ty - py * after.texelsPerPixel + height / 2.0 * after.texelsPerPixel) / levelSize.height;
        fit_ = false;
    }

    const ViewWindow window = windowFor(source, level, width, height);
    const double pixelsPerTexel = 1.0 / window.texelsPerPixel;
    surface_.resize(width, height);
    display.draw(surface_, source, settings, window, pixelsPerTexel >= kGridFrom);
    ImDrawList* draw = ImGui::GetWindowDrawList();
    const ImVec2 bottomRight(topLeft.x + float(width), topLeft.y + float(height));
    draw->AddImage(surface_.id(), topLeft, bottomRight, DisplaySurface::uvTopLeft(),
                   DisplaySurface::uvBottomRight());

    if (hovered) {
        double px = io.MousePos.x - topLeft.x, py = height - (io.MousePos.y - topLeft.y);
        int tx = static_cast<int>(std::floor(window.texelX(px)));
        int ty = static_cast<int>(std::floor(window.texelY(py)));
        if (tx >= 0 && ty >= 0 && tx < levelSize.width && ty < levelSize.height) {
            result.hovered = PixelProbe::Target{level, tx, ty, {}};
            result.pinRequested = ImGui::IsItemClicked(ImGuiMouseButton_Right);
        }
    }

    // The probed texel, outlined (or pointed at when texels are smaller than a few pixels).
    if (mark && mark->level == level) {
        float x0 = topLeft.x + float((mark->x - window.originX) * pixelsPerTexel);
        float y1 = bottomRight.y - float((mark->y - window.originY) * pixelsPerTexel);
        float side = float(pixelsPerTexel);
        draw->PushClipRect(topLeft, bottomRight, true);
        if (side >= 5.0f) {
            draw->AddRect(ImVec2(x0 - 1, y1 - side - 1), ImVec2(x0 + side + 1, y1 + 1),
                          IM_COL32(0, 0, 0, 255), 0, 0, 3);
            draw->AddRect(ImVec2(x0, y1 - side), ImVec2(x0 + side, y1), IM_COL32(255, 255, 255, 255), 0, 0,
                          1.5f);
        } else {
            ImVec2 c(x0 + side / 2, y1 - side / 2);
            draw->AddCircle(c, 7.0f, IM_COL32(0, 0, 0, 255), 16, 3.0f);
            draw->AddCircle(c, 7.0f, IM_COL32(255, 255, 255, 255), 16, 1.5f);
        }
        draw->PopClipRect();
    }
    draw->AddRect(topLeft, bottomRight, ui_style::packed(ImGui::GetStyleColorVec4(ImGuiCol_Border)));
    char zoomText[64];
    std::snprintf(zoomText, sizeof zoomText, pixelsPerTexel >= 1.0 ? "%.0f%%, %.3g px per texel" : "%.0f%%",
                  pixelsPerTexel * 100.0, pixelsPerTexel);
    ImVec2 textSize = ImGui::CalcTextSize(zoomText);
    ImVec2 textPos(bottomRight.x - textSize.x - 6, bottomRight.y - textSize.y - 4);
    draw->AddRectFilled(ImVec2(textPos.x - 3, textPos.y - 1), ImVec2(bottomRight.x - 3, bottomRight.y - 3),
                        IM_COL32(0, 0, 0, 160), 3.0f);
    draw->AddText(textPos, IM_COL32(230, 230, 230, 255), zoomText);
    return result;
}

}  // namespace fx
