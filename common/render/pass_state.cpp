#include "render/pass_state.hpp"

namespace fx {

BlendFunction BlendFunction::additive() {
    BlendFunction f;
    f.srcRgb = f.dstRgb = f.srcAlpha = f.dstAlpha = BlendFactor::One;
    return f;
}

BlendFunction BlendFunction::alpha() {
    BlendFunction f;
    f.srcRgb = BlendFactor::SrcAlpha;
    f.dstRgb = BlendFactor::OneMinusSrcAlpha;
    f.srcAlpha = BlendFactor::One;
    f.dstAlpha = BlendFactor::OneMinusSrcAlpha;
    return f;
}

BlendFunction BlendFunction::premultipliedAlpha() {
    BlendFunction f;
    f.srcRgb = f.srcAlpha = BlendFactor::One;
    f.dstRgb = f.dstAlpha = BlendFactor::OneMinusSrcAlpha;
    return f;
}

GlStateSnapshot GlStateSnapshot::glInitial(Size2D size) {
    GlStateSnapshot s;
    s.viewport = {0, 0, size.width, size.height};
    return s;
}

GlStateSnapshot applyPassState(const GlStateSnapshot& before, const PassState& state, Size2D targetSize) {
    GlStateSnapshot after = before;
    after.viewport = state.viewport.value_or(Viewport{0, 0, targetSize.width, targetSize.height});
    if (state.depthTest) after.depthTest = *state.depthTest;
    if (state.depthWrite) after.depthWrite = *state.depthWrite;
    if (state.depthFunction) after.depthFunction = *state.depthFunction;
    if (state.blend) after.blend = *state.blend;
    if (state.blendFunction) after.blendFunction = *state.blendFunction;
    if (state.faceCulling) after.faceCulling = *state.faceCulling;
    if (state.cullFace) after.cullFace = *state.cullFace;
    if (state.colorMask) after.colorMask = *state.colorMask;
    if (state.clearColor) after.clearColor = *state.clearColor;
    if (state.clearDepth) after.clearDepth = *state.clearDepth;
    return after;
}

std::vector<std::string_view> inheritedFields(const PassState& state) {
    std::vector<std::string_view> names;
    if (!state.depthTest) names.push_back("depth test");
    if (!state.depthWrite) names.push_back("depth write");
    if (!state.depthFunction) names.push_back("depth function");
    if (!state.blend) names.push_back("blend");
    if (!state.blendFunction) names.push_back("blend function");
    if (!state.faceCulling) names.push_back("face culling");
    if (!state.cullFace) names.push_back("cull face");
    if (!state.colorMask) names.push_back("colour mask");
    return names;
}

std::string_view toString(DepthFunction value) {
    switch (value) {
        case DepthFunction::Never:
            return "Never";
        case DepthFunction::Less:
            return "Less";
        case DepthFunction::Equal:
            return "Equal";
        case DepthFunction::LessEqual:
            return "LessEqual";
        case DepthFunction::Greater:
            return "Greater";
        case DepthFunction::NotEqual:
            return "NotEqual";
        case DepthFunction::GreaterEqual:
            return "GreaterEqual";
        case DepthFunction::Always:
            return "Always";
    }
    return "?";
}

std::string_view toString(BlendEquation value) {
    switch (value) {
        case BlendEquation::Add:
            return "Add";
        case BlendEquation::Subtract:
            return "Subtract";
        case BlendEquation::ReverseSubtract:
            return "ReverseSubtract";
        case BlendEquation::Min:
            return "Min";
        case BlendEquation::Max:
            return "Max";
    }
    return "?";
}

std::string_view toString(BlendFactor value) {
    switch (value) {
        case BlendFactor::Zero:
            return "Zero";
        case BlendFactor::One:
            return "One";
        case BlendFactor::SrcColor:
            return "SrcColor";
        case BlendFactor::OneMinusSrcColor:
            return "OneMinusSrcColor";
        case BlendFactor::DstColor:
            return "DstColor";
        case BlendFactor::OneMinusDstColor:
            return "OneMinusDstColor";
        case BlendFactor::SrcAlpha:
            return "SrcAlpha";
        case BlendFactor::OneMinusSrcAlpha:
            return "OneMinusSrcAlpha";
        case BlendFactor::DstAlpha:
            return "DstAlpha";
        case BlendFactor::OneMinusDstAlpha:
            return "OneMinusDstAlpha";
        case BlendFactor::ConstantColor:
            return "ConstantColor";
        case BlendFactor::OneMinusConstantColor:
            return "OneMinusConstantColor";
        case BlendFactor::ConstantAlpha:
            return "ConstantAlpha";
        case BlendFactor::OneMinusConstantAlpha:
            return "OneMinusConstantAlpha";
        case BlendFactor::SrcAlphaSaturate:
            return "SrcAlphaSaturate";
    }
    return "?";
}

std::string_view toString(CullFace value) {
    switch (value) {
        case CullFace::Back:
            return "Back";
        case CullFace::Front:
            return "Front";
        case CullFace::FrontAndBack:
            return "FrontAndBack";
    }
    return "?";
}

}  // namespace fx
