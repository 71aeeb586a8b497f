#pragma once
// Writes glTF 2.0 files: a .gltf document (JSON) and one .bin buffer. Data goes in through typed
// helpers that align every buffer view to 4 bytes and give POSITION accessors their min and max, as
// the spec requires. Floats are snapped to a 2^-20 grid before they are stored, so the tiny
// differences a maths library could make in the last bit do not reach the committed bytes.
#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>
#include <nlohmann/json.hpp>

namespace fx::assetgen {

using Json = nlohmann::ordered_json;

// The value on the 2^-20 grid nearest to v.
float snap(float v);
glm::vec3 snap(glm::vec3 v);
// The shortest decimal that reads back as the same float (0.95f -> 0.95, not 0.949999988079071), for
// numbers written into the JSON document.
double decimal(float v);
Json decimals(glm::vec3 v);

class GltfBuilder {
public:
    // `binUri` is the buffer's file name, relative to the .gltf (e.g. "character.bin").
    explicit GltfBuilder(std::string binUri);

    // Accessors; each returns the accessor index.
    int addPositions(const std::vector<glm::vec3>& values);  // with min and max
    int addVec3(const std::vector<glm::vec3>& values);
    int addVec2(const std::vector<glm::vec2>& values);
    int addVec4(const std::vector<glm::vec4>& values);
    int addJoints8(const std::vector<std::array<std::uint8_t, 4>>& values);
    // Normalised unsigned bytes (value / 255), as glTF allows for WEIGHTS_0.
    int addWeights8(const std::vector<std::array<std::uint8_t, 4>>& values);
    int addIndices16(const std::vector<std::uint32_t>& values);  // values must be < 65536
    int addIndices32(const std::vector<std::uint32_t>& values);
    // Key times with min and max (the spec requires them for animation inputs); the same list twice
    // gives the same accessor.
    int addTimes(const std::vector<float>& values);
    int addMat4(const std::vector<glm::mat4>& values);

    int addImage(const std::string& uri);
    int addTexture(int image);  // with a repeating, mipmapped sampler
    int addMaterial(Json material);
    int addMesh(Json mesh);
    int addNode(Json node);
    int addSkin(Json skin);
    int addAnimation(Json animation);
    // Children are set after the nodes exist.
    Json& node(int index) { return doc_["nodes"][static_cast<std::size_t>(index)]; }
    void setSceneRoots(const std::vector<int>& roots);
    void useExtension(const std::string& name);

    // The finished files.
    std::string gltfText() const;
    const std::vector<std::byte>& binBytes() const { return bin_; }

private:
    Json doc_;
    std::vector<std::byte> bin_;
    int sampler_ = -1;
    std::vector<std::pair<std::vector<float>, int>> times_;

    int addView(const void* data, std::size_t bytes, int target);
    int addAccessor(int view, int componentType, std::size_t count, const char* type,
                    Json extra = Json::object());
    int append(const char* array, Json value);
};

}  // namespace fx::assetgen
