#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>
#include <glm/gtc/constants.hpp>

#include "geometry/mesh_data.hpp"

namespace fx {
namespace {

void addQuad(MeshData& m, glm::vec3 origin, glm::vec3 u, glm::vec3 v, glm::vec3 normal) {
    auto base = static_cast<std::uint32_t>(m.positions.size());
    const glm::vec2 uv[4] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    const glm::vec3 corners[4] = {origin, origin + u, origin + u + v, origin + v};
    for (int i = 0; i < 4; ++i) {
        m.positions.push_back(corners[i]);
        m.normals.push_back(normal);
        m.uvs.push_back(uv[i]);
    }
    for (std::uint32_t i : {0u, 1u, 2u, 0u, 2u, 3u}) m.indices.push_back(base + i);
}

// A surface of revolution around Y from a profile of (radius, y, normal-in-profile) points.
struct ProfilePoint {
    float radius, y;
    glm::vec2 normal;  // (outward, up)
    float v;
};

void addRevolution(MeshData& m, const std::vector<ProfilePoint>& profile, int segments) {
    auto base = static_cast<std::uint32_t>(m.positions.size());
    for (const ProfilePoint& p : profile) {
        for (int s = 0; s <= segments; ++s) {
            float t = float(s) / float(segments);
            float angle = t * glm::two_pi<float>();
            glm::vec3 dir(std::sin(angle), 0.0f, std::cos(angle));
            m.positions.push_back(dir * p.radius + glm::vec3(0, p.y, 0));
            glm::vec3 n = dir * p.normal.x + glm::vec3(0, p.normal.y, 0);
            float len = glm::length(n);
            m.normals.push_back(len > 0 ? n / len : glm::vec3(0, 1, 0));
            m.uvs.push_back({t, p.v});
        }
    }
    auto row = static_cast<std::uint32_t>(segments + 1);
    for (std::uint32_t r = 0; r + 1 < profile.size(); ++r) {
        for (std::uint32_t s = 0; s < static_cast<std::uint32_t>(segments); ++s) {
            std::uint32_t a = base + r * row + s, b = a + 1, c = a + row, d = c + 1;
            // Profiles run bottom to top; this winding faces outward.
            for (std::uint32_t i : {a, b, d, a, d, c}) m.indices.push_back(i);
        }
    }
}

void addDisc(MeshData& m, float radius, float y, bool up, int segments) {
    auto centre = static_cast<std::uint32_t>(m.positions.size());
    glm::vec3 normal(0, up ? 1.0f : -1.0f, 0);
    m.positions.push_back({0, y, 0});
    m.normals.push_back(normal);
    m.uvs.push_back({0.5f, 0.5f});
    for (int s = 0; s <= segments; ++s) {
        float angle = float(s) / float(segments) * glm::two_pi<float>();
        m.positions.push_back({radius * std::sin(angle), y, radius * std::cos(angle)});
        m.normals.push_back(normal);
        m.uvs.push_back({0.5f + 0.5f * std::sin(angle), 0.5f + 0.5f * std::cos(angle)});
    }
    for (std::uint32_t s = 0; s < static_cast<std::uint32_t>(segments); ++s) {
        std::uint32_t a = centre + 1 + s, b = a + 1;
        if (up) {
            for (std::uint32_t i : {centre, a, b}) m.indices.push_back(i);
        } else {
            for (std::uint32_t i : {centre, b, a}) m.indices.push_back(i);
        }
    }
}

}  // namespace

MeshData makePlane(float sizeX, float sizeZ) {
    MeshData m;
    addQuad(m, {-sizeX / 2, 0, sizeZ / 2}, {sizeX, 0, 0}, {0, 0, -sizeZ}, {0, 1, 0});
    return m;
}

MeshData makeBox(glm::vec3 size) {
    MeshData m;
    glm::vec3 h = size * 0.5f;
    addQuad(m, {-h.x, -h.y, h.z}, {size.x, 0, 0}, {0, size.y, 0}, {0, 0, 1});    // front
    addQuad(m, {h.x, -h.y, -h.z}, {-size.x, 0, 0}, {0, size.y, 0}, {0, 0, -1});  // back
    addQuad(m, {h.x, -h.y, h.z}, {0, 0, -size.z}, {0, size.y, 0}, {1, 0, 0});    // right
    addQuad(m, {-h.x, -h.y, -h.z}, {0, 0, size.z}, {0, size.y, 0}, {-1, 0, 0});  // left
    addQuad(m, {-h.x, h.y, h.z}, {size.x, 0, 0}, {0, 0, -size.z}, {0, 1, 0});    // top
    addQuad(m, {-h.x, -h.y, -h.z}, {size.x, 0, 0}, {0, 0, size.z}, {0, -1, 0});  // bottom
    return m;
}

MeshData makeSphere(float radius, int segments, int rings) {
    segments = std::max(segments, 3);
    rings = std::max(rings, 2);
    std::vector<ProfilePoint> profile;
    for (int r = 0; r <= rings; ++r) {
        float phi = glm::pi<float>() * (1.0f - float(r) / float(rings));  // bottom pole to top pole
        glm::vec2 n(std::sin(phi), std::cos(phi));
        profile.push_back({radius * n.x, radius * n.y, n, float(r) / float(rings)});
    }
    MeshData m;
    addRevolution(m, profile, segments);
    return m;
}

MeshData makeCylinder(float radius, float height, int segments) {
    segments = std::max(segments, 3);
    MeshData m;
    addRevolution(m, {{radius, -height / 2, {1, 0}, 0}, {radius, height / 2, {1, 0}, 1}}, segments);
    addDisc(m, radius, height / 2, true, segments);
    addDisc(m, radius, -height / 2, false, segments);
    return m;
}

MeshData makeCapsule(float radius, float height, int segments, int capRings) {
    segments = std::max(segments, 3);
    capRings = std::max(capRings, 1);
    float half = std::max(height / 2 - radius, 0.0f);
    std::vector<ProfilePoint> profile;
    float total = 2 * half + 2 * radius;
    auto v = [&](float y) { return total > 0 ? (y + half + radius) / total : 0.0f; };
    for (int r = 0; r <= capRings; ++r) {  // bottom cap, pole to equator
        float phi = glm::pi<float>() * (1.0f - 0.5f * float(r) / float(capRings));
        glm::vec2 n(std::sin(phi), std::cos(phi));
        float y = -half + radius * n.y;
        profile.push_back({radius * n.x, y, n, v(y)});
    }
    for (int r = 0; r <= capRings; ++r) {  // top cap, equator to pole
        float phi = glm::half_pi<float>() * (1.0f - float(r) / float(capRings));
        glm::vec2 n(std::sin(phi), std::cos(phi));
        float y = half + radius * n.y;
        profile.push_back({radius * n.x, y, n, v(y)});
    }
    MeshData m;
    addRevolution(m, profile, segments);
    return m;
}

}  // namespace fx
