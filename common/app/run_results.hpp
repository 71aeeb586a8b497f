#pragma once
// What a run leaves behind: the captures (final.png and every texture of the last frame) and the
// JSON report, with the lesson's facts for its last frame.
#include <filesystem>
#include <string>

#include <nlohmann/json.hpp>

#include "app/frame_loop.hpp"

namespace fx {

// What the log says the captures are: only the files that were written, and why final.png is missing
// when it is (emptyFrame: the frame was 0x0; otherwise the run ended before its last frame).
std::string capturesWrittenMessage(const std::filesystem::path& dir, bool finalImage, bool picture,
                                   std::size_t textures, bool emptyFrame);

// The report's "layout": the window's size, the text scale and each place as [x, y, width, height] from the
// top left.
nlohmann::ordered_json layoutJson(const PanelLayout& layout, Size2D window, float textScale);

// Returns 0, or 1 when something could not be written.
int writeRunResults(RunSession& session, const RunPlan& plan, Context& context,
                    const gl::ProgramRegistry& programs, RunRecord& record);

}  // namespace fx
