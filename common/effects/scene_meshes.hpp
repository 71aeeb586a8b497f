#pragma once
// The GPU side of a scene's objects: one mesh per built-in primitive, and a draw call per object
// with its model matrix and material in the uniforms every lit shader declares (shaders/common/
// scene_uniforms.glsl). Objects that come from glTF files are drawn by the skinning code once it
// exists; here they are counted and listed as not drawn.
#include <string>
#include <vector>

#include <glm/mat4x4.hpp>

#include "effects/camera_matrices.hpp"
#include "effects/gpu_mesh.hpp"
#include "scene/scene.hpp"

namespace fx {

// Uniform locations shared by the lit shaders (explicit, as in the chapter's location map).
namespace uniform_location {
inline constexpr GLint model = 0;
inline constexpr GLint viewProjection = 2;
inline constexpr GLint baseColor = 3;
inline constexpr GLint emissive = 4;
inline constexpr GLint lightDirection = 10;  // towards the light, normalised
inline constexpr GLint lightColor = 11;      // HDR colour times intensity
inline constexpr GLint ambient = 12;
inline constexpr GLint cameraPosition = 13;
}  // namespace uniform_location

class SceneMeshes {
public:
    SceneMeshes() = default;
    explicit SceneMeshes(const Scene& scene);

    // Model matrix of an object at a time (its transform plus its simple motion).
    static glm::mat4 modelAt(const SceneObject& object, double seconds);

    // Sets the camera and the first directional light (or a default one) on `program`.
    static void setFrameUniforms(GLuint program, const Scene& scene, const CameraMatrices& camera);
    // Draws every primitive object with its material.
    void draw(GLuint program, const Scene& scene, double seconds) const;

    std::size_t drawnObjects() const;
    const std::vector<std::string>& notDrawn() const { return notDrawn_; }

private:
    std::vector<GpuMesh> meshes_;      // per object; empty mesh for objects not drawn here
    std::vector<std::string> notDrawn_;
};

}  // namespace fx
