#pragma once
// A texture as the inspector sees it: its GL name (0 while the texture is not alive) and what GL
// needs to read it. Built from the frame graph's view of a texture, or from a gl::Texture in tests.
#include "gl/texture.hpp"
#include "render/graph_texture.hpp"

namespace fx {

struct TextureSource {
    GLuint native = 0;
    gl::TextureInfo info;  // label = the texture's name

    bool alive() const { return native != 0; }
    int levels() const { return info.levels; }
    Size2D levelSize(int level) const {
        return {gl::mipSize(info.width, level), gl::mipSize(info.height, level)};
    }
};

TextureSource textureSource(const TextureView& view);
TextureSource textureSource(const gl::Texture& texture);

}  // namespace fx
