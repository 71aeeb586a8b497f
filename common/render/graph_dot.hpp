#pragma once
// One frame's graph as Graphviz dot, to see its shape: passes as boxes numbered in the order they ran
// (with the order they were declared in), textures as ellipses, an edge for every read and write.
// Passes that did not run and textures that got no memory are grey, labelled with the reason. A pass
// that inherited state it depends on (PassRecord::stateInherited) has a red outline and says what.
// Inspected and captured textures have a double outline. The runner writes it with --graph FILE.dot;
// `dot -Tpng FILE.dot -o FILE.png` draws it (Graphviz is a tool for reading it, not a dependency).
#include <string>

#include "render/frame_report.hpp"

namespace fx {

// From the report of a compiled (and usually executed) frame: FrameGraph::report().
std::string toDot(const FrameReport& report);

// A graph toDot wrote, drawn top to bottom instead of left to right: a long chain of passes fits a
// page taller than it is wide this way (the handout picks whichever direction fits its page better).
std::string topToBottom(std::string dot);

}  // namespace fx
