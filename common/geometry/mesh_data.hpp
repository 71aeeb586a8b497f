#pragma once
// Triangle meshes on the CPU: the built-in primitives a scene can ask for, generated with normals
// and texture coordinates, counter-clockwise front faces, indices into one vertex array.
#include <cstdint>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace fx {

struct MeshData {
    std::vector<glm::vec3> positions;
    std::vector<glm::vec3> normals;
    std::vector<glm::vec2> uvs;
    std::vector<std::uint32_t> indices;

    std::size_t vertexCount() const { return positions.size(); }
    std::size_t triangleCount() const { return indices.size() / 3; }
};

// A plane in XZ facing +Y, centred on the origin.
MeshData makePlane(float sizeX, float sizeZ);
// A box centred on the origin, flat-shaded (4 vertices a face).
MeshData makeBox(glm::vec3 size);
// A UV sphere; segments around Y (at least 3), rings from pole to pole (at least 2).
MeshData makeSphere(float radius, int segments = 32, int rings = 16);
// A capped cylinder along Y, centred on the origin.
MeshData makeCylinder(float radius, float height, int segments = 32);
// A cylinder with hemispherical caps; `height` includes the caps (at least 2 radius).
MeshData makeCapsule(float radius, float height, int segments = 32, int capRings = 8);

}  // namespace fx
