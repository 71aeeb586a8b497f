#include "effects/deferred/planar_reflection.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>

#include <glm/geometric.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <glm/matrix.hpp>

#include "base/log.hpp"
#include "effects/deferred/deferred_bindings.hpp"
#include "effects/scene/hdr_scene_pass.hpp"
#include "effects/scene/scene_work.hpp"
#include "geometry/mesh_data.hpp"
#include "render_gl/program_pass.hpp"

namespace fx {
namespace {

// Clip a millimetre above the plane: the mirror itself (and a floor in its plane) stay out of it.
constexpr float kClipAbove = 0.001f;

}  // namespace

std::optional<MirrorPlane> findMirror(const Scene& scene, double seconds) {
    for (std::size_t i = 0; i < scene.objects.size(); ++i) {
        const SceneObject& o = scene.objects[i];
        if (!o.mirror) continue;
        glm::mat4 model = SceneMeshes::modelAt(o, seconds);
        glm::vec3 n = glm::mat3(glm::transpose(glm::inverse(model))) * glm::vec3(0, 1, 0);
        float len = glm::length(n);
        if (!(len > 1e-12f)) return std::nullopt;
        n /= len;
        glm::vec3 p = glm::vec3(model[3]);
        return MirrorPlane{i, glm::vec4(n, -glm::dot(n, p)), o.mirror->strength};
    }
    return std::nullopt;
}

glm::mat4 reflectionMatrix(glm::vec4 plane) {
    glm::vec3 n(plane);
    float d = plane.w;
    glm::mat4 r(1.0f);
    for (int c = 0; c < 3; ++c)
        for (int row = 0; row < 3; ++row) r[c][row] -= 2.0f * n[row] * n[c];
    for (int row = 0; row < 3; ++row) r[3][row] = -2.0f * d * n[row];
    return r;
}

std::array<glm::vec2, 16> reflectionBlurOffsets() {
    // Marsaglia's xorshift128 from its published seeds, then Box-Muller: two uniform numbers in (0, 1]
    // give a radius sqrt(-2 ln u1) and an angle 2 pi u2, one standard-normal 2-D sample.
    std::uint32_t x = 123456789u, y = 362436069u, z = 521288629u, w = 88675123u;
    auto next = [&] {
        std::uint32_t t = x ^ (x << 11);
        x = y;
        y = z;
        z = w;
        w = w ^ (w >> 19) ^ (t ^ (t >> 8));
        return (double(w) + 1.0) / 4294967296.0;  // (0, 1]: the logarithm stays finite
    };
    std::array<glm::vec2, 16> samples{};
    for (glm::vec2& sample : samples) {
        double radius = std::sqrt(-2.0 * std::log(next()));
        double angle = 2.0 * 3.14159265358979323846 * next();
        sample = glm::vec2(float(radius * std::cos(angle)), float(radius * std::sin(angle)));
    }
    return samples;
}

PlanarReflection::PlanarReflection(const Scene& scene) {
    if (auto mirror = findMirror(scene, 0.0)) {
        const Primitive& plane = *scene.objects[mirror->object].primitive;
        mirrorMesh_ = GpuMesh(makePlane(plane.planeSize.x, plane.planeSize.y), "mirror surface mesh");
    }
}

TextureHandle PlanarReflection::declare(FrameGraph& graph, const World& world, const PointLightBuffer& lights,
                                        const GBufferTargets& g, TextureHandle lit, int fraction,
                                        const ReflectionMistakes& mistakes, ReflectionBlur blur) const {
    std::optional<MirrorPlane> mirror = findMirror(world.scene(), world.seconds());
    const gl::ReloadableProgram* reflect = &reflect_;
    const PointLightBuffer* buffer = &lights;
    const MirrorPlane m = mirror.value_or(MirrorPlane{});
    const bool mirrorObjects = mistakes.mirrorObjects;
    Pass& pass =
        graph.addPass("planar reflection", [reflect, buffer, world, m, mirrorObjects](PassContext& ctx) {
            const Scene& scene = world.scene();
            // The same projection as the camera's, the view mirrored in the plane. The output's aspect, not
            // the target's: a fraction of an output that is not its multiple (98 x 54 / 4 = 24 x 13) has an
            // aspect of its own, and a reflection projected with it slides against the mirror (hard case 14).
            Size2D size = ctx.outputSize();
            CameraMatrices camera = cameraMatrices(scene.camera, size.width, size.height);
            glm::mat4 r = reflectionMatrix(m.plane);
            glm::mat4 objectMirror(1.0f);
            glm::vec4 clip(glm::vec3(m.plane), m.plane.w - kClipAbove);
            if (!mirrorObjects) {
                camera.view = camera.view * r;
                camera.viewProjection = camera.projection * camera.view;
                camera.position = glm::vec3(r * glm::vec4(camera.position, 1.0f));
            } else {
                // The raw-GL alternative: the objects mirrored below the plane, so the clip keeps what is
                // below it.
                objectMirror = r;
                clip = -glm::vec4(glm::vec3(m.plane), m.plane.w + kClipAbove);
            }
            GLuint program = reflect->name();
            SceneMeshes::setFrameUniforms(program, scene, camera);
            glProgramUniformMatrix4fv(program, glsl::kObjectMirrorLocation, 1, GL_FALSE,
                                      glm::value_ptr(objectMirror));
            glProgramUniform4fv(program, glsl::kClipPlaneLocation, 1, glm::value_ptr(clip));
            glProgramUniform1f(program, glsl::kHdrMaxLocation, kSceneHdrMax);
            glProgramUniform1i(program, glsl::kPointLightCountLocation, buffer->count());
            buffer->bind();
            glEnable(GL_CLIP_DISTANCE0);
            world.draw(program);
            glDisable(GL_CLIP_DISTANCE0);
        });
    const TextureSize at = TextureSize::outputFraction(1, std::clamp(fraction, 1, 8));
    TextureHandle color =
        pass.create("reflection.color", {at, TextureFormat::RGBA16F, 1}, TextureUsage::ColorAttachment);
    pass.create("reflection.depth", {at, TextureFormat::Depth32F, 1}, TextureUsage::DepthAttachment);
    PassState state = hdrSceneState(world.scene());
    // The mirrored view turns every triangle's winding round; so do mirrored objects (determinant -1).
    state.cullFace = CullFace::Front;
    if (mistakes.clearColor)
        state.clearColor =
            ClearColor{mistakes.clearColor->r, mistakes.clearColor->g, mistakes.clearColor->b, 1.0f};
    pass.setState(state).setTaps(1);  // the base colour; the lights come from a buffer
    needs(pass, SceneFeature::mirror);
    runsWith(pass, reflect_);

    const gl::ReloadableProgram* surface = &surface_;
    const GpuMesh* mesh = &mirrorMesh_;
    static const std::array<glm::vec2, 16> kBlurOffsets = reflectionBlurOffsets();
    Pass& over = graph.addPass("mirror surface", [surface, mesh, world, m, color, g, blur](PassContext& ctx) {
        const Scene& scene = world.scene();
        Size2D size = ctx.targetSize();
        CameraMatrices camera = offsetCameraMatrices(scene.camera, g.worldOffset, size);
        GLuint program = surface->name();
        SceneMeshes::setFrameUniforms(program, scene, camera);
        glm::mat4 model = SceneMeshes::modelAt(scene.objects[m.object], world.seconds());
        glProgramUniformMatrix4fv(program, glsl::kModelLocation, 1, GL_FALSE, glm::value_ptr(model));
        glProgramUniform1f(program, glsl::kMirrorStrengthLocation, m.strength);
        glProgramUniform2f(program, glsl::kMirrorOutputSizeLocation, float(size.width), float(size.height));
        glProgramUniform1f(program, glsl::kMirrorBlurSigmaLocation, std::max(blur.sigma, 0.0f));
        glProgramUniform2fv(program, glsl::kMirrorBlurOffsetsLocation, GLsizei(kBlurOffsets.size()),
                            glm::value_ptr(kBlurOffsets[0]));
        glBindTextureUnit(glsl::kMirrorReflectionBinding, ctx.native(color));
        glBindTextureUnit(glsl::kMirrorSceneDepthBinding, ctx.native(g.depth));
        glUseProgram(program);
        mesh->draw();
    });
    // The depth test is done in the shader against the G-buffer's depth, which the lighting pass also
    // samples: as a depth attachment here it would be modified after the lighting pass read it.
    over.read(color)
        .read(g.depth)
        .modify(lit, TextureUsage::ColorAttachment)
        .setState({.depthTest = false,
                   .depthWrite = false,
                   .blend = true,
                   .blendFunction = BlendFunction::alpha(),
                   .faceCulling = true,
                   .cullFace = CullFace::Back,
                   .colorMask = ColorMask{}});
    over.setTaps(blur.sigma > 0.0f ? 17 : 2);  // the G-buffer's depth, then the reflection (16 when blurred)
    needs(over, SceneFeature::mirror);
    if (!mirror) over.notCalledFor("scene has no mirror (no object with \"mirror\")");
    runsWith(over, surface_);
    return color;
}

}  // namespace fx
