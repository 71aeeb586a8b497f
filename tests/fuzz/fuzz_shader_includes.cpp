// A student's shader file and its #include lines (gl/shader_source.hpp, base/path_rule.hpp): the input
// is the text of a file in a student's folder that also holds a helper, a link to an exercise's answer
// and a link out of the folder. Whatever it says, every file the expansion reads lies beside it, in
// shaders/ or in exercises/, and none in exercises/solutions/; anything else read is a finding.
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>

#include "base/file_io.hpp"
#include "base/log.hpp"
#include "base/path_rule.hpp"
#include "fuzz_input.hpp"
#include "gl/shader_source.hpp"

namespace {

namespace fs = std::filesystem;

fs::path studentFolder() {
    static const fs::path folder = [] {
        const fs::path root = fs::temp_directory_path() / ("fx_fuzz_includes_" + std::to_string(::getpid()));
        fs::remove_all(root);
        fs::create_directories(root / "student");
        (void)fx::writeFileAtomically(root / "student" / "helper.glsl", std::string_view("float helper;\n"));
        (void)fx::writeFileAtomically(root / "secret.glsl", std::string_view("float secret;\n"));
        fs::create_symlink(fx::projectRoot() / "exercises" / "solutions" / "05-1" / "radial_blur_offset.glsl",
                           root / "student" / "answer.glsl");
        fs::create_symlink(root / "secret.glsl", root / "student" / "out.glsl");
        std::atexit([] {
            fs::remove_all(fs::temp_directory_path() / ("fx_fuzz_includes_" + std::to_string(::getpid())));
        });
        return root / "student";
    }();
    return folder;
}

bool allowed(const fs::path& file) {
    const fs::path resolved = fx::resolvedPath(file);
    const fs::path exercises = fx::resolvedPath(fx::projectRoot() / "exercises");
    if (fx::isInsideFolder(resolved, fx::resolvedPath(exercises / "solutions"))) return false;
    return fx::isInsideFolder(resolved, fx::resolvedPath(studentFolder())) ||
           fx::isInsideFolder(resolved, fx::resolvedPath(fx::shaderDir())) ||
           fx::isInsideFolder(resolved, exercises);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const fs::path folder = studentFolder();
    const std::string text(fuzz::text(data, size));
    const fs::path file = folder / "student.frag";
    // Read from memory: the student's file is the input; every other file from the disk, as the check reads
    // it.
    auto reader = [&](const fs::path& path) -> fx::Result<std::string> {
        if (path == file) return text;
        if (!allowed(path)) {
            std::fprintf(stderr, "an #include read %s\n", path.c_str());
            std::abort();
        }
        return fx::readFile(path, fx::file_limits::shader);
    };
    (void)fx::gl::expandShaderSource(file, fx::shaderDir(), {}, reader);
    return 0;
}
