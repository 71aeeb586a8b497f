#include "chapter_order.hpp"

#include <algorithm>

namespace lesson03 {

namespace {

// Section 3.2, the order before the rework.
const std::vector<ChapterLine> kBefore = {
    {"1. Clear the window", "clear + draw state"},
    {"2. Upload the camera", "scene"},
    {"3. Draw state: depth test on, alpha blending on", "clear + draw state"},
    {"4. Upload the lights", "scene"},
    {"5. Sort objects by render queue", ""},
    {"6. Create the shadow map", "shadow map"},
    {"7. Bind the window and its viewport", "scene"},
    {"8. Draw 3D", "scene"},
    {"9. UI queue: depth test off", "ui queue"},
};

// Section 3.2, the new order, as first written: the shadow map before any state is set.
const std::vector<ChapterLine> kReordered = {
    {"1. Sort objects by render queue", ""},
    {"2. Create the shadow map", "shadow map"},
    {"3. Bind the window and its viewport", "clear + draw state"},
    {"4. Clear to the sky", "clear + draw state"},
    {"5. Upload the camera", "scene"},
    {"6. Draw state: depth test on, alpha blending on", "clear + draw state"},
    {"7. Upload the lights", "scene"},
    {"8. Draw 3D", "scene"},
    {"9. UI queue: depth test off", "ui queue"},
};

// Section 3.3: every pass sets the state it depends on.
const std::vector<ChapterLine> kFixed = {
    {"1. Sort objects by render queue", ""},
    {"2. Create the shadow map: depth test on, blending off, clear depth", "shadow map"},
    {"3. Bind the window and its viewport", "scene"},
    {"4. Clear to the sky", "scene"},
    {"5. Upload the camera", "scene"},
    {"6. Draw state: depth test on, blending off", "scene"},
    {"7. Upload the lights", "scene"},
    {"8. Draw 3D", "scene"},
    {"9. UI queue: depth test off", "ui queue"},
};

// Section 3.4: the scene into fboMain, one full-screen pass to the window, the UI on top.
std::vector<ChapterLine> intoFloatTarget(const std::string& finalPass) {
    return {
        {"1. Sort objects by render queue", ""},
        {"2. Create the shadow map: depth test on, blending off, clear depth", "shadow map"},
        {"3. Bind fboMain (RGBA16F + depth texture) and its viewport", "scene"},
        {"4. Clear to the sky", "scene"},
        {"5. Upload the camera and the lights, set the draw state", "scene"},
        {"6. Draw 3D", "scene"},
        {"7. Bind the window and its viewport", finalPass},
        {"8. DrawMainImageToDefaultFramebuffer", finalPass},
        {"9. UI queue: depth test off", "ui queue"},
    };
}

}  // namespace

const std::vector<ChapterLine>& chapterOrder(int step) {
    static const std::vector<ChapterLine> copyToWindow = intoFloatTarget("to the window");
    static const std::vector<ChapterLine> outputTransform = intoFloatTarget("output transform");
    switch (step) {
        case 0:
            return kBefore;
        case 1:
            return kReordered;
        case 2:
            return kFixed;
        case 3:
            return copyToWindow;
        default:
            return outputTransform;
    }
}

std::vector<std::string> chapterPassOrder(int step) {
    // A pass runs where its last line is: the chapter uploads the camera early, but the pass that
    // uses it draws at "Draw 3D".
    std::vector<std::string> passes;
    for (const ChapterLine& line : chapterOrder(step)) {
        if (line.pass.empty()) continue;
        passes.erase(std::remove(passes.begin(), passes.end(), line.pass), passes.end());
        passes.push_back(line.pass);
    }
    return passes;
}

}  // namespace lesson03
