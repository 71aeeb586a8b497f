#pragma once
// A 2D texture with immutable storage, described by the same TextureSpec the frame graph resolves
// (size, format, mip levels), plus its label.
#include <string>
#include <string_view>

#include "base/texture_spec.hpp"
#include "gl/object.hpp"

namespace fx::gl {

class Texture {
public:
    Texture() = default;
    // Immutable storage (glTextureStorage2D); sizes are clamped to at least 1x1, levels to at least 1.
    static Texture create2D(TextureFormat format, int width, int height, int levels, std::string_view label);

    GLuint name() const { return name_.name(); }
    explicit operator bool() const { return static_cast<bool>(name_); }
    const TextureSpec& spec() const { return spec_; }
    const std::string& label() const { return label_; }
    int width() const { return spec_.width; }
    int height() const { return spec_.height; }
    void relabel(std::string_view label);

private:
    TextureName name_;
    TextureSpec spec_;
    std::string label_;
};

}  // namespace fx::gl
