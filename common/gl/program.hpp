#pragma once
// Program objects built from files in shaders/: compile and link errors come back with the real
// file name and line, a program knows its active uniforms (looked up once, not per draw), and a
// ReloadableProgram keeps the last good program when an edited source fails.
#include <filesystem>
#include <string>
#include <unordered_map>
#include <vector>

#include "base/result.hpp"
#include "gl/object.hpp"

namespace fx::gl {

// Paths are relative to shaders/ (or absolute). A program has a vertex and a fragment stage, or a
// compute stage alone.
struct ProgramSources {
    std::filesystem::path vertex;
    std::filesystem::path fragment;
    std::filesystem::path compute;
    std::string defines;  // extra lines after #version, e.g. "#define TAPS 16"
    std::string label;    // for debuggers and messages; defaults to the file names
};

class Program {
public:
    Program() = default;

    // Compiles and links; on failure the error holds the mapped compiler or linker log.
    static Result<Program> build(const ProgramSources& sources);

    GLuint name() const { return name_.name(); }
    explicit operator bool() const { return static_cast<bool>(name_); }
    const std::string& label() const { return label_; }

    // -1 when the program has no active uniform of that name (declared but unused counts as absent:
    // the compiler removes it, the chapter's pitfall).
    GLint uniformLocation(const std::string& uniform) const;
    bool hasUniform(const std::string& uniform) const { return uniformLocation(uniform) >= 0; }
    const std::unordered_map<std::string, GLint>& activeUniforms() const { return uniforms_; }

    // Every file that went into the program, includes too.
    const std::vector<std::filesystem::path>& sourceFiles() const { return files_; }

private:
    ProgramName name_;
    std::string label_;
    std::unordered_map<std::string, GLint> uniforms_;
    std::vector<std::filesystem::path> files_;
};

class ReloadableProgram {
public:
    ReloadableProgram() = default;
    explicit ReloadableProgram(ProgramSources sources);

    // Builds from the current files. On failure the last good program stays in use and error()
    // says why.
    Status reload();
    // Reloads when a source file (or an include) changed on disk since the last attempt.
    bool reloadIfChanged();

    const Program& program() const { return program_; }
    GLuint name() const { return program_.name(); }
    bool usable() const { return static_cast<bool>(program_); }
    const std::string& error() const { return error_; }
    const ProgramSources& sources() const { return sources_; }
    // Builds so far that succeeded, for the overlay.
    int generation() const { return generation_; }

private:
    ProgramSources sources_;
    Program program_;
    std::string error_;
    std::vector<std::filesystem::path> watched_;
    std::vector<std::filesystem::file_time_type> stamps_;
    int generation_ = 0;

    void rememberStamps(const std::vector<std::filesystem::path>& files);
};

}  // namespace fx::gl
