#include "ui/texture_source.hpp"

#include <algorithm>

namespace fx {

TextureSource textureSource(const TextureView& view) {
    TextureSource s;
    // The presented output of a window is the default framebuffer: nothing to sample.
    s.native = view.origin == TextureOrigin::PresentedOutput ? 0 : view.native;
    s.spec = view.spec;
    s.spec.mipLevels = std::max(s.spec.mipLevels, 1);
    s.name = view.name;
    return s;
}

TextureSource textureSource(const gl::Texture& texture) {
    return {texture.name(), texture.spec(), texture.label()};
}

}  // namespace fx
