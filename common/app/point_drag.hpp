#pragma once
// Dragging a point on the picture with the mouse (a blur centre, a split-view divider): a press that
// starts on the picture, not on the overlay, grabs it, and it follows the pointer until release.
#include <optional>

#include <glm/vec2.hpp>

#include "app/lesson.hpp"

namespace fx {

class PointDrag {
public:
    // Where the point is while dragged, in texture coordinates of the frame (0..1 on screen, bottom
    // left origin); nullopt when it is not being dragged this frame.
    std::optional<glm::vec2> update(const FrameInfo& frame);
    bool dragging() const { return dragging_; }

private:
    bool dragging_ = false;
    bool wasDown_ = false;
};

}  // namespace fx
