// Windows always has its desktop: a program started there can open a window (the lessons never fall
// back to headless for want of a display).
#include "platform/context.hpp"

namespace fx {

bool displayAvailable() {
    return true;
}

}  // namespace fx
