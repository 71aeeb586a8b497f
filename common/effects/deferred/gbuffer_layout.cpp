#include "effects/deferred/gbuffer_layout.hpp"

#include <cmath>

#include <glm/geometric.hpp>

namespace fx {

GBufferFormats gbufferFormats(GBufferLayout layout) {
    GBufferFormats f;
    switch (layout) {
        case GBufferLayout::compact:
            break;
        case GBufferLayout::fat:
            f.normal = TextureFormat::RGBA16F;
            f.position = TextureFormat::RGBA16F;
            break;
        case GBufferLayout::fat32:
            f.normal = TextureFormat::RGBA32F;
            f.position = TextureFormat::RGBA32F;
            break;
        case GBufferLayout::rgba8Raw:
            f.normal = TextureFormat::RGBA8;
            f.position = TextureFormat::RGBA16F;
            break;
    }
    return f;
}

int gbufferBytesPerPixel(GBufferLayout layout) {
    GBufferFormats f = gbufferFormats(layout);
    int bytes = bytesPerTexel(f.albedo) + bytesPerTexel(f.normal) + bytesPerTexel(f.depth);
    if (f.position) bytes += bytesPerTexel(*f.position);
    return bytes;
}

const char* toString(GBufferLayout layout) {
    switch (layout) {
        case GBufferLayout::compact:
            return "compact";
        case GBufferLayout::fat:
            return "fat";
        case GBufferLayout::fat32:
            return "fat32";
        case GBufferLayout::rgba8Raw:
            return "rgba8Raw";
    }
    return "?";
}

std::vector<std::string> gbufferLayoutNames() {
    return {"compact", "fat", "fat32", "rgba8Raw"};
}

namespace {
float signNotZero(float v) {
    return v >= 0.0f ? 1.0f : -1.0f;
}
}  // namespace

glm::vec2 octahedralEncode(glm::vec3 n) {
    float l1 = std::abs(n.x) + std::abs(n.y) + std::abs(n.z);
    if (!(l1 > 1e-20f)) return glm::vec2(kNoNormalCode);
    glm::vec3 o = n / l1;
    if (o.z >= 0.0f) return {o.x, o.y};
    return {(1.0f - std::abs(o.y)) * signNotZero(o.x), (1.0f - std::abs(o.x)) * signNotZero(o.y)};
}

glm::vec3 octahedralDecode(glm::vec2 e) {
    if (std::abs(e.x) > 1.5f) return glm::vec3(0.0f);
    glm::vec3 n(e.x, e.y, 1.0f - std::abs(e.x) - std::abs(e.y));
    float t = std::max(-n.z, 0.0f);
    n.x -= t * signNotZero(n.x);
    n.y -= t * signNotZero(n.y);
    return glm::normalize(n);
}

float halfFloatSpacing(float x) {
    float a = std::abs(x);
    if (a < 6.103515625e-05f) return 5.9604645e-08f;  // subnormal range: 2^-24
    return std::ldexp(1.0f, int(std::floor(std::log2(a))) - 10);
}

}  // namespace fx
