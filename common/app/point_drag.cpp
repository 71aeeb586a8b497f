#include "app/point_drag.hpp"

namespace fx {

std::optional<glm::vec2> PointDrag::update(const FrameInfo& frame) {
    const Pointer& p = frame.pointer;
    bool down = p.present && p.leftDown;
    if (down && !wasDown_ && !p.overUi) dragging_ = true;  // the press starts on the picture
    if (!down) dragging_ = false;
    wasDown_ = down;
    if (!dragging_ || frame.size.empty()) return std::nullopt;
    return glm::vec2(p.x / float(frame.size.width), p.y / float(frame.size.height));
}

}  // namespace fx
