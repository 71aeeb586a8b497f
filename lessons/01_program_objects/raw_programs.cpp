#include "raw_programs.hpp"

#include "base/paths.hpp"
#include "gl/shader_dump.hpp"
#include "gl/shader_source.hpp"

namespace lesson01 {

fx::gl::ProgramName buildProgramWithoutChecks(const std::filesystem::path& vertexFile,
                                              const std::filesystem::path& fragmentFile,
                                              const std::string& label) {
    // #include still has to be expanded for the files to compile at all; that part is fxlab's.
    auto vsText = fx::gl::expandShaderSource(fx::shaderDir() / vertexFile, fx::shaderDir());
    auto fsText = fx::gl::expandShaderSource(fx::shaderDir() / fragmentFile, fx::shaderDir());
    const char* vsSource = vsText ? vsText->text.c_str() : "";
    const char* fsSource = fsText ? fsText->text.c_str() : "";

    GLuint vs = glCreateShader(GL_VERTEX_SHADER);
    glShaderSource(vs, 1, &vsSource, nullptr);
    glCompileShader(vs);
    if (vsText) fx::gl::dumpShaderStage(label, GL_VERTEX_SHADER, vs, *vsText);  // --dump-shaders, not a check
    fx::gl::labelObject(GL_SHADER, vs, label + ".vert");
    GLuint fs = glCreateShader(GL_FRAGMENT_SHADER);
    glShaderSource(fs, 1, &fsSource, nullptr);
    glCompileShader(fs);
    if (fsText) fx::gl::dumpShaderStage(label, GL_FRAGMENT_SHADER, fs, *fsText);
    fx::gl::labelObject(GL_SHADER, fs, label + ".frag");
    GLuint program = glCreateProgram();
    fx::gl::labelObject(GL_PROGRAM, program, label + " (unchecked)");
    glAttachShader(program, vs);
    glAttachShader(program, fs);
    glLinkProgram(program);
    // No GL_COMPILE_STATUS, no GL_LINK_STATUS: a typo gives a black object and no message.
    glDeleteShader(vs);
    glDeleteShader(fs);
    return fx::gl::ProgramName(program);
}

}  // namespace lesson01
