// The generated assets load on the GPU: every texture uploads at its size, every model builds its
// buffers, and the shipped scenes that use them have nothing left undrawn.
#include <filesystem>

#include "base/paths.hpp"
#include "effects/scene/gpu_model.hpp"
#include "effects/scene/scene_meshes.hpp"
#include "gl/readback.hpp"
#include "gl_test.hpp"
#include "scene/gltf_loader.hpp"
#include "scene/scene_loader.hpp"

using namespace fx;
namespace fs = std::filesystem;

class GeneratedAssets : public GlTest {};

TEST_F(GeneratedAssets, TexturesUploadWithTheirSizes) {
    MaterialTextures textures;
    struct Expected {
        const char* file;
        int size;
    } expected[] = {{"ground_checker.png", 256},
                    {"cloud_density.png", 512},
                    {"fire_sprite.png", 256},
                    {"crate_planks.png", 256},
                    {"suit_fabric.png", 256}};
    for (const auto& e : expected) {
        SCOPED_TRACE(e.file);
        GLuint texture = textures.file(resourceDir() / "textures" / e.file);
        ASSERT_NE(texture, textures.white());
        GLint width = 0, height = 0, format = 0;
        glGetTextureLevelParameteriv(texture, 0, GL_TEXTURE_WIDTH, &width);
        glGetTextureLevelParameteriv(texture, 0, GL_TEXTURE_HEIGHT, &height);
        glGetTextureLevelParameteriv(texture, 0, GL_TEXTURE_INTERNAL_FORMAT, &format);
        EXPECT_EQ(width, e.size);
        EXPECT_EQ(height, e.size);
        EXPECT_EQ(format, GL_SRGB8_ALPHA8);
    }
    EXPECT_TRUE(textures.failures().empty());
    // The fire sprite's alpha survives the upload: the top-left texel is transparent, the base opaque.
    GLuint fire = textures.file(resourceDir() / "textures/fire_sprite.png");
    TextureSpec info{256, 256, TextureFormat::SRGB8_ALPHA8, 9};
    EXPECT_EQ(gl::readTexel(fire, info, 0, 0, 255).value[3], 0.0f);
    EXPECT_GT(gl::readTexel(fire, info, 0, 128, 70).value[3], 0.95f);  // v = 0.27: the round base
}

TEST_F(GeneratedAssets, ModelsBuildTheirBuffers) {
    MaterialTextures textures;
    for (const char* name : {"character", "crate", "lantern", "ground"}) {
        SCOPED_TRACE(name);
        auto model = loadGltf(resourceDir() / "models" / (std::string(name) + ".gltf"));
        ASSERT_TRUE(model.ok()) << model.error();
        EXPECT_TRUE(model->warnings.empty()) << model->warnings.front();
        auto shared = std::make_shared<const GltfModel>(std::move(*model));
        GpuModel gpu(shared, textures, name);
        EXPECT_EQ(gpu.nodeWorld().size(), shared->nodes.size());
        EXPECT_EQ(gpu.unweightedVertices(), 0u);
        std::size_t expectedSkinned =
            std::string(name) == "character" ? shared->meshes[0].primitives.size() : 0;
        EXPECT_EQ(gpu.skinnedMeshes(), expectedSkinned);
    }
    EXPECT_TRUE(textures.failures().empty());
    EXPECT_GE(textures.loaded(), 3u);  // suit fabric, crate planks, ground checker
}

TEST_F(GeneratedAssets, ShippedScenesDrawEveryObject) {
    for (const auto& entry : fs::directory_iterator(resourceDir() / "scenes")) {
        SCOPED_TRACE(entry.path().filename().string());
        auto scene = loadScene(entry.path());  // with the existence check on
        ASSERT_TRUE(scene.ok()) << scene.error();
        SceneMeshes meshes(*scene);
        EXPECT_TRUE(meshes.notDrawn().empty()) << meshes.notDrawn().front();
        EXPECT_EQ(meshes.drawnObjects(), scene->objects.size());
        EXPECT_TRUE(meshes.textures().failures().empty());
    }
}
