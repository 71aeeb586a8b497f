#include "scene/scene_enums.hpp"

namespace fx {

std::span<const EnumName<LightType>> enumNames(LightType) {
    static constexpr EnumName<LightType> names[] = {
        {LightType::directional, "directional"}, {LightType::point, "point"}, {LightType::spot, "spot"}};
    return names;
}

std::span<const EnumName<PrimitiveShape>> enumNames(PrimitiveShape) {
    static constexpr EnumName<PrimitiveShape> names[] = {{PrimitiveShape::plane, "plane"},
                                                         {PrimitiveShape::box, "box"},
                                                         {PrimitiveShape::sphere, "sphere"},
                                                         {PrimitiveShape::cylinder, "cylinder"},
                                                         {PrimitiveShape::capsule, "capsule"}};
    return names;
}

std::span<const EnumName<MotionType>> enumNames(MotionType) {
    static constexpr EnumName<MotionType> names[] = {
        {MotionType::none, "none"}, {MotionType::circle, "circle"}, {MotionType::bob, "bob"}};
    return names;
}

std::span<const EnumName<EmitterKind>> enumNames(EmitterKind) {
    static constexpr EnumName<EmitterKind> names[] = {
        {EmitterKind::fire, "fire"}, {EmitterKind::smoke, "smoke"}, {EmitterKind::sparks, "sparks"}};
    return names;
}

std::span<const EnumName<ColorMatrixPreset>> enumNames(ColorMatrixPreset) {
    static constexpr EnumName<ColorMatrixPreset> names[] = {{ColorMatrixPreset::identity, "identity"},
                                                            {ColorMatrixPreset::grayscale, "grayscale"},
                                                            {ColorMatrixPreset::sepia, "sepia"},
                                                            {ColorMatrixPreset::invert, "invert"}};
    return names;
}

std::span<const EnumName<ToneCurve>> enumNames(ToneCurve) {
    static constexpr EnumName<ToneCurve> names[] = {
        {ToneCurve::clip, "clip"}, {ToneCurve::reinhard, "reinhard"}, {ToneCurve::filmic, "filmic"}};
    return names;
}

std::span<const EnumName<PostEffect>> enumNames(PostEffect) {
    static constexpr EnumName<PostEffect> names[] = {{PostEffect::bloom, "bloom"},
                                                     {PostEffect::colorMatrix, "colorMatrix"},
                                                     {PostEffect::radialBlur, "radialBlur"},
                                                     {PostEffect::depthOfField, "depthOfField"},
                                                     {PostEffect::toneMap, "toneMap"}};
    return names;
}

}  // namespace fx
