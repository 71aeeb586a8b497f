#pragma once
// Beyond the Clouds chapter: the cloud layer marched into a texture of its own (at full or half
// resolution), averaged over frames with reprojection, then blended over the scene.
//
//   clouds march ──► clouds.layer (RGBA16F, premultiplied; the output's size or half of it)
//   clouds accumulate ──► clouds.result + clouds.history.next   reads clouds.layer and
//                         clouds.history.previous (two imports, swapped every frame)
//   clouds composite ──► scene.color          premultiplied "over", bilinear from the layer's size
//
// With a jitter that moves every frame (IGN, R2) each frame's banding error is different noise, and
// the average converges to what many more samples give. The history is reprojected with last frame's
// camera: a pixel's cloud is taken to sit where its ray crosses the slab's middle (or at the surface,
// if nearer), and last frame's value there is clamped to the range of this frame's 3x3 neighbourhood,
// so clouds that moved or were uncovered do not leave ghosts. Any change of the settings, the size or
// the step starts the average again. Without accumulation the march writes clouds.result itself:
// either way the composite reads clouds.result, the cloud layer's final output (the bench compares it).
#include <cstdint>

#include <glm/mat4x4.hpp>

#include "effects/clouds/cloud_pass.hpp"

namespace fx {

struct CloudTemporalOptions {
    bool accumulate = false;
    bool halfResolution = false;
    // Frames averaged at most: the weight of the new frame never drops below 1/maxFrames.
    int maxFrames = 16;
};

class CloudTemporal {
public:
    // Declares the march, the accumulation (when asked for) and the composite over inputs.color.
    // `settingsKey` changes whenever anything but the jitter changes (the average restarts).
    // `scene`, the density texture and `march` must outlive the frame's execution.
    void declare(FrameGraph& graph, const CloudPass& march, const CloudInputs& inputs,
                 const CloudDensityTexture& density, const CloudFrameSettings& settings,
                 const CloudTemporalOptions& options, std::uint64_t settingsKey, Size2D outputSize);

    // Frames in the running average (0 when accumulation is off).
    int framesAveraged() const { return frames_; }
    std::uint64_t historyBytes() const;

private:
    FullscreenPass accumulate_{"effects/clouds/cloud_accumulate.frag", "clouds accumulate"};
    FullscreenPass composite_{"common/copy.frag", "clouds composite"};
    gl::Texture history_[2];
    int newest_ = 0;  // history_[newest_] holds last frame's result
    int frames_ = 0;
    Size2D historySize_;
    std::uint64_t key_ = 0;
    glm::mat4 previousViewProjection_{1.0f};
};

}  // namespace fx
