#pragma once
// A student's file in place of one of ours: while a substitute is set, every shader that names
// `original` (as a program's stage or through #include) is built from `replacement` instead. Compile
// errors then name the student's file and line, and the reload watch follows it, so an exercise reuses
// the live reload that keeps the last good program (app/exercise_*.hpp, docs/exercises.md).
#include <filesystem>
#include <map>
#include <optional>
#include <vector>

namespace fx::gl {

// Sets one substitute for the life of this object (the one set before for `original`, if any, is
// back afterwards). Paths may be relative to shaders/ or absolute.
class ShaderSubstitute {
public:
    ShaderSubstitute(const std::filesystem::path& original, const std::filesystem::path& replacement);
    ~ShaderSubstitute();
    ShaderSubstitute(const ShaderSubstitute&) = delete;
    ShaderSubstitute& operator=(const ShaderSubstitute&) = delete;

private:
    std::filesystem::path original_;
    std::optional<std::filesystem::path> before_;
};

// Sets every substitute aside for the life of this object, so that programs build from our files: a
// lesson whose student's file never compiled opens with the lesson's own program (ReloadableProgram).
class ShaderSubstitutesSetAside {
public:
    ShaderSubstitutesSetAside();
    ~ShaderSubstitutesSetAside();
    ShaderSubstitutesSetAside(const ShaderSubstitutesSetAside&) = delete;
    ShaderSubstitutesSetAside& operator=(const ShaderSubstitutesSetAside&) = delete;

private:
    std::map<std::filesystem::path, std::filesystem::path> set_;
};

// The file to read for `file` (absolute): its substitute, or `file` itself.
std::filesystem::path substitutedShaderFile(const std::filesystem::path& file);
// Every replacement set now: a program that failed before its includes were known watches them too.
std::vector<std::filesystem::path> shaderSubstituteFiles();

}  // namespace fx::gl
