#pragma once
// `./fxlab handout`: a lesson as a folder a student keeps (index.html, its pictures, style.css), made
// from the lesson itself. The lesson's executable captures every step headless at a fixed moment of
// its clock (--all-steps --capture: a fixed frame count at the fixed time step, so two runs give the
// same pictures), with each step's report (facts, passes, textures) and frame graph (Graphviz dot,
// drawn as SVG); the text is lesson.md and lesson.<lang>.md read as the overlay reads them
// (app/lesson_text_files.hpp); the bench's results come from its output folder.
//
// Everything is written into a folder the caller stages (base/output_folder.hpp), so a failure at
// any point leaves nothing half-written at the target.
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "app/handout_page.hpp"
#include "base/result.hpp"
#include "base/size2d.hpp"

namespace fx::handout {

struct HandoutOptions {
    std::vector<std::string> languages{"en"};  // the first one's page is index.html
    Size2D size{1280, 720};
    int frames = 3;          // the captured frame: this many frames of the headless clock
    bool withBench = false;  // run the bench (slow) instead of reading earlier results
    std::filesystem::path benchRoot = "out/bench";  // earlier results: <benchRoot>/<NN-name>/bench.json
    std::function<void(const std::string&)> progress = [](const std::string&) {};
};

// The handout folder's name of a lesson executable: fxlab-06-bloom -> "06-bloom"; an error for any
// other name.
Result<std::string> lessonFolderOf(const std::filesystem::path& executable);

// Writes the handout of the lesson built as `executable` (fxlab-NN-name) into `folder` (empty).
// Gives its entry for a contents page. Errors name the lesson, the step or file, and the reason; a
// failed capture quotes the end of its log.
Result<ContentsEntry> writeLessonHandout(const std::filesystem::path& executable,
                                         const HandoutOptions& options, const std::filesystem::path& folder);

// style.css, from res/handout/style.css.
Status writeStyle(const std::filesystem::path& folder);

// The contents pages of several lessons (index.html, and index.<lang>.html for the other languages).
Status writeContents(const std::vector<ContentsEntry>& lessons, const std::vector<std::string>& languages,
                     const std::filesystem::path& folder);

}  // namespace fx::handout
