#include "effects/dof/depth_of_field.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

#include "base/log.hpp"
#include "effects/dof/dof_bindings.hpp"

namespace fx {
namespace {

// coc.glsl's uniforms, set only in the programs that have them (dof_bindings.glsl).
void setLens(GLuint program, const DofLensUniforms& l) {
    glProgramUniform2f(program, glsl::kDofDepthRangeLocation, l.nearM, l.farM);
    glProgramUniform4f(program, glsl::kDofLensLocation, l.inverseFocusM, l.scalePixelsM, l.maxCocPixels,
                       l.radiusPerDiameter);
}

// The radius part of coc.glsl only: heat map, chapter, prefilter and composite use blurRadiusPixels
// and the clamp, not the depth range.
void setRadius(GLuint program, const DofLensUniforms& l) {
    glProgramUniform4f(program, glsl::kDofLensLocation, l.inverseFocusM, l.scalePixelsM, l.maxCocPixels,
                       l.radiusPerDiameter);
}

}  // namespace

DofLensUniforms dofLensUniforms(const ThinLensModel& m) {
    return {float(1.0 / m.focusM),      float(m.scalePixelsM), float(m.maxCocPixels),
            float(m.radiusPerDiameter), float(m.nearM),        float(m.farM)};
}

DofKernel dofKernelForTaps(int taps) {
    if (taps >= 71) return {71, 4, 7};
    if (taps >= 43) return {43, 3, 7};
    if (taps >= 22) return {22, 2, 7};
    return {16, 2, 5};
}

const FullscreenPass& DepthOfField::gatherProgram(bool separateFields) const {
    return gather_.get({{"DOF_SEPARATE", separateFields ? 1 : 0}});
}

DeclaredPass DepthOfField::declareCoc(FrameGraph& graph, TextureHandle depth,
                                      const DofLensUniforms& lens) const {
    const FullscreenPass* program = &coc_;
    Pass& pass = coc_.addPass(graph, "dof coc", [program, depth, lens](PassContext& ctx) {
        setLens(program->program(), lens);
        program->draw({ctx.native(depth)});
    });
    TextureHandle coc = pass.create("dof.coc", {TextureSize::output(), TextureFormat::R32F, 1},
                                    TextureUsage::ColorAttachment);
    pass.read(depth).setTaps(1);
    return {pass, coc};
}

// The heat map and the chapter's 13 taps: a full-resolution picture from the scene's colour and the CoC.
static DeclaredPass declareFromCoc(FrameGraph& graph, const char* name, const char* output,
                                   const FullscreenPass& program, TextureHandle color, TextureHandle coc,
                                   const DofLensUniforms& lens, double taps) {
    const FullscreenPass* p = &program;
    Pass& pass = program.addPass(graph, name, [p, color, coc, lens](PassContext& ctx) {
        setRadius(p->program(), lens);
        p->draw({ctx.native(color), ctx.native(coc)});
    });
    TextureHandle out = pass.create(output, {TextureSize::output(), TextureFormat::RGBA16F, 1},
                                    TextureUsage::ColorAttachment);
    pass.read(color).read(coc).setTaps(taps);
    return {pass, out};
}

DeclaredPass DepthOfField::declareHeatMap(FrameGraph& graph, TextureHandle color, TextureHandle coc,
                                          const DofLensUniforms& lens) const {
    return declareFromCoc(graph, "dof heat map", "dof.heat", heat_, color, coc, lens, 2);
}

DeclaredPass DepthOfField::declareNaive(FrameGraph& graph, TextureHandle color, TextureHandle depth,
                                        const NaiveDofSettings& s) const {
    const FullscreenPass* program = &naive_;
    Pass& pass = naive_.addPass(graph, "dof naive", [program, color, depth, s](PassContext& ctx) {
        glProgramUniform2f(program->program(), glsl::kDofNaiveLocation, s.sharpDepth, s.scale);
        program->draw({ctx.native(color), ctx.native(depth)});
    });
    TextureHandle out = pass.create("dof.naive", {TextureSize::output(), TextureFormat::RGBA16F, 1},
                                    TextureUsage::ColorAttachment);
    pass.read(color).read(depth).setTaps(14);  // the depth, the pixel and 12 Poisson taps
    return {pass, out};
}

DeclaredPass DepthOfField::declareChapter(FrameGraph& graph, TextureHandle color, TextureHandle coc,
                                          const DofLensUniforms& lens) const {
    // The CoC, the pixel itself and the chapter's 12 Poisson taps around it.
    return declareFromCoc(graph, "dof chapter", "dof.chapter", chapter_, color, coc, lens, 14);
}

DepthOfField::Gather DepthOfField::declareGather(FrameGraph& graph, TextureHandle color, TextureHandle coc,
                                                 const DofLensUniforms& lens,
                                                 const DofGatherSettings& s) const {
    Gather g;
    const int scale = s.halfResolution ? 2 : 1;
    const int tile = kDofTileFullPixels / scale;  // gather texels per tile
    const TextureSize gatherSize = TextureSize::outputFraction(1, scale);

    const FullscreenPass* prefilter = &prefilter_;
    Pass& pre =
        prefilter_.addPass(graph, "dof prefilter", [prefilter, color, coc, lens, scale](PassContext& ctx) {
            setRadius(prefilter->program(), lens);
            glProgramUniform1i(prefilter->program(), glsl::kDofPrefilterScaleLocation, scale);
            prefilter->draw({ctx.native(color), ctx.native(coc)});
        });
    g.prefiltered =
        pre.create("dof.prefiltered", {gatherSize, TextureFormat::RGBA16F, 1}, TextureUsage::ColorAttachment);
    pre.read(color).read(coc).setTaps(2 * scale * scale);  // colour and CoC of every full-size texel under it

    const FullscreenPass* tileMax = &tileMax_;
    TextureHandle prefiltered = g.prefiltered;
    Pass& tiles = tileMax_.addPass(graph, "dof tile max", [tileMax, prefiltered, tile](PassContext& ctx) {
        glProgramUniform1i(tileMax->program(), glsl::kDofTilePixelsLocation, tile);
        tileMax->draw({ctx.native(prefiltered)});
    });
    g.tiles = tiles.create("dof.tiles",
                           {TextureSize::outputFraction(1, kDofTileFullPixels), TextureFormat::RG16F, 1},
                           TextureUsage::ColorAttachment);
    tiles.read(g.prefiltered).setTaps(tile * tile);

    // One field or two is built into the program: a uniform branch ran both on llvmpipe.
    const FullscreenPass& gatherPass = gatherProgram(s.separateFields);
    const FullscreenPass* gather = &gatherPass;
    const DofKernel kernel = dofKernelForTaps(s.taps);
    // The clamp as a radius in gather texels bounds the kernel and how many tiles it looks across.
    const float maxRadius = lens.maxCocPixels * lens.radiusPerDiameter / float(scale);
    TextureHandle tileTexture = g.tiles;
    Pass& gath = gatherPass.addPass(
        graph, "dof gather",
        [gather, prefiltered, tileTexture, kernel, s, tile, maxRadius, scale](PassContext& ctx) {
            GLuint p = gather->program();
            glProgramUniform1i(p, glsl::kDofRingsLocation, kernel.rings);
            glProgramUniform1i(p, glsl::kDofTapsPerRingLocation, kernel.tapsPerRing);
            glProgramUniform1i(p, glsl::kDofGatherTilePixelsLocation, tile);
            glProgramUniform1f(p, glsl::kDofMaxRadiusLocation, std::max(maxRadius, 0.0f));
            glProgramUniform1f(p, glsl::kDofHighlightLocation, std::max(s.highlight, 0.0f));
            glProgramUniform1i(p, glsl::kDofGatherScaleLocation, scale);
            gather->draw({ctx.native(prefiltered), ctx.native(tileTexture)});
        });
    g.gathered =
        gath.create("dof.gathered", {gatherSize, TextureFormat::RGBA16F, 1}, TextureUsage::ColorAttachment);
    // The centre, the tiles within the clamp's reach (their largest CoC), then the kernel's rings.
    const int reach = int(std::ceil(std::max(maxRadius, 0.0f) / float(tile)));
    gath.read(g.prefiltered).read(g.tiles).setTaps(1 + (2 * reach + 1) * (2 * reach + 1) + kernel.taps);

    const FullscreenPass* composite = &composite_;
    TextureHandle gathered = g.gathered;
    Pass& comp =
        composite_.addPass(graph, "dof composite", [composite, color, coc, gathered, lens](PassContext& ctx) {
            setRadius(composite->program(), lens);
            composite->draw({ctx.native(color), ctx.native(coc), ctx.native(gathered)});
        });
    g.result = comp.create("dof.result", {TextureSize::output(), TextureFormat::RGBA16F, 1},
                           TextureUsage::ColorAttachment);
    comp.read(color).read(coc).read(g.gathered).setTaps(3);
    return g;
}

}  // namespace fx
