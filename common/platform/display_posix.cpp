// A window system on Linux: X11 or Wayland, as the environment names it.
#include <cstdlib>

#include "platform/context.hpp"

namespace fx {

bool displayAvailable() {
    const char* x = std::getenv("DISPLAY");
    const char* wayland = std::getenv("WAYLAND_DISPLAY");
    return (x && *x) || (wayland && *wayland);
}

}  // namespace fx
