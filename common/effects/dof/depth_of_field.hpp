#pragma once
// Depth of field after the scene pass (the Depth of field chapter and, beyond it, the gather of the
// state of the art). Every pass is full-screen (effects/post/fullscreen_pass.hpp) and reads the HDR
// scene's colour and depth:
//   "dof coc"        scene.depth -> dof.coc (R32F): the signed CoC diameter in pixels (coc.glsl, the
//                    same maths as scene/thin_lens.hpp);
//   "dof heat map"   dof.coc -> dof.heat: near field orange, far field blue, in focus grey;
//   "dof naive"      the chapter's first version: 13 Poisson taps scaled by (raw depth - 0.935) * 0.1;
//   "dof chapter"    the chapter's physical version: 13 Poisson taps scaled by the centre's CoC;
//   "dof prefilter", "dof tile max", "dof gather", "dof composite": the ring-kernel gather with
//                    near and far fields, at half (or full) resolution, bounded by a tile-max CoC.
#include <string>

#include "effects/post/fullscreen_pass.hpp"
#include "effects/post/fullscreen_variants.hpp"
#include "render/frame_graph.hpp"
#include "scene/thin_lens.hpp"

namespace fx {

// What the CoC shaders take (coc.glsl's uniforms), from a thin-lens model.
struct DofLensUniforms {
    float inverseFocusM = 0.1f;  // 1/P
    float scalePixelsM = 0.0f;   // K
    float maxCocPixels = 16.0f;  // |CoC| clamp (a diameter)
    float radiusPerDiameter = 0.5f;
    float nearM = 0.1f, farM = 500.0f;
};
DofLensUniforms dofLensUniforms(const ThinLensModel& model);

// The chapter's naive version: raw depth minus `sharpDepth`, times `scale`, in texture coordinates.
struct NaiveDofSettings {
    float sharpDepth = 0.935f;
    float scale = 0.1f;
};

// Disk kernels of rings around a centre tap: ring k of `rings` holds tapsPerRing * k taps.
struct DofKernel {
    int taps;
    int rings;
    int tapsPerRing;
};
// 16 (2 rings of 5k), 22, 43, 71 (2, 3, 4 rings of 7k): Unity PPv2's small to very large. `taps` is
// rounded down to one of these (below 16: 16).
DofKernel dofKernelForTaps(int taps);

struct DofGatherSettings {
    int taps = 22;  // the ring kernel (dofKernelForTaps)
    bool halfResolution = true;
    bool separateFields = true;  // near/far separation
    float highlight = 0.0f;      // bokeh: extra weight per unit of luminance above 1 (0: none)
};

// The gather's tile: 16 full-resolution pixels (8 gather texels at half resolution).
inline constexpr int kDofTileFullPixels = 16;

class DepthOfField {
public:
    // "dof coc": depth -> dof.coc, the signed CoC diameter in pixels.
    DeclaredPass declareCoc(FrameGraph& graph, TextureHandle depth, const DofLensUniforms& lens) const;
    // "dof heat map": the CoC as a picture over the scene in grey.
    DeclaredPass declareHeatMap(FrameGraph& graph, TextureHandle color, TextureHandle coc,
                                const DofLensUniforms& lens) const;
    // "dof naive": the chapter's first version, from the raw depth.
    DeclaredPass declareNaive(FrameGraph& graph, TextureHandle color, TextureHandle depth,
                              const NaiveDofSettings& settings) const;
    // "dof chapter": 13 Poisson taps scaled by the centre's blur radius.
    DeclaredPass declareChapter(FrameGraph& graph, TextureHandle color, TextureHandle coc,
                                const DofLensUniforms& lens) const;

    struct Gather {
        TextureHandle prefiltered, tiles, gathered, result;
    };
    // The four gather passes; `result` is full resolution.
    Gather declareGather(FrameGraph& graph, TextureHandle color, TextureHandle coc,
                         const DofLensUniforms& lens, const DofGatherSettings& settings) const;

private:
    // The gather with near/far separation on or off (DOF_SEPARATE), built into the program.
    const FullscreenPass& gatherProgram(bool separateFields) const;

    FullscreenPass coc_{"effects/dof/coc.frag", "dof coc"};
    FullscreenPass heat_{"effects/dof/heat_map.frag", "dof heat map"};
    FullscreenPass naive_{"effects/dof/naive.frag", "dof naive"};
    FullscreenPass chapter_{"effects/dof/chapter.frag", "dof chapter"};
    FullscreenPass prefilter_{"effects/dof/prefilter.frag", "dof prefilter"};
    FullscreenPass tileMax_{"effects/dof/tile_max.frag", "dof tile max"};
    FullscreenVariants gather_{"effects/dof/gather.frag", "dof gather"};
    FullscreenPass composite_{"effects/dof/composite.frag", "dof composite"};
};

}  // namespace fx
