#include "effects/scene_meshes.hpp"

#include <glm/geometric.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "base/log.hpp"

namespace fx {
namespace {

MeshData meshFor(const Primitive& p) {
    switch (p.shape) {
        case PrimitiveShape::plane: return makePlane(p.planeSize.x, p.planeSize.y);
        case PrimitiveShape::box: return makeBox(p.boxSize);
        case PrimitiveShape::sphere: return makeSphere(p.radius, 48, 24);
        case PrimitiveShape::cylinder: return makeCylinder(p.radius, p.height, 48);
        case PrimitiveShape::capsule: return makeCapsule(p.radius, p.height, 48, 12);
    }
    return {};
}

}  // namespace

SceneMeshes::SceneMeshes(const Scene& scene) {
    for (const SceneObject& object : scene.objects) {
        if (object.primitive) {
            meshes_.emplace_back(meshFor(*object.primitive), object.name.empty() ? "object" : object.name);
        } else {
            meshes_.emplace_back();
            notDrawn_.push_back(object.name + " (glTF, drawn by the skinned-mesh path)");
        }
    }
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
    glProgramUniformMatrix4fv(program, uniform_location::viewProjection, 1, GL_FALSE, glm::value_ptr(camera.viewProjection));
    glProgramUniform3fv(program, uniform_location::lightDirection, 1, glm::value_ptr(toLight));
    glProgramUniform3fv(program, uniform_location::lightColor, 1, glm::value_ptr(lightColor));
    glProgramUniform3fv(program, uniform_location::ambient, 1, glm::value_ptr(scene.ambient));
    glProgramUniform3fv(program, uniform_location::cameraPosition, 1, glm::value_ptr(camera.position));
}

void SceneMeshes::draw(GLuint program, const Scene& scene, double seconds) const {
    glUseProgram(program);
    for (std::size_t i = 0; i < meshes_.size() && i < scene.objects.size(); ++i) {
        if (meshes_[i].indexCount() == 0) continue;
        const SceneObject& object = scene.objects[i];
        glm::mat4 model = modelAt(object, seconds);
        glm::vec3 emitted = object.material.emitted();
        glProgramUniformMatrix4fv(program, uniform_location::model, 1, GL_FALSE, glm::value_ptr(model));
        glProgramUniform3fv(program, uniform_location::baseColor, 1, glm::value_ptr(object.material.baseColor));
        glProgramUniform3fv(program, uniform_location::emissive, 1, glm::value_ptr(emitted));
        meshes_[i].draw();
    }
}

std::size_t SceneMeshes::drawnObjects() const {
    std::size_t n = 0;
    for (auto& m : meshes_) n += m.indexCount() > 0 ? 1 : 0;
    return n;
}

}  // namespace fx
