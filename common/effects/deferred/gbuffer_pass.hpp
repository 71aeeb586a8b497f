#pragma once
// The G-buffer pass of deferred shading: the scene's geometry once, no light, into several targets at
// once (gbuffer_layout.hpp says which). The lighting pass then reads them under each pixel.
//
//   GBufferPass gbuffer;  // its programs build when a frame first asks for a layout
//   GBufferTargets g = gbuffer.declare(graph, frame.world, {GBufferLayout::compact});
//
// A world offset moves the whole scene and its camera away from the origin by that many metres, so
// a lesson can show what storing world positions in half floats costs at 1,000 and 10,000 m.
#include <optional>

#include "effects/deferred/gbuffer_layout.hpp"
#include "effects/scene/camera_matrices.hpp"
#include "effects/scene/world.hpp"
#include "gl/program.hpp"
#include "render/frame_graph.hpp"

namespace fx {

struct GBufferOptions {
    GBufferLayout layout = GBufferLayout::compact;
    // Also write the world position in RGBA32F ("gbuffer.reference_position") to measure against.
    bool referencePosition = false;
    glm::vec3 worldOffset{0.0f};
};

struct GBufferTargets {
    GBufferLayout layout = GBufferLayout::compact;
    TextureHandle albedo;                            // "gbuffer.albedo"
    TextureHandle normal;                            // "gbuffer.normal"
    std::optional<TextureHandle> position;           // "gbuffer.position" (fat layouts)
    TextureHandle depth;                             // "gbuffer.depth"
    std::optional<TextureHandle> referencePosition;  // "gbuffer.reference_position"
    glm::vec3 worldOffset{0.0f};
};

// The scene's camera moved by `offset`, and its matrices at `size`: what the G-buffer pass drew with and
// what the lighting pass rebuilds positions with.
CameraMatrices offsetCameraMatrices(const Camera& camera, glm::vec3 offset, Size2D size);

class GBufferPass {
public:
    // Declares "gbuffer": `world` at its time.
    GBufferTargets declare(FrameGraph& graph, const World& world, const GBufferOptions& options) const;

    // The program for a layout (built the first time it is asked for).
    const gl::ReloadableProgram& program(GBufferLayout layout, bool referencePosition) const;

private:
    // One program per layout, with and without the reference position: [layout * 2 + reference].
    mutable std::optional<gl::ReloadableProgram> programs_[8];
};

}  // namespace fx
