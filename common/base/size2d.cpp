#include "base/size2d.hpp"

#include "base/log.hpp"

namespace fx {

std::string toString(Size2D size) {
    return cat(size.width, "x", size.height);
}

}  // namespace fx
