#pragma once
// --dump-shaders DIR: every shader stage the app hands to the driver, written out as the exact text it
// compiled (includes expanded, #defines in, #line directives kept), so that another compiler can check
// what this one accepted. The portability test runs every step and the bench sweep of every lesson with
// it and has Khronos' reference compiler (glslangValidator) validate each file: Mesa is one driver of
// several, and a variant nobody built elsewhere is a variant nobody checked.
//
// Files are named by the program's label and the stage ("bloom_upsample_BLOOM_FILTERS_1_BLOOM_WIDE_0.frag");
// a second, different text under one name gets "-2", "-3"... A text already there is not written again,
// so runs of every step into one folder leave one file per variant. DIR/index.tsv lists every file with
// its stage, whether the driver compiled it ("compiled") or refused it ("refused": lesson 01's
// deliberate mistakes), the program's label and the files that went into it, in source-string order
// (the number a compiler message and a #line directive give). One run at a time per folder.
#include <filesystem>
#include <string>

#include "base/result.hpp"
#include "gl/gl.hpp"
#include "gl/shader_source.hpp"

namespace fx::gl {

// Starts writing into `folder` (created when missing; a file there is refused). Empty: stops.
Status setShaderDumpFolder(const std::filesystem::path& folder);
const std::filesystem::path& shaderDumpFolder();

// After glCompileShader: writes the stage's text and its index line, when a folder is set. A failure to
// write is logged with the file and the reason, and counted (shaderDumpFailures), never thrown.
void dumpShaderStage(const std::string& programLabel, GLenum stage, GLuint shader,
                     const ExpandedSource& source);
int shaderDumpFailures();

// What a label becomes in a file name: letters, digits, '-' and '_' kept, every other run of
// characters one '_' ("bloom upsample (BLOOM_FILTERS 1)" -> "bloom_upsample_BLOOM_FILTERS_1").
std::string shaderDumpBaseName(const std::string& programLabel);

}  // namespace fx::gl
