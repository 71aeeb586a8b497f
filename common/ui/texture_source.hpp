#pragma once
// A texture as the inspector sees it: its GL name (0 while the texture is not alive) and what GL
// needs to read it. Built from the frame graph's view of a texture, or from a gl::Texture in tests.
#include <string>

#include "gl/texture.hpp"
#include "render/graph_texture.hpp"

namespace fx {

struct TextureSource {
    GLuint native = 0;
    TextureSpec spec;
    std::string name;

    bool alive() const { return native != 0; }
    int levels() const { return spec.mipLevels; }
    Size2D levelSize(int level) const { return spec.levelSize(level); }
};

TextureSource textureSource(const TextureView& view);
TextureSource textureSource(const gl::Texture& texture);

}  // namespace fx
