#pragma once
// What a lesson's --all-steps capture gives the handout: each step's report, frame graph and
// pictures (DIR/step-K/), the textures its text points at, and its graph drawn by Graphviz.
#include <filesystem>
#include <string>
#include <vector>

#include "app/handout_io.hpp"
#include "app/handout_page.hpp"

namespace fx::handout {

struct CapturedStep {
    std::filesystem::path folder;  // DIR/step-K
    json report;
    std::string dot;  // graph.dot, as the lesson wrote it
};

// DIR/step-1, step-2 ... as long as there is one (the capture ran every step, or failed).
Result<std::vector<CapturedStep>> readCapturedSteps(const std::filesystem::path& dir);

// The textures step `number`'s text points at (a `code` name the frame has a picture of), moved into
// `folder` as step-K-<name>.png; a name with an index ("bloom.down[0]") brings its whole chain, shown
// as a strip, as the inspector does.
Result<std::vector<View>> takeViews(const CapturedStep& step, const std::string& text, int number,
                                    const std::filesystem::path& folder);

// A frame graph drawn as SVG by Graphviz's `dot`, left to right or top to bottom, whichever keeps
// more of its size on a printed page.
struct DrawnGraph {
    std::filesystem::path file;  // in `work`
    int width = 0, height = 0;   // CSS pixels
};
Result<DrawnGraph> drawGraph(const std::filesystem::path& dot, const std::string& graph,
                             const std::filesystem::path& work, const std::string& what);

}  // namespace fx::handout
