#include "effects/shadow/shadow_map.hpp"

#include <algorithm>
#include <cmath>
#include <optional>

#include <glm/gtc/type_ptr.hpp>

#include "effects/shadow/shadow_bindings.hpp"
#include "gl/debug_output.hpp"
#include "render_gl/program_pass.hpp"

namespace fx {
namespace {

constexpr int kMaxMapSize = 8192;
// A walking character's limbs leave its bind-pose box; this much room around skinned meshes keeps
// their feet and hands inside the fitted map.
constexpr float kSkinnedPadding = 0.3f;

Bounds primitiveBounds(const Primitive& p) {
    glm::vec3 half(0.5f);
    switch (p.shape) {
        case PrimitiveShape::plane:
            half = {0.5f * p.planeSize.x, 0.0f, 0.5f * p.planeSize.y};
            break;
        case PrimitiveShape::box:
            half = 0.5f * p.boxSize;
            break;
        case PrimitiveShape::sphere:
            half = glm::vec3(p.radius);
            break;
        case PrimitiveShape::cylinder:
        case PrimitiveShape::capsule:
            half = {p.radius, 0.5f * p.height, p.radius};
            break;
    }
    Bounds b;
    b.add(-half);
    b.add(half);
    return b;
}

Bounds modelBounds(const GpuModel& gpu) {
    const GltfModel& model = gpu.model();
    Bounds out;
    for (int node : model.meshNodes()) {
        const ModelNode& n = model.nodes[std::size_t(node)];
        Bounds local;
        bool skinned = false;
        for (const ModelPrimitive& prim : model.meshes[std::size_t(n.mesh)].primitives) {
            for (const glm::vec3& p : prim.mesh.positions) local.add(p);
            skinned = skinned || prim.skinned();
        }
        if (local.empty()) continue;
        if (skinned) {
            local.min -= glm::vec3(kSkinnedPadding);
            local.max += glm::vec3(kSkinnedPadding);
        }
        out.add(local.transformed(gpu.nodeWorld()[std::size_t(node)]));
    }
    return out;
}

ShadowSettings checked(ShadowSettings s) {
    s.mapSize = std::clamp(s.mapSize, 1, kMaxMapSize);
    s.filterTaps = std::clamp(s.filterTaps, 1, kShadowMaxFilterTaps);
    if (!std::isfinite(s.bias)) s.bias = 0.0f;
    if (!std::isfinite(s.normalOffset)) s.normalOffset = 0.0f;
    return s;
}

}  // namespace

OperationCount operationCount(SkinningProduct product) {
    // mat4*vec4: 16 mul + 12 add; mat4*mat4: 64 mul + 48 add (Shader effects chapter, §2).
    return product == SkinningProduct::parenthesised ? OperationCount{32, 24} : OperationCount{80, 60};
}

int shadowLookupTaps(const ShadowLookup& lookup) {
    return lookup.enabled ? std::clamp(lookup.filterTaps, 1, kShadowMaxFilterTaps) : 0;
}

ShadowLookup shadowLookup(const ShadowSettings& settings, const LightView& light, float filterRadiusMetres) {
    ShadowLookup lookup;
    lookup.light = light;
    float texel = std::max(light.texelWorldSize, 1e-9f);
    lookup.normalOffsetMetres = settings.normalOffset * texel;
    lookup.depthBias = settings.bias;
    lookup.filterRadiusTexels =
        (filterRadiusMetres > 0.0f && std::isfinite(filterRadiusMetres)) ? filterRadiusMetres / texel : 1.5f;
    lookup.filterTaps = std::clamp(settings.filterTaps, 1, kShadowMaxFilterTaps);
    lookup.enabled = settings.casts;
    return lookup;
}

const Light* shadowCastingLight(const Scene& scene) {
    for (const Light& light : scene.lights)
        if (light.castsShadows()) return &light;
    return nullptr;
}

ShadowBounds sceneBounds(const World& world, const std::vector<glm::mat4>& skinnedPlacements) {
    ShadowBounds out;
    const Scene& scene = world.scene();
    for (std::size_t i = 0; i < scene.objects.size(); ++i) {
        const SceneObject& object = scene.objects[i];
        Bounds local;
        if (object.primitive) {
            local = primitiveBounds(*object.primitive);
        } else if (const GpuModel* gpu = world.meshes().model(i)) {
            local = modelBounds(*gpu);
        }
        glm::mat4 model = SceneMeshes::modelAt(object, world.seconds());
        Bounds placed = local.transformed(model);
        if (world.meshes().isSkinned(i))
            for (const glm::mat4& placement : skinnedPlacements)
                placed.add(local.transformed(placement * model));
        out.everything.add(placed);
        if (object.castsShadows) out.casters.add(placed);
    }
    return out;
}

const gl::ReloadableProgram& ShadowMap::skinnedReloadable(SkinningProduct product) const {
    return product == SkinningProduct::parenthesised ? skinned_ : skinnedGrouped_;
}

const gl::Program& ShadowMap::skinnedProgram(SkinningProduct product) const {
    return skinnedReloadable(product).program();
}

DeclaredShadowMap ShadowMap::declare(FrameGraph& graph, const World& world, const ShadowSettings& settings,
                                     const ShadowPassOptions& options) const {
    const Light* light = shadowCastingLight(world.scene());
    glm::vec3 direction = light ? light->direction : glm::vec3(0.0f, -1.0f, 0.0f);
    ShadowSettings s = checked(settings);
    ShadowBounds bounds = sceneBounds(world, options.skinnedPlacements);
    LightView view = fitLightFrustum(bounds.casters, bounds.everything, direction, s.extent, s.mapSize);
    return declare(graph, world, s, view, options);
}

DeclaredShadowMap ShadowMap::declare(FrameGraph& graph, const World& world, const ShadowSettings& settings,
                                     const LightView& light, const ShadowPassOptions& options) const {
    DeclaredShadowMap out;
    out.settings = checked(settings);
    out.lookup = shadowLookup(out.settings, light, options.filterRadiusMetres);
    const Light* caster = shadowCastingLight(world.scene());
    if (!caster) {
        out.lookup.enabled = false;
        return out;
    }
    out.lookup.enabled = true;

    const gl::ReloadableProgram* staticProgram = &static_;
    const gl::Program* skinnedProgram = &this->skinnedProgram(options.product);
    Pass& pass =
        graph.addPass(options.passName, [staticProgram, skinnedProgram, world, light, options](PassContext&) {
            ShadowPassStats stats;
            const float* vp = glm::value_ptr(light.viewProjection);
            glProgramUniformMatrix4fv(staticProgram->name(), glsl::kViewProjectionLocation, 1, GL_FALSE, vp);
            glProgramUniformMatrix4fv(skinnedProgram->name(), glsl::kViewProjectionLocation, 1, GL_FALSE, vp);
            // One cutoff per program. The bug leaves the skinned program's at 0, the value GL gives a
            // uniform nobody set (set explicitly here because the program outlives the toggle).
            glProgramUniform1f(staticProgram->name(), glsl::kAlphaCutoffLocation, kAlphaCutoff);
            glProgramUniform1f(skinnedProgram->name(), glsl::kAlphaCutoffLocation,
                               options.cutoff == CutoffUniform::everyProgram ? kAlphaCutoff : 0.0f);
            if (options.drawStatic) {
                MeshDrawOptions o;
                o.shadowCastersOnly = true;
                o.setMaterial = false;  // the static path asks, as the chapter's Draw helper already did
                o.bindTextures = true;  // the base colour alpha, for the cutoff
                o.skinFilter = SkinFilter::withoutSkin;
                stats.staticDraws = world.draw(staticProgram->name(), o);
            }
            if (options.drawSkinned) {
                // One switch, then every skinned object (Shader effects chapter, §2).
                if (options.drawStatic) ++stats.programSwitches;
                MeshDrawOptions o;
                o.shadowCastersOnly = true;
                o.bindTextures = true;
                o.skinned = SkinnedDraw::source;
                o.skinFilter = SkinFilter::skinnedOnly;
                // The fix asks the program (its active uniforms were listed once, at link time).
                o.setMaterial = options.materialUpload == MaterialUpload::always ||
                                skinnedProgram->hasUniform("baseColor");
                std::optional<gl::ExpectedErrorScope> expected;
                if (options.materialUpload == MaterialUpload::always)
                    expected.emplace("lesson 02: material uniforms uploaded to the skinned shadow program");
                std::int64_t before = gl::debugCounters().errors + gl::debugCounters().expectedErrors;
                std::vector<glm::mat4> placements = options.skinnedPlacements;
                if (placements.empty()) placements.emplace_back(1.0f);
                for (const glm::mat4& placement : placements) {
                    o.placement = placement;
                    stats.skinnedDraws += world.draw(skinnedProgram->name(), o);
                }
                stats.glErrors = gl::debugCounters().errors + gl::debugCounters().expectedErrors - before;
                stats.skinnedVertices = skinnedVertexCount(world.meshes()) * placements.size();
            }
            if (options.stats) *options.stats = stats;
        });
    std::string texName = options.textureName;
    out.map = pass.create(
        texName,
        {TextureSize::absolute(out.settings.mapSize, out.settings.mapSize), TextureFormat::Depth32F, 1},
        TextureUsage::DepthAttachment);
    out.pass = &pass;
    if (options.setsItsOwnState) {
        // Shader effects §3.3: the pass enables its own depth test (without it GL writes no depth,
        // whatever the depth mask says) and switches blending off. Culling is off so that open or
        // one-sided casters still cast.
        pass.setState({.depthTest = true,
                       .depthWrite = true,
                       .depthFunction = DepthFunction::Less,
                       .blend = false,
                       .faceCulling = false,
                       .clearDepth = 1.0f});
    } else {
        // The chapter's bug: depth test, depth write and blend are whatever the previous pass left.
        pass.setState({.faceCulling = false, .clearDepth = 1.0f});
    }
    pass.setTaps(1);  // the base colour's alpha, for the cutoff
    runsWith(pass, static_);
    runsWith(pass, skinnedReloadable(options.product));
    return out;
}

TextureHandle ShadowMap::declareDepthView(FrameGraph& graph, const DeclaredShadowMap& map, int size) const {
    size = std::max(size, 1);
    const FullscreenPass* view = &depthView_;
    TextureHandle input = map.map;
    glm::vec2 range(map.lookup.light.nearDistance, map.lookup.light.farDistance);
    Pass& pass = depthView_.addPass(graph, "shadow depth view", [view, input, range](PassContext& ctx) {
        Size2D target = ctx.targetSize();
        glProgramUniform2f(view->program(), glsl::kDepthViewRangeLocation, range.x, range.y);
        glProgramUniform2f(view->program(), glsl::kDepthViewTargetSizeLocation, float(target.width),
                           float(target.height));
        view->draw({ctx.native(input)});
    });
    TextureHandle out =
        pass.create("shadow.depth_metres", {TextureSize::absolute(size, size), TextureFormat::R32F, 1},
                    TextureUsage::ColorAttachment);
    if (map.pass) pass.read(map.map);
    pass.setTaps(1);
    if (!map.pass) pass.notCalledFor("scene has no directional light that casts shadows");
    return out;
}

void ShadowMap::bindForLookup(GLuint program, GLuint depthTexture, const ShadowLookup& lookup) {
    bool on = lookup.enabled && depthTexture != 0;
    glProgramUniformMatrix4fv(program, glsl::kShadowMatrixLocation, 1, GL_FALSE,
                              glm::value_ptr(lookup.light.viewProjection));
    glProgramUniform4f(program, glsl::kShadowParamsLocation, lookup.normalOffsetMetres, lookup.depthBias,
                       lookup.filterRadiusTexels, on ? 1.0f : 0.0f);
    glProgramUniform1i(program, glsl::kShadowTapsLocation, lookup.filterTaps);
    glProgramUniform3fv(program, glsl::kShadowToLightLocation, 1,
                        glm::value_ptr(lookup.light.directionToLight));
    glBindTextureUnit(glsl::kShadowMapBinding, on ? depthTexture : 0);
}

std::size_t ShadowMap::skinnedVertexCount(const SceneMeshes& meshes) {
    std::size_t n = 0;
    for (std::size_t i = 0; i < meshes.objectCount(); ++i) {
        const GpuModel* gpu = meshes.model(i);
        if (!gpu || !meshes.isSkinned(i)) continue;
        const GltfModel& model = gpu->model();
        for (int node : model.meshNodes()) {
            const ModelNode& n0 = model.nodes[std::size_t(node)];
            if (n0.skin < 0) continue;
            for (const ModelPrimitive& prim : model.meshes[std::size_t(n0.mesh)].primitives)
                if (prim.skinned()) n += prim.mesh.vertexCount();
        }
    }
    return n;
}

}  // namespace fx
