#include "effects/scene/scene_meshes.hpp"

#include <glm/geometric.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "base/log.hpp"
#include "scene/clip_selection.hpp"
#include "scene/gltf_loader.hpp"

namespace fx {
namespace {

MeshData meshFor(const Primitive& p) {
    switch (p.shape) {
        case PrimitiveShape::plane:
            return makePlane(p.planeSize.x, p.planeSize.y);
        case PrimitiveShape::box:
            return makeBox(p.boxSize);
        case PrimitiveShape::sphere:
            return makeSphere(p.radius, 48, 24);
        case PrimitiveShape::cylinder:
            return makeCylinder(p.radius, p.height, 48);
        case PrimitiveShape::capsule:
            return makeCapsule(p.radius, p.height, 48, 12);
    }
    return {};
}

}  // namespace

SceneMeshes::~SceneMeshes() = default;
SceneMeshes::SceneMeshes(SceneMeshes&&) noexcept = default;
SceneMeshes& SceneMeshes::operator=(SceneMeshes&&) noexcept = default;

SceneMeshes::SceneMeshes(const Scene& scene) : textures_(std::make_unique<MaterialTextures>()) {
    bool needsSkinning = false;
    for (const SceneObject& object : scene.objects) {
        ObjectMeshes meshes;
        std::string label = object.name.empty() ? "object" : object.name;
        if (object.primitive) {
            meshes.primitive = GpuMesh(meshFor(*object.primitive), label);
            if (!object.material.baseColorTexture.empty())
                meshes.baseColorTexture = textures_->file(object.material.baseColorTexture.resolved);
            objects_.push_back(std::move(meshes));
            continue;
        }
        // A glTF object: the file is read once however many objects use it.
        std::string key = object.gltf.resolved.string();
        auto cached = files_.find(key);
        if (cached == files_.end()) {
            auto loaded = loadGltf(object.gltf.resolved);
            if (!loaded) {
                log::error(loaded.error());
                notDrawn_.push_back(cat(label, " (", loaded.error(), ")"));
                objects_.push_back(std::move(meshes));
                continue;
            }
            cached = files_.emplace(key, std::make_shared<const GltfModel>(std::move(*loaded))).first;
        }
        meshes.model = std::make_unique<GpuModel>(cached->second, *textures_, label);
        // The scene's texture replaces the model's own (lesson 02 dresses a character in a cut-out lattice).
        if (!object.material.baseColorTexture.empty())
            meshes.baseColorTexture = textures_->file(object.material.baseColorTexture.resolved);
        if (!object.animation.clips.empty()) {
            auto clip = selectClips(*cached->second, object.animation);
            meshes.speed = object.animation.speed;
            if (clip)
                meshes.clip = std::make_shared<const AnimationClip>(std::move(*clip));
            else
                log::warning(label, ": ", object.gltf.path, " ", clip.error(), "; drawn in its rest pose");
        }
        needsSkinning = needsSkinning || meshes.model->skinnedMeshes() > 0;
        objects_.push_back(std::move(meshes));
    }
    // The skinning program exists only when the scene has something to skin.
    if (needsSkinning) skinning_ = std::make_unique<GpuSkinning>();
}

glm::mat4 SceneMeshes::modelAt(const SceneObject& object, double seconds) {
    Transform t = object.transform;
    t.position += motionOffset(object.motion, seconds);
    return modelMatrix(t);
}

void SceneMeshes::setFrameUniforms(GLuint program, const Scene& scene, const CameraMatrices& camera) {
    glm::vec3 toLight = glm::normalize(glm::vec3(0.4f, 1.0f, 0.3f));
    glm::vec3 lightColor(1.0f);
    for (const Light& light : scene.lights) {
        if (light.type == LightType::directional) {
            float len = glm::length(light.direction);
            if (len > 0.0f) toLight = -light.direction / len;  // the light shines along direction
            lightColor = light.color * light.intensity;
            break;
        }
    }
    glProgramUniformMatrix4fv(program, glsl::kViewProjectionLocation, 1, GL_FALSE,
                              glm::value_ptr(camera.viewProjection));
    glProgramUniform3fv(program, glsl::kToLightLocation, 1, glm::value_ptr(toLight));
    glProgramUniform3fv(program, glsl::kLightColorLocation, 1, glm::value_ptr(lightColor));
    glProgramUniform3fv(program, glsl::kAmbientLocation, 1, glm::value_ptr(scene.ambient));
    glProgramUniform3fv(program, glsl::kCameraPositionLocation, 1, glm::value_ptr(camera.position));
}

void SceneMeshes::pose(double seconds) const {
    bool any = false;
    clipTimes_.resize(objects_.size(), 0.0f);
    for (std::size_t i = 0; i < objects_.size(); ++i) {
        const ObjectMeshes& o = objects_[i];
        if (!o.model || !o.clip) continue;
        // Wrapped in double precision first: hours of play give the same pose as the first loop.
        clipTimes_[i] = fx::clipTime(seconds * double(o.speed), o.clip->duration);
        o.model->animate(o.clip.get(), clipTimes_[i], skinning_.get());
        if (o.model->skinnedMeshes() > 0) any = true;
    }
    if (any) ++skinningUpdates_;
    posedAt_ = seconds;
    posed_ = true;
}

void SceneMeshes::update(double seconds) {
    pose(seconds);
}

void SceneMeshes::draw(GLuint program, const Scene& scene, double seconds) const {
    (void)draw(program, scene, seconds, MeshDrawOptions{});
}

std::size_t SceneMeshes::draw(GLuint program, const Scene& scene, double seconds,
                              const MeshDrawOptions& options) const {
    if (!posed_ || posedAt_ != seconds) pose(seconds);
    glUseProgram(program);
    GLuint white = textures_->white();
    std::size_t drawn = 0;
    for (std::size_t i = 0; i < objects_.size() && i < scene.objects.size(); ++i) {
        const ObjectMeshes& meshes = objects_[i];
        const SceneObject& object = scene.objects[i];
        if (options.shadowCastersOnly && !object.castsShadows) continue;
        if (options.only && !options.only(object)) continue;
        if (options.skinFilter == SkinFilter::withoutSkin && isSkinned(i)) continue;
        if (options.skinFilter == SkinFilter::skinnedOnly && !isSkinned(i)) continue;
        glm::mat4 model = options.placement * modelAt(object, seconds);
        if (meshes.model) {
            if (!options.models) continue;
            ModelDrawStyle style;
            style.tint = object.material.baseColor;
            style.addedEmissive = object.material.emitted();
            style.setMaterial = options.setMaterial;
            style.bindTextures = options.bindTextures;
            style.baseColorTexture = meshes.baseColorTexture;
            style.skinned = options.skinned;
            meshes.model->draw(program, model, style);
            ++drawn;
            continue;
        }
        if (!options.primitives || meshes.primitive.indexCount() == 0) continue;
        glProgramUniformMatrix4fv(program, glsl::kModelLocation, 1, GL_FALSE, glm::value_ptr(model));
        if (options.setMaterial) {
            glm::vec3 emitted = object.material.emitted();
            glProgramUniform3fv(program, glsl::kBaseColorLocation, 1,
                                glm::value_ptr(object.material.baseColor));
            glProgramUniform3fv(program, glsl::kEmissiveLocation, 1, glm::value_ptr(emitted));
        }
        if (options.bindTextures) {
            glBindTextureUnit(glsl::kBaseColorTextureBinding,
                              meshes.baseColorTexture ? meshes.baseColorTexture : white);
            glBindTextureUnit(glsl::kEmissiveTextureBinding, white);
        }
        meshes.primitive.draw();
        ++drawn;
    }
    return drawn;
}

bool SceneMeshes::isSkinned(std::size_t index) const {
    return index < objects_.size() && objects_[index].model && objects_[index].model->skinnedMeshes() > 0;
}

std::size_t SceneMeshes::drawnObjects() const {
    std::size_t n = 0;
    for (const auto& o : objects_) n += (o.primitive.indexCount() > 0 || o.model) ? 1 : 0;
    return n;
}

std::size_t SceneMeshes::skinnedObjects() const {
    std::size_t n = 0;
    for (const auto& o : objects_) n += (o.model && o.model->skinnedMeshes() > 0) ? 1 : 0;
    return n;
}

const GpuModel* SceneMeshes::model(std::size_t index) const {
    return index < objects_.size() ? objects_[index].model.get() : nullptr;
}

float SceneMeshes::clipTime(std::size_t index) const {
    return index < clipTimes_.size() ? clipTimes_[index] : 0.0f;
}

}  // namespace fx
