// The glTF model builder: meshes (attributes, indices of every width, strips and fans).
#include "scene/gltf_model_builder.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <optional>

#include <glm/geometric.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "scene/gltf_loader.hpp"

#include "scene/gltf_accessor_reader.hpp"

namespace fx::gltf_detail {

Status ModelBuilder::readIndices(const tinygltf::Primitive& p, std::size_t vertices, const std::string& what,
                                 std::vector<std::uint32_t>& out) {
    std::vector<std::uint32_t> raw;
    if (p.indices >= 0) {
        auto r = AccessorReader::open(
            m_, p.indices, what + " indices",
            {1, {kUnsignedByte, kUnsignedShort, kUnsignedInt}, "unsigned 8-, 16- or 32-bit scalars"});
        if (!r) return Error{r.error()};
        raw.resize(r->count());
        for (std::size_t i = 0; i < raw.size(); ++i) {
            raw[i] = r->whole(i, 0);
            if (raw[i] >= vertices)
                return Error{cat(what, ": index ", raw[i], " is beyond the ", vertices, " vertices")};
        }
    } else {
        raw.resize(vertices);
        for (std::size_t i = 0; i < vertices; ++i) raw[i] = static_cast<std::uint32_t>(i);
    }
    int mode = p.mode < 0 ? kTriangles : p.mode;
    out.clear();
    if (mode == kTriangles) {
        out.assign(raw.begin(), raw.end() - static_cast<std::ptrdiff_t>(raw.size() % 3));
    } else if (mode == kTriangleStrip) {
        for (std::size_t i = 2; i < raw.size(); ++i) {
            bool even = (i % 2) == 0;
            out.insert(out.end(), {raw[i - 2], even ? raw[i - 1] : raw[i], even ? raw[i] : raw[i - 1]});
        }
    } else if (mode == kTriangleFan) {
        for (std::size_t i = 2; i < raw.size(); ++i) out.insert(out.end(), {raw[0], raw[i - 1], raw[i]});
    }
    return Status::success();
}

Status ModelBuilder::readMesh(std::size_t meshIndex) {
    const tinygltf::Mesh& src = m_.meshes[meshIndex];
    ModelMesh mesh;
    mesh.name = src.name;
    for (std::size_t pi = 0; pi < src.primitives.size(); ++pi) {
        const tinygltf::Primitive& p = src.primitives[pi];
        std::string what = cat(named("mesh", meshIndex, src.name), " primitive ", pi);
        int mode = p.mode < 0 ? kTriangles : p.mode;
        if (mode != kTriangles && mode != kTriangleStrip && mode != kTriangleFan) {
            warn(cat(what, ": points and lines are not drawn; skipped"));
            continue;
        }
        if (!p.targets.empty()) warn(cat(what, ": morph targets are ignored"));
        auto attribute = [&](const char* name) {
            auto it = p.attributes.find(name);
            return it == p.attributes.end() ? -1 : it->second;
        };
        int positionIndex = attribute("POSITION");
        if (positionIndex < 0) return Error{cat(what, ": has no POSITION attribute")};
        auto positions = AccessorReader::open(m_, positionIndex, what + " POSITION", {3, {}, "VEC3"});
        if (!positions) return Error{positions.error()};
        std::size_t n = positions->count();

        ModelPrimitive prim;
        prim.material = p.material;
        if (p.material >= 0 && static_cast<std::size_t>(p.material) >= model_.materials.size()) {
            warn(cat(what, ": material ", p.material, " does not exist; drawn with the default material"));
            prim.material = -1;
        }
        MeshData& data = prim.mesh;
        data.positions.resize(n);
        for (std::size_t i = 0; i < n; ++i) {
            glm::vec3 v(positions->vec(i));
            if (!std::isfinite(v.x) || !std::isfinite(v.y) || !std::isfinite(v.z))
                return Error{cat(what, ": position ", i, " is not finite")};
            data.positions[i] = v;
        }
        // Optional attributes must match the vertex count.
        auto openSized = [&](const char* name,
                             const AccessorShape& shape) -> Result<std::optional<AccessorReader>> {
            int index = attribute(name);
            if (index < 0) return std::optional<AccessorReader>{};
            auto r = AccessorReader::open(m_, index, cat(what, " ", name), shape);
            if (!r) return Error{r.error()};
            if (r->count() != n)
                return Error{cat(what, ": ", name, " has ", r->count(), " elements for ", n, " vertices")};
            return std::optional<AccessorReader>{*r};
        };
        auto normals = openSized("NORMAL", {3, {}, "VEC3"});
        if (!normals) return Error{normals.error()};
        auto uvs = openSized("TEXCOORD_0", {2, {}, "VEC2"});
        if (!uvs) return Error{uvs.error()};
        auto joints =
            openSized("JOINTS_0", {4, {kUnsignedByte, kUnsignedShort}, "unsigned 8- or 16-bit VEC4"});
        if (!joints) return Error{joints.error()};
        auto weights = openSized("WEIGHTS_0", {4,
                                               {kFloat, kUnsignedByte, kUnsignedShort},
                                               "VEC4 of float or normalised unsigned 8- or 16-bit"});
        if (!weights) return Error{weights.error()};

        data.uvs.assign(n, glm::vec2(0.0f));
        if (*uvs) {
            // glTF's v runs down from the top of the image; fxlab's (GL's) runs up from the bottom row.
            for (std::size_t i = 0; i < n; ++i) data.uvs[i] = {(*uvs)->real(i, 0), 1.0f - (*uvs)->real(i, 1)};
        }
        if (auto s = readIndices(p, n, what, data.indices); !s) return s;
        if (*normals) {
            data.normals.resize(n);
            for (std::size_t i = 0; i < n; ++i) data.normals[i] = glm::vec3((*normals)->vec(i));
        } else {
            computeNormals(data);
            prim.generatedNormals = true;
        }
        if (*joints && *weights) {
            prim.influences.resize(n);
            for (std::size_t i = 0; i < n; ++i) {
                JointInfluence& inf = prim.influences[i];
                for (int c = 0; c < 4; ++c)
                    inf.joints[c] = static_cast<std::uint16_t>((*joints)->whole(i, c));
                inf.weights = (*weights)->vec(i);
            }
        } else if (*joints || *weights) {
            warn(cat(what, ": JOINTS_0 without WEIGHTS_0 (or the reverse); drawn unskinned"));
        }
        mesh.primitives.push_back(std::move(prim));
    }
    model_.meshes.push_back(std::move(mesh));
    return Status::success();
}

}  // namespace fx::gltf_detail
