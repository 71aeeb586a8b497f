#include "gl/shader_dump.hpp"

#include <sstream>

#include "base/file_io.hpp"
#include "base/log.hpp"

namespace fx::gl {
namespace {

namespace fs = std::filesystem;

struct DumpState {
    fs::path folder;
    int failures = 0;
};

DumpState& state() {
    static DumpState s;
    return s;
}

const char* stageExtension(GLenum stage) {
    switch (stage) {
        case GL_VERTEX_SHADER:
            return "vert";
        case GL_FRAGMENT_SHADER:
            return "frag";
        case GL_COMPUTE_SHADER:
            return "comp";
        case GL_GEOMETRY_SHADER:
            return "geom";
        case GL_TESS_CONTROL_SHADER:
            return "tesc";
        case GL_TESS_EVALUATION_SHADER:
            return "tese";
        default:
            return "glsl";
    }
}

// One line of the index: tabs and line breaks inside a field would split it.
std::string field(std::string text) {
    for (char& c : text) {
        if (c == '\t' || c == '\n' || c == '\r') c = ' ';
    }
    return text;
}

void fail(const std::string& message) {
    log::error("--dump-shaders: ", message);
    ++state().failures;
}

// The file that holds `text` under `base`: the first name that is free or already holds that text.
Result<fs::path> fileFor(const fs::path& folder, const std::string& base, const char* extension,
                         const std::string& text, bool& alreadyThere) {
    for (int n = 1; n <= 1000; ++n) {
        fs::path path = folder / cat(base, n > 1 ? cat("-", n) : "", ".", extension);
        std::error_code ec;
        if (!fs::exists(path, ec)) {
            alreadyThere = false;
            return path;
        }
        auto existing = readFile(path, file_limits::shader);
        if (existing && *existing == text) {
            alreadyThere = true;
            return path;
        }
    }
    return Error{cat("more than 1000 different texts for ", base, ".", extension)};
}

}  // namespace

Status setShaderDumpFolder(const fs::path& folder) {
    if (!folder.empty()) {
        std::error_code ec;
        fs::create_directories(folder, ec);
        if (!fs::is_directory(folder, ec)) {
            return Error{cat(folder.string(), ": cannot write shaders there: ",
                             ec ? ec.message() : std::string("not a folder"))};
        }
    }
    state().folder = folder;
    return Status::success();
}

const fs::path& shaderDumpFolder() {
    return state().folder;
}

int shaderDumpFailures() {
    return state().failures;
}

std::string shaderDumpBaseName(const std::string& programLabel) {
    std::string out;
    bool gap = false;
    for (char c : programLabel) {
        const bool kept = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') ||
                          c == '-' || c == '_';
        if (!kept) {
            gap = true;
            continue;
        }
        if (gap && !out.empty()) out += '_';
        gap = false;
        out += c;
    }
    return out.empty() ? "program" : out;
}

void dumpShaderStage(const std::string& programLabel, GLenum stage, GLuint shader,
                     const ExpandedSource& source) {
    const fs::path& folder = state().folder;
    if (folder.empty()) return;
    GLint compiled = GL_FALSE;
    glGetShaderiv(shader, GL_COMPILE_STATUS, &compiled);

    bool alreadyThere = false;
    auto file =
        fileFor(folder, shaderDumpBaseName(programLabel), stageExtension(stage), source.text, alreadyThere);
    if (!file) return fail(file.error());
    if (!alreadyThere) {
        if (Status written = writeFileAtomically(*file, source.text); !written) return fail(written.error());
    }

    // The index gets one line per file, kept across runs into the same folder.
    const fs::path indexFile = folder / "index.tsv";
    std::string index;
    std::error_code ec;
    if (fs::exists(indexFile, ec)) {
        auto text = readTextFile(indexFile);
        if (!text) return fail(text.error());
        index = std::move(*text);
    } else {
        index = "file\tstage\tdriver\tprogram\tsources\n";
    }
    const std::string name = file->filename().string();
    if (index.find("\n" + name + "\t") != std::string::npos) return;
    std::string sources;
    for (const std::string& f : source.fileNames) sources += (sources.empty() ? "" : ",") + field(f);
    index += cat(name, "\t", stageExtension(stage), "\t", compiled == GL_TRUE ? "compiled" : "refused", "\t",
                 field(programLabel), "\t", sources, "\n");
    if (Status written = writeFileAtomically(indexFile, index); !written) fail(written.error());
}

}  // namespace fx::gl
