#pragma once
// Colour textures of materials on the GPU: PNG files from scene materials and glTF models, and
// images embedded in glTF files. Each file is uploaded once (sRGB, with mipmaps, repeating) and
// shared. A texture that cannot be read is logged once and replaced by plain white, so the material's
// colour factor still shows.
#include <filesystem>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "effects/scene/scene_bindings.hpp"
#include "gl/texture.hpp"

namespace fx {

class MaterialTextures {
public:
    MaterialTextures() = default;

    // The GL texture of a PNG file (0 only before the first call created the white fallback).
    GLuint file(const std::filesystem::path& path);
    // A texture from encoded PNG or JPEG bytes, keyed by `key` (the model file and image index).
    GLuint encoded(const std::string& key, const std::vector<unsigned char>& bytes);
    // 1x1 opaque white: what an untextured material samples.
    GLuint white();

    std::size_t loaded() const { return textures_.size(); }
    std::uint64_t bytes() const;
    const std::vector<std::string>& failures() const { return failures_; }

private:
    std::map<std::string, gl::Texture> textures_;
    gl::Texture white_;
    std::vector<std::string> failures_;

    GLuint upload(const std::string& key, const std::string& label, int width, int height,
                  const unsigned char* rgba);
};

}  // namespace fx
