#pragma once
// Program objects built from files in shaders/: compile and link errors come back with the real
// file name and line, a program knows its active uniforms (looked up once, not per draw), and a
// ReloadableProgram keeps the last good program when an edited source fails.
#include <filesystem>
#include <memory>
#include <optional>
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

    std::string name() const;  // the label, or the file names joined by " + "
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
    // Builds at once, and joins the ProgramRegistry open on this thread, if any.
    explicit ReloadableProgram(ProgramSources sources);
    ReloadableProgram(ReloadableProgram&&) noexcept = default;
    ReloadableProgram& operator=(ReloadableProgram&&) noexcept = default;
    ReloadableProgram(const ReloadableProgram&) = delete;
    ReloadableProgram& operator=(const ReloadableProgram&) = delete;

    // Builds from the current files. On failure the last good program stays in use and error()
    // says why. One that never built from a student's file (gl/shader_substitutes.hpp) is built from
    // ours instead, keeping the student's error, so an exercise's lesson opens.
    Status reload();
    // Reloads when a source file (or an include) changed on disk since the last attempt.
    bool reloadIfChanged();

    const Program& program() const;
    GLuint name() const { return program().name(); }
    bool usable() const { return static_cast<bool>(program()); }
    const std::string& error() const;
    const ProgramSources& sources() const;
    // Builds so far that succeeded, for the overlay.
    int generation() const;

    // The program itself, shared with the registry it joined, so that moving a ReloadableProgram
    // (effects are made by value and moved into place) leaves the registry's entry valid.
    struct State;

private:
    friend class ProgramRegistry;
    std::shared_ptr<State> state_;
};

// The programs made while it is open, wherever they were made (a lesson, the effects it uses): the
// runner opens one for a lesson, reloads every program in it on F5 or when a file changes, and shows
// their errors, so no lesson keeps a list. Programs join when built and leave when destroyed.
class ProgramRegistry {
public:
    // Opens this registry on the calling thread until it is destroyed (the one open before is open
    // again then).
    ProgramRegistry();
    ~ProgramRegistry();
    ProgramRegistry(const ProgramRegistry&) = delete;
    ProgramRegistry& operator=(const ProgramRegistry&) = delete;

    // Both return how many programs were built again (a failed build counts: its error is new).
    int reloadAll();
    int reloadChanged();
    // The errors of the programs whose last build failed, in the order they were made.
    std::vector<std::string> errors() const;
    // The error of the first program that never built (no last good program to draw with), if any.
    std::optional<std::string> firstUnusable() const;
    // Programs alive now.
    std::size_t size() const;

    static ProgramRegistry* open();

private:
    friend class ReloadableProgram;
    std::vector<std::shared_ptr<ReloadableProgram::State>> live() const;
    std::vector<std::weak_ptr<ReloadableProgram::State>> programs_;
    ProgramRegistry* outer_ = nullptr;
};

}  // namespace fx::gl
