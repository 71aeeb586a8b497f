#pragma once
// The chapter's homework: a planar reflection through a framebuffer. The scene is drawn a second time
// from the camera mirrored in the mirror's plane (view * R, R the reflection in the plane) into
// "reflection.color", with a clip plane (gl_ClipDistance) that drops everything below the mirror, so
// objects under or through the plane do not appear above it. Mirroring the camera rather than the
// objects leaves every world-space normal as it is (no negation, whatever the normal matrix); only the
// winding flips, so the pass culls front faces. Then "mirror surface" draws the mirror's plane again
// over the lit picture, depth-tested against the G-buffer's depth in its shader, and mixes the reflection in
// at the mirror's strength, fetched at the pixel's own place (both passes use the same projection).
//
// Both passes need SceneFeature::mirror: a scene without a mirror has no reflection pass.
#include <array>
#include <optional>

#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec4.hpp>

#include "effects/deferred/gbuffer_pass.hpp"
#include "effects/deferred/point_light_buffer.hpp"
#include "effects/scene/gpu_mesh.hpp"
#include "effects/scene/world.hpp"
#include "gl/program.hpp"

namespace fx {

// The mirror of a scene: its object's index and plane (unit normal n and d with n.p + d = 0 on it).
struct MirrorPlane {
    std::size_t object = 0;
    glm::vec4 plane{0, 1, 0, 0};
    float strength = 0.5f;
};
std::optional<MirrorPlane> findMirror(const Scene& scene, double seconds);

// The reflection in `plane` as a matrix: p - 2 (n.p + d) n. Its determinant is -1.
glm::mat4 reflectionMatrix(glm::vec4 plane);

// The raw-GL mistakes lesson 10 step 7 shows beside the way fxlab does it (off by default).
struct ReflectionMistakes {
    // Mirror the objects (model matrix times the reflection, determinant -1) under the unmirrored
    // camera, instead of mirroring the camera: the geometry lands where it does either way, but every
    // normal is mirrored and the sun is not, so the reflection is lit from below (hard cases 16, 18).
    bool mirrorObjects = false;
    // The colour the reflection target is cleared to (nullopt: the scene's sky, which is what a mirror
    // shows where nothing is reflected). The chapter's clear colour tints the empty mirror.
    std::optional<glm::vec3> clearColor;
};

// The homework's optional blur of the reflection: 16 taps around the pixel's place, each offset sigma
// times a standard-normal 2-D sample (reflectionBlurOffsets). sigma is in texture units (a fraction of
// the reflection's width and height); 0 takes one sharp tap.
struct ReflectionBlur {
    float sigma = 0.0f;
};
inline constexpr float kChapterReflectionBlurSigma = 0.005f;

// The 16 standard-normal samples, as the chapter's host makes them: Xorshift128 uniform numbers put
// through the Box-Muller transform, the same every run.
std::array<glm::vec2, 16> reflectionBlurOffsets();

class PlanarReflection {
public:
    // Builds the programs, and the mirror's mesh when `scene` has a mirror.
    explicit PlanarReflection(const Scene& scene);

    // "planar reflection" at `fraction` of the output (1, 2 or 4: full, half, quarter size), then
    // "mirror surface" over `lit` (modified in place). Returns reflection.color.
    TextureHandle declare(FrameGraph& graph, const World& world, const PointLightBuffer& lights,
                          const GBufferTargets& g, TextureHandle lit, int fraction,
                          const ReflectionMistakes& mistakes = {}, ReflectionBlur blur = {}) const;

private:
    gl::ReloadableProgram reflect_{{"effects/deferred/mirrored_scene.vert",
                                    "effects/deferred/reflection.frag",
                                    {},
                                    {},
                                    "planar reflection (mirrored camera)"}};
    gl::ReloadableProgram surface_{{"effects/deferred/lit_scene.vert",
                                    "effects/deferred/mirror_surface.frag",
                                    {},
                                    {},
                                    "mirror surface"}};
    GpuMesh mirrorMesh_;
};

}  // namespace fx
