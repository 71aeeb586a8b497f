#pragma once
// The lighting deferred shading replaces, shown on purpose (lesson 10 step 4's `lighting`): the scene
// drawn forward with its light computed at the vertices and interpolated (Gouraud), as the slides' MRT
// shader receives it. The same light as the mirror's pass (ambient, the sun without its shadow, every
// point light, specular 0.3 and shininess 40), but a floor of 4 vertices samples it at 4 corners: a
// point light's highlight in the middle of the quad is not at any vertex and is lost. Per pixel, the
// deferred pass evaluates it where it is. "per-vertex lighting" -> forward.per_vertex (RGBA16F).
#include "effects/deferred/point_light_buffer.hpp"
#include "effects/scene/world.hpp"
#include "gl/program.hpp"
#include "render/frame_graph.hpp"

namespace fx {

class PerVertexLighting {
public:
    TextureHandle declare(FrameGraph& graph, const World& world, const PointLightBuffer& lights) const;

private:
    gl::ReloadableProgram program_{{"effects/deferred/per_vertex_lit.vert",
                                    "effects/deferred/per_vertex_lit.frag",
                                    {},
                                    {},
                                    "per-vertex lighting (Gouraud)"}};
};

}  // namespace fx
