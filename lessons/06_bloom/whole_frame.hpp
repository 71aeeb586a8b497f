#pragma once
// Step 6: the Shader effects chapter's whole frame, its final per-frame pipeline (§4 of its digest in
// docs/chapters.md): the shadow map, the lit scene into a float target, the bloom chain and its
// composite, the radial blur, the colour matrix, one output encode, and the engine's UI queue on top.
// The three post effects run in an order the lesson chooses (`frame_order`): the chapter's is bloom,
// radial blur, colour matrix, so the matrix also greys the glow. The bloom chain always extracts from
// the scene, as the chapter's high pass reads fboMain; the order moves where its glow is added.
#include <array>
#include <string>
#include <vector>

#include "app/lesson.hpp"
#include "base/params.hpp"
#include "effects/bloom/bloom_chain.hpp"
#include "effects/bloom/bloom_composite.hpp"
#include "effects/post/colour_matrix.hpp"
#include "effects/post/output_transform_pass.hpp"
#include "effects/post/radial_blur.hpp"
#include "effects/post/ui_queue_pass.hpp"
#include "effects/scene/scene_meshes.hpp"
#include "effects/shadow/shadow_lit_pass.hpp"
#include "effects/shadow/shadow_map.hpp"

namespace lesson06 {

enum class FrameEffect { bloom, radialBlur, colourMatrix };

using EffectOrder = std::array<FrameEffect, 3>;
// Every order of the three, named ("bloom, radial blur, colour matrix"); the first is the chapter's.
const std::vector<fx::TableChoice<EffectOrder>::Option>& effectOrders();

// One row of the chapter's final per-frame pipeline table, with the fxlab pass that does its work
// (a pass name, or the start of one: "bloom down" covers "bloom down 1" to "bloom down 5").
struct ChapterFrameRow {
    std::string rows;    // the table's row numbers: "9"
    std::string action;  // "Extract + 1/4 downscale from fboMain"
    std::string pass;    // "bloom bright pass"
};
const std::vector<ChapterFrameRow>& chapterFrameTable();

// Whether `executed` (pass names in the order they ran) does the table's work in the table's order:
// every row's pass runs, and no pass of a later row runs before one of an earlier row. Passes the
// table has no row for are ignored. On a mismatch `why` says where.
bool followsChapterTable(const std::vector<std::string>& executed, std::string* why);

struct WholeFrameSettings {
    EffectOrder order = effectOrders().front().value;
    fx::ColourTransform matrix = fx::ColourTransform::grayscale();
    fx::BloomChainSettings chain;
    float compositeScale = 1.0f;
    fx::RadialBlurParams blur;  // the chapter's: length 0.02, start 0.2
};

class WholeFrame {
public:
    // Declares the frame. `chain`, `composite` and `present` are the lesson's (one program each).
    void declare(fx::FrameGraph& graph, const fx::FrameInfo& frame, const WholeFrameSettings& settings,
                 const fx::BloomChain& chain, const fx::BloomComposite& composite,
                 const fx::OutputTransformPass& present);

private:
    fx::ShadowMap shadows_;
    fx::ShadowLitPass lit_;
    fx::RadialBlur blur_;
    fx::ColourMatrixPass grading_;
    fx::UiQueuePass ui_;
};

}  // namespace lesson06
