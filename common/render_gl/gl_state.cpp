#include "render_gl/gl_state.hpp"

#include <array>
#include <utility>

namespace fx {
namespace {

constexpr std::array<std::pair<DepthFunction, GLenum>, 8> kDepthFunctions{{
    {DepthFunction::Never, GL_NEVER},
    {DepthFunction::Less, GL_LESS},
    {DepthFunction::Equal, GL_EQUAL},
    {DepthFunction::LessEqual, GL_LEQUAL},
    {DepthFunction::Greater, GL_GREATER},
    {DepthFunction::NotEqual, GL_NOTEQUAL},
    {DepthFunction::GreaterEqual, GL_GEQUAL},
    {DepthFunction::Always, GL_ALWAYS},
}};
constexpr std::array<std::pair<BlendEquation, GLenum>, 5> kBlendEquations{{
    {BlendEquation::Add, GL_FUNC_ADD},
    {BlendEquation::Subtract, GL_FUNC_SUBTRACT},
    {BlendEquation::ReverseSubtract, GL_FUNC_REVERSE_SUBTRACT},
    {BlendEquation::Min, GL_MIN},
    {BlendEquation::Max, GL_MAX},
}};
constexpr std::array<std::pair<BlendFactor, GLenum>, 15> kBlendFactors{{
    {BlendFactor::Zero, GL_ZERO},
    {BlendFactor::One, GL_ONE},
    {BlendFactor::SrcColor, GL_SRC_COLOR},
    {BlendFactor::OneMinusSrcColor, GL_ONE_MINUS_SRC_COLOR},
    {BlendFactor::DstColor, GL_DST_COLOR},
    {BlendFactor::OneMinusDstColor, GL_ONE_MINUS_DST_COLOR},
    {BlendFactor::SrcAlpha, GL_SRC_ALPHA},
    {BlendFactor::OneMinusSrcAlpha, GL_ONE_MINUS_SRC_ALPHA},
    {BlendFactor::DstAlpha, GL_DST_ALPHA},
    {BlendFactor::OneMinusDstAlpha, GL_ONE_MINUS_DST_ALPHA},
    {BlendFactor::ConstantColor, GL_CONSTANT_COLOR},
    {BlendFactor::OneMinusConstantColor, GL_ONE_MINUS_CONSTANT_COLOR},
    {BlendFactor::ConstantAlpha, GL_CONSTANT_ALPHA},
    {BlendFactor::OneMinusConstantAlpha, GL_ONE_MINUS_CONSTANT_ALPHA},
    {BlendFactor::SrcAlphaSaturate, GL_SRC_ALPHA_SATURATE},
}};
constexpr std::array<std::pair<CullFace, GLenum>, 3> kCullFaces{{
    {CullFace::Back, GL_BACK},
    {CullFace::Front, GL_FRONT},
    {CullFace::FrontAndBack, GL_FRONT_AND_BACK},
}};

template <class E, std::size_t N>
GLenum toGl(const std::array<std::pair<E, GLenum>, N>& table, E value) {
    for (auto& [e, g] : table) {
        if (e == value) return g;
    }
    return table[0].second;
}

template <class E, std::size_t N>
E fromGl(const std::array<std::pair<E, GLenum>, N>& table, GLint value) {
    for (auto& [e, g] : table) {
        if (static_cast<GLint>(g) == value) return e;
    }
    return table[0].first;
}

void enable(GLenum capability, bool on) {
    on ? glEnable(capability) : glDisable(capability);
}

GLint getInt(GLenum what) {
    GLint v = 0;
    glGetIntegerv(what, &v);
    return v;
}

}  // namespace

void applyGlState(const PassState& s, Size2D target) {
    Viewport v = s.viewport.value_or(Viewport{0, 0, target.width, target.height});
    glViewport(v.x, v.y, v.width, v.height);
    if (s.depthTest) enable(GL_DEPTH_TEST, *s.depthTest);
    if (s.depthWrite) glDepthMask(*s.depthWrite ? GL_TRUE : GL_FALSE);
    if (s.depthFunction) glDepthFunc(toGl(kDepthFunctions, *s.depthFunction));
    if (s.blend) enable(GL_BLEND, *s.blend);
    if (s.blendFunction) {
        const BlendFunction& b = *s.blendFunction;
        glBlendEquationSeparate(toGl(kBlendEquations, b.equationRgb), toGl(kBlendEquations, b.equationAlpha));
        glBlendFuncSeparate(toGl(kBlendFactors, b.srcRgb), toGl(kBlendFactors, b.dstRgb),
                            toGl(kBlendFactors, b.srcAlpha), toGl(kBlendFactors, b.dstAlpha));
    }
    if (s.faceCulling) enable(GL_CULL_FACE, *s.faceCulling);
    if (s.cullFace) glCullFace(toGl(kCullFaces, *s.cullFace));
    if (s.colorMask) glColorMask(s.colorMask->r, s.colorMask->g, s.colorMask->b, s.colorMask->a);
}

GlStateSnapshot snapshotGlState() {
    GlStateSnapshot s;
    GLint v[4] = {};
    glGetIntegerv(GL_VIEWPORT, v);
    s.viewport = {v[0], v[1], v[2], v[3]};
    s.depthTest = glIsEnabled(GL_DEPTH_TEST) == GL_TRUE;
    GLboolean mask = GL_TRUE;
    glGetBooleanv(GL_DEPTH_WRITEMASK, &mask);
    s.depthWrite = mask == GL_TRUE;
    s.depthFunction = fromGl(kDepthFunctions, getInt(GL_DEPTH_FUNC));
    s.blend = glIsEnabled(GL_BLEND) == GL_TRUE;
    s.blendFunction.equationRgb = fromGl(kBlendEquations, getInt(GL_BLEND_EQUATION_RGB));
    s.blendFunction.equationAlpha = fromGl(kBlendEquations, getInt(GL_BLEND_EQUATION_ALPHA));
    s.blendFunction.srcRgb = fromGl(kBlendFactors, getInt(GL_BLEND_SRC_RGB));
    s.blendFunction.dstRgb = fromGl(kBlendFactors, getInt(GL_BLEND_DST_RGB));
    s.blendFunction.srcAlpha = fromGl(kBlendFactors, getInt(GL_BLEND_SRC_ALPHA));
    s.blendFunction.dstAlpha = fromGl(kBlendFactors, getInt(GL_BLEND_DST_ALPHA));
    s.faceCulling = glIsEnabled(GL_CULL_FACE) == GL_TRUE;
    s.cullFace = fromGl(kCullFaces, getInt(GL_CULL_FACE_MODE));
    GLboolean colorMask[4] = {GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE};
    glGetBooleanv(GL_COLOR_WRITEMASK, colorMask);
    s.colorMask = {colorMask[0] == GL_TRUE, colorMask[1] == GL_TRUE, colorMask[2] == GL_TRUE,
                   colorMask[3] == GL_TRUE};
    glGetFloatv(GL_COLOR_CLEAR_VALUE, s.clearColor.data());
    glGetFloatv(GL_DEPTH_CLEAR_VALUE, &s.clearDepth);
    return s;
}

void restoreGlState(const GlStateSnapshot& s) {
    PassState all;
    all.viewport = s.viewport;
    all.depthTest = s.depthTest;
    all.depthWrite = s.depthWrite;
    all.depthFunction = s.depthFunction;
    all.blend = s.blend;
    all.blendFunction = s.blendFunction;
    all.faceCulling = s.faceCulling;
    all.cullFace = s.cullFace;
    all.colorMask = s.colorMask;
    applyGlState(all, {s.viewport.width, s.viewport.height});
    glClearColor(s.clearColor[0], s.clearColor[1], s.clearColor[2], s.clearColor[3]);
    glClearDepth(s.clearDepth);
}

}  // namespace fx
