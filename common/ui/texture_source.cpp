#include "ui/texture_source.hpp"

#include "render_gl/gl_formats.hpp"

namespace fx {

TextureSource textureSource(const TextureView& view) {
    TextureSource s;
    // The presented output of a window is the default framebuffer: nothing to sample.
    s.native = view.origin == TextureOrigin::PresentedOutput ? 0 : view.native;
    s.info = {view.spec.width, view.spec.height, std::max(view.spec.mipLevels, 1),
              glInternalFormat(view.spec.format), view.name};
    return s;
}

TextureSource textureSource(const gl::Texture& texture) {
    return {texture.name(), texture.info()};
}

}  // namespace fx
