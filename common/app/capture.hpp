#pragma once
// Captures: the final image and every texture of the frame, read back from the GPU, with their
// statistics for the report. PNGs show float textures through the fixed view transform documented
// in docs/captures.md (clamp to [0, 1], sRGB encode); --capture-float adds exact PFM files.
#include <filesystem>
#include <string>
#include <vector>

#include "base/result.hpp"
#include "image/image.hpp"
#include "image/image_stats.hpp"
#include "render/frame_graph.hpp"

namespace fx {

struct CapturedTexture {
    std::string name;
    TextureSpec spec;
    FloatImage pixels;  // level 0
    std::vector<ChannelStats> stats;
};

// Every texture of the graph that has a GL texture now (call after execute, before releaseTextures).
std::vector<CapturedTexture> readFrameTextures(const FrameGraph& graph);

// "bloom.down[3]" -> "bloom.down-3": a file name without brackets or spaces.
std::string captureFileStem(std::string_view textureName);

// out/fxlab-05-radial-blur-step2-003.png: the first number from 1 that no file in `folder` has yet for
// this lesson and step, so a screenshot never replaces an earlier one (of this run or another).
std::filesystem::path nextScreenshotPath(const std::filesystem::path& folder, const std::string& exe,
                                         int step);

// Writes final.png and <texture>.png (and .pfm with floats) into dir; each file whole or not at all.
Status writeCaptures(const std::filesystem::path& dir, const ByteImage& finalImage,
                     const std::vector<CapturedTexture>& textures, bool floats);

}  // namespace fx
