#pragma once
// The frame as the chapter writes it by hand in Engine::Render() (Shader effects §3.2 to §3.4), one
// line per step of its code, each with the fxlab pass that does that work. The overlay shows it next
// to the order the frame graph derives from what each pass reads and writes.
#include <string>
#include <vector>

namespace lesson03 {

struct ChapterLine {
    std::string text;  // "Create the shadow map"
    std::string pass;  // "shadow map"; empty for work outside the GL frame (sorting on the CPU)
};

// The chapter's Render() for a lesson step (0-based, FboPipelineLesson::Step).
const std::vector<ChapterLine>& chapterOrder(int step);

// The passes in the order the chapter runs them (each where its last line is).
std::vector<std::string> chapterPassOrder(int step);

}  // namespace lesson03
