#pragma once
// A multiple-render-target pass's safety net: a fragment output whose location has no entry in the
// framebuffer's draw-buffer list, or whose entry names an attachment without an image, is written
// nowhere and GL says nothing. checkOutputsOnce asks GL (gl::checkProgramOutputs) the first time a
// program draws into a framebuffer and logs the error by name; later draws cost nothing.
#include <string_view>

#include "gl/gl.hpp"

namespace fx {

// Checks `program` against the framebuffer bound for drawing now, once per (program, framebuffer).
// Returns false (and logs "pass '<pass>': output ...") when an output would be lost.
bool checkOutputsOnce(GLuint program, std::string_view pass);

}  // namespace fx
