#pragma once
// The GL state a pass depends on, as plain data. The GL executor applies it before the pass runs.
// Every field is optional on purpose: an unset field means "whatever the previous pass left", which
// is exactly the leak lesson 03 teaches (a reordered shadow pass inherits depth testing off). The
// viewport is the exception: unset means the full size of the pass's target.
#include <array>
#include <optional>
#include <string_view>
#include <vector>

#include "render/texture_desc.hpp"

namespace fx {

enum class DepthFunction { Never, Less, Equal, LessEqual, Greater, NotEqual, GreaterEqual, Always };

enum class BlendEquation { Add, Subtract, ReverseSubtract, Min, Max };

enum class BlendFactor {
    Zero,
    One,
    SrcColor,
    OneMinusSrcColor,
    DstColor,
    OneMinusDstColor,
    SrcAlpha,
    OneMinusSrcAlpha,
    DstAlpha,
    OneMinusDstAlpha,
    ConstantColor,
    OneMinusConstantColor,
    ConstantAlpha,
    OneMinusConstantAlpha,
    SrcAlphaSaturate,
};

enum class CullFace { Back, Front, FrontAndBack };

struct Viewport {
    int x = 0;
    int y = 0;
    int width = 0;
    int height = 0;
    bool operator==(const Viewport&) const = default;
};

// result.rgb = equationRgb(src.rgb * srcRgb, dst.rgb * dstRgb), and the same for alpha.
struct BlendFunction {
    BlendEquation equationRgb = BlendEquation::Add;
    BlendEquation equationAlpha = BlendEquation::Add;
    BlendFactor srcRgb = BlendFactor::One;
    BlendFactor dstRgb = BlendFactor::Zero;
    BlendFactor srcAlpha = BlendFactor::One;
    BlendFactor dstAlpha = BlendFactor::Zero;
    bool operator==(const BlendFunction&) const = default;

    static BlendFunction replace() { return {}; }  // GL's initial function
    static BlendFunction additive();               // dst + src (bloom accumulation, particles)
    static BlendFunction alpha();                  // src over dst, straight alpha
    static BlendFunction premultipliedAlpha();
};

struct ColorMask {
    bool r = true;
    bool g = true;
    bool b = true;
    bool a = true;
    bool operator==(const ColorMask&) const = default;
};

using ClearColor = std::array<float, 4>;

// Declared per pass. Fields are in the order designated initialisers must follow:
//   pass.setState({.depthTest = true, .depthWrite = true, .clearDepth = 1.0f});
struct PassState {
    std::optional<Viewport> viewport{};  // unset: 0, 0 and the target's full size
    std::optional<bool> depthTest{};
    std::optional<bool> depthWrite{};
    std::optional<DepthFunction> depthFunction{};
    std::optional<bool> blend{};
    std::optional<BlendFunction> blendFunction{};
    std::optional<bool> faceCulling{};
    std::optional<CullFace> cullFace{};
    std::optional<ColorMask> colorMask{};
    // Clears of the pass's attachments when it begins: every colour attachment, the depth attachment.
    std::optional<ClearColor> clearColor{};
    std::optional<float> clearDepth{};
};

// The state GL is actually in: what the GL layer reads back with glGet after a pass. Same fields as
// PassState, none optional. clearColor and clearDepth are GL's clear values (GL_COLOR_CLEAR_VALUE,
// GL_DEPTH_CLEAR_VALUE).
struct GlStateSnapshot {
    Viewport viewport{};
    bool depthTest = false;
    bool depthWrite = true;
    DepthFunction depthFunction = DepthFunction::Less;
    bool blend = false;
    BlendFunction blendFunction{};
    bool faceCulling = false;
    CullFace cullFace = CullFace::Back;
    ColorMask colorMask{};
    ClearColor clearColor{0.0f, 0.0f, 0.0f, 0.0f};
    float clearDepth = 1.0f;
    bool operator==(const GlStateSnapshot&) const = default;

    // GL's initial state for a context whose default framebuffer is `size` (depth test off!).
    static GlStateSnapshot glInitial(Size2D size);
};

// The state after a pass applies its declared state on top of `before`: set fields replace, unset
// fields stay as the previous pass left them, an unset viewport becomes the full target.
GlStateSnapshot applyPassState(const GlStateSnapshot& before, const PassState& state, Size2D targetSize);

// Names of the fields a pass leaves to its predecessor ("depth test", "blend", ...), for the overlay.
std::vector<std::string_view> inheritedFields(const PassState& state);

std::string_view toString(DepthFunction value);
std::string_view toString(BlendEquation value);
std::string_view toString(BlendFactor value);
std::string_view toString(CullFace value);

}  // namespace fx
