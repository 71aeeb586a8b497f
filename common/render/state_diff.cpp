#include "render/state_diff.hpp"

#include "base/log.hpp"

namespace fx {
namespace {

std::string onOff(bool value) {
    return value ? "on" : "off";
}

std::string describe(const Viewport& v) {
    return cat(v.x, ", ", v.y, ", ", v.width, "x", v.height);
}

std::string describe(const BlendFunction& f) {
    if (f.equationRgb == f.equationAlpha && f.srcRgb == f.srcAlpha && f.dstRgb == f.dstAlpha) {
        return cat(toString(f.equationRgb), "(", toString(f.srcRgb), ", ", toString(f.dstRgb), ")");
    }
    return cat("rgb ", toString(f.equationRgb), "(", toString(f.srcRgb), ", ", toString(f.dstRgb),
               "), alpha ", toString(f.equationAlpha), "(", toString(f.srcAlpha), ", ", toString(f.dstAlpha),
               ")");
}

std::string describe(const ColorMask& m) {
    return cat(m.r ? 'R' : '-', m.g ? 'G' : '-', m.b ? 'B' : '-', m.a ? 'A' : '-');
}

std::string describe(const ClearColor& c) {
    return cat("(", c[0], ", ", c[1], ", ", c[2], ", ", c[3], ")");
}

}  // namespace

std::string StateDifference::text() const {
    return cat(field, ": ", value, " (default ", defaultValue, ")");
}

std::vector<StateDifference> diffState(const GlStateSnapshot& actual, const GlStateSnapshot& defaults) {
    std::vector<StateDifference> out;
    auto add = [&](const char* field, const auto& a, const auto& d, auto&& show) {
        if (!(a == d)) out.push_back({field, show(a), show(d)});
    };
    auto text = [](auto v) { return std::string(toString(v)); };
    add("viewport", actual.viewport, defaults.viewport, [](const Viewport& v) { return describe(v); });
    add("depth test", actual.depthTest, defaults.depthTest, onOff);
    add("depth write", actual.depthWrite, defaults.depthWrite, onOff);
    add("depth function", actual.depthFunction, defaults.depthFunction, text);
    add("blend", actual.blend, defaults.blend, onOff);
    add("blend function", actual.blendFunction, defaults.blendFunction,
        [](const BlendFunction& f) { return describe(f); });
    add("face culling", actual.faceCulling, defaults.faceCulling, onOff);
    add("cull face", actual.cullFace, defaults.cullFace, text);
    add("colour mask", actual.colorMask, defaults.colorMask, [](const ColorMask& m) { return describe(m); });
    add("clear colour", actual.clearColor, defaults.clearColor,
        [](const ClearColor& c) { return describe(c); });
    add("clear depth", actual.clearDepth, defaults.clearDepth, [](float v) { return cat(v); });
    return out;
}

std::vector<std::string> inheritedDependencies(const PassState& declared, const GlStateSnapshot& inherited,
                                               PassWrites writes) {
    std::vector<std::string> out;
    auto add = [&](bool isDeclared, const char* field, const std::string& value) {
        if (!isDeclared) out.push_back(cat(field, ": ", value, " (inherited)"));
    };
    auto text = [](auto v) { return std::string(toString(v)); };
    // The values the pass ends up with: declared fields win, the rest is what it inherited.
    GlStateSnapshot effective = applyPassState(inherited, declared, Size2D{});
    if (writes.depth) {
        add(declared.depthTest.has_value(), "depth test", onOff(inherited.depthTest));
        // The depth clear obeys the depth mask as drawing does: a pass that clears depth with writes
        // left off by the pass before keeps the old depth (stale depth), even if it never tests.
        if (effective.depthTest || declared.clearDepth) {
            add(declared.depthWrite.has_value(), "depth write", onOff(inherited.depthWrite));
        }
        if (effective.depthTest) {
            add(declared.depthFunction.has_value(), "depth function", text(inherited.depthFunction));
        }
    }
    if (writes.color) {
        add(declared.blend.has_value(), "blend", onOff(inherited.blend));
        if (effective.blend) {
            add(declared.blendFunction.has_value(), "blend function", describe(inherited.blendFunction));
        }
        add(declared.colorMask.has_value(), "colour mask", describe(inherited.colorMask));
    }
    if (writes.depth || writes.color) {
        add(declared.faceCulling.has_value(), "face culling", onOff(inherited.faceCulling));
        if (effective.faceCulling) add(declared.cullFace.has_value(), "cull face", text(inherited.cullFace));
    }
    return out;
}

}  // namespace fx
