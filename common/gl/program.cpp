#include "gl/program.hpp"

#include "base/log.hpp"
#include "base/paths.hpp"
#include "gl/context_guard.hpp"
#include "gl/shader_dump.hpp"
#include "gl/shader_source.hpp"
#include "gl/shader_substitutes.hpp"

namespace fx::gl {
namespace {

namespace fs = std::filesystem;

fs::path resolveShaderPath(const fs::path& p) {
    return p.is_absolute() ? p : shaderDir() / p;
}

std::string shaderInfoLog(GLuint shader) {
    GLint length = 0;
    glGetShaderiv(shader, GL_INFO_LOG_LENGTH, &length);
    std::string log(static_cast<std::size_t>(std::max(length, 1)), '\0');
    glGetShaderInfoLog(shader, length, nullptr, log.data());
    log.resize(std::char_traits<char>::length(log.c_str()));
    return log;
}

std::string programInfoLog(GLuint program) {
    GLint length = 0;
    glGetProgramiv(program, GL_INFO_LOG_LENGTH, &length);
    std::string log(static_cast<std::size_t>(std::max(length, 1)), '\0');
    glGetProgramInfoLog(program, length, nullptr, log.data());
    log.resize(std::char_traits<char>::length(log.c_str()));
    return log;
}

struct CompiledStage {
    ShaderName shader;
    std::vector<fs::path> files;
};

Result<CompiledStage> compileStage(GLenum stage, const fs::path& file, const std::string& defines,
                                   const std::string& programLabel) {
    auto source = expandShaderSource(resolveShaderPath(file), shaderDir(), defines);
    if (!source) return Error{source.error()};
    ShaderName shader(glCreateShader(stage));
    shader.label(source->fileNames.front());
    const char* text = source->text.c_str();
    auto length = static_cast<GLint>(source->text.size());
    glShaderSource(shader.name(), 1, &text, &length);
    glCompileShader(shader.name());
    dumpShaderStage(programLabel, stage, shader.name(), *source);
    GLint ok = GL_FALSE;
    glGetShaderiv(shader.name(), GL_COMPILE_STATUS, &ok);
    if (ok != GL_TRUE) {
        return Error{cat("compile failed: ", source->fileNames.front(), "\n",
                         mapCompilerLog(shaderInfoLog(shader.name()), source->fileNames))};
    }
    return CompiledStage{std::move(shader), std::move(source->files)};
}

}  // namespace

std::string ProgramSources::name() const {
    if (!label.empty()) return label;
    std::string files;
    for (const fs::path* path : {&compute, &vertex, &fragment}) {
        if (!path->empty()) files += (files.empty() ? "" : " + ") + path->generic_string();
    }
    return files;
}

Result<Program> Program::build(const ProgramSources& sources) {
    std::vector<std::pair<GLenum, fs::path>> stages;
    if (!sources.compute.empty()) stages.emplace_back(GL_COMPUTE_SHADER, sources.compute);
    if (!sources.vertex.empty()) stages.emplace_back(GL_VERTEX_SHADER, sources.vertex);
    if (!sources.fragment.empty()) stages.emplace_back(GL_FRAGMENT_SHADER, sources.fragment);
    if (stages.empty()) return Error{"a program needs a vertex and fragment shader, or a compute shader"};

    Program program;
    program.label_ = sources.name();

    // The Shader effects chapter's lifetime pitfall, the other end: a program made before the context
    // (a global, or an object built before the window) would call GL through null function pointers.
    if (!contextAlive()) {
        return Error{
            cat("cannot build program ", program.label_,
                ": no GL context is current on this thread (create the window or headless context first)")};
    }

    std::vector<CompiledStage> compiled;
    for (auto& [stage, path] : stages) {
        auto result = compileStage(stage, path, sources.defines, program.label_);
        if (!result) return Error{result.error()};
        for (auto& f : result->files) program.files_.push_back(f);
        compiled.push_back(std::move(*result));
    }

    program.name_ = ProgramName(glCreateProgram());
    program.name_.label(program.label_);
    for (auto& stage : compiled) glAttachShader(program.name(), stage.shader.name());
    glLinkProgram(program.name());
    GLint linked = GL_FALSE;
    glGetProgramiv(program.name(), GL_LINK_STATUS, &linked);
    // Shaders are no longer needed once linked (or once linking failed).
    for (auto& stage : compiled) glDetachShader(program.name(), stage.shader.name());
    if (linked != GL_TRUE) {
        // Unlike the chapter's version, a failed program is not kept: an unusable non-zero name
        // would raise GL_INVALID_OPERATION at every draw.
        return Error{cat("link failed: ", program.label_, "\n", programInfoLog(program.name()))};
    }

    GLint count = 0;
    glGetProgramInterfaceiv(program.name(), GL_UNIFORM, GL_ACTIVE_RESOURCES, &count);
    for (GLint i = 0; i < count; ++i) {
        const GLenum properties[] = {GL_NAME_LENGTH, GL_LOCATION};
        GLint values[2] = {};
        glGetProgramResourceiv(program.name(), GL_UNIFORM, static_cast<GLuint>(i), 2, properties, 2, nullptr,
                               values);
        std::string uniform(static_cast<std::size_t>(std::max(values[0], 1)), '\0');
        glGetProgramResourceName(program.name(), GL_UNIFORM, static_cast<GLuint>(i), values[0], nullptr,
                                 uniform.data());
        uniform.resize(std::char_traits<char>::length(uniform.c_str()));
        if (values[1] >= 0) program.uniforms_[uniform] = values[1];
    }
    return program;
}

GLint Program::uniformLocation(const std::string& uniform) const {
    auto it = uniforms_.find(uniform);
    if (it != uniforms_.end()) return it->second;
    // Arrays are listed as "name[0]".
    it = uniforms_.find(uniform + "[0]");
    return it != uniforms_.end() ? it->second : -1;
}

struct ReloadableProgram::State {
    ProgramSources sources;
    Program program;
    std::string error;
    std::vector<fs::path> watched;
    std::vector<fs::file_time_type> stamps;
    int generation = 0;

    void rememberStamps(const std::vector<fs::path>& files) {
        watched = files;
        stamps.clear();
        for (auto& f : watched) {
            std::error_code ec;
            stamps.push_back(fs::last_write_time(f, ec));
        }
    }

    Status reload() {
        auto built = Program::build(sources);
        if (!built) {
            error = built.error();
            if (!program && !shaderSubstituteFiles().empty() && buildOursInstead()) {
                log::error(error, "(drawing with the lesson's own file until yours compiles)");
            } else {
                log::error(error, program ? "(keeping the last good program)" : "");
            }
            // Watch the top-level files so that a fix is picked up; includes are watched once they built.
            std::vector<fs::path> files = watched;
            for (auto* p : {&sources.vertex, &sources.fragment, &sources.compute}) {
                if (!p->empty()) files.push_back(resolveShaderPath(*p));
            }
            // A student's file (an exercise) may be what failed, before any build knew it as an include.
            for (auto& f : shaderSubstituteFiles()) files.push_back(f);
            rememberStamps(files);
            return Error{error};
        }
        program = std::move(*built);
        error.clear();
        ++generation;
        rememberStamps(program.sourceFiles());
        return Status::success();
    }

    // A student's file (an exercise) that never compiled: the program builds from our own files, the
    // last good program there is, so the lesson opens; the error stays the student's, and the first
    // save that compiles takes over.
    bool buildOursInstead() {
        ShaderSubstitutesSetAside ours;
        auto built = Program::build(sources);
        if (!built) return false;
        program = std::move(*built);
        ++generation;
        return true;
    }

    bool reloadIfChanged() {
        for (std::size_t i = 0; i < watched.size(); ++i) {
            std::error_code ec;
            auto stamp = fs::last_write_time(watched[i], ec);
            if (ec || stamp != stamps[i]) {
                (void)reload();
                return true;
            }
        }
        return false;
    }
};

namespace {

thread_local ProgramRegistry* openRegistry = nullptr;

const ReloadableProgram::State& emptyState() {
    static const ReloadableProgram::State empty;
    return empty;
}

}  // namespace

ReloadableProgram::ReloadableProgram(ProgramSources sources) : state_(std::make_shared<State>()) {
    state_->sources = std::move(sources);
    (void)state_->reload();
    if (openRegistry) openRegistry->programs_.push_back(state_);
}

Status ReloadableProgram::reload() {
    if (!state_) return Error{"reload: this program was never given its sources"};
    return state_->reload();
}

bool ReloadableProgram::reloadIfChanged() {
    return state_ && state_->reloadIfChanged();
}

const Program& ReloadableProgram::program() const {
    return (state_ ? *state_ : emptyState()).program;
}

const std::string& ReloadableProgram::error() const {
    return (state_ ? *state_ : emptyState()).error;
}

const ProgramSources& ReloadableProgram::sources() const {
    return (state_ ? *state_ : emptyState()).sources;
}

int ReloadableProgram::generation() const {
    return state_ ? state_->generation : 0;
}

ProgramRegistry::ProgramRegistry() : outer_(openRegistry) {
    openRegistry = this;
}

ProgramRegistry::~ProgramRegistry() {
    openRegistry = outer_;
}

ProgramRegistry* ProgramRegistry::open() {
    return openRegistry;
}

std::vector<std::shared_ptr<ReloadableProgram::State>> ProgramRegistry::live() const {
    std::vector<std::shared_ptr<ReloadableProgram::State>> out;
    for (const auto& weak : programs_) {
        if (auto p = weak.lock()) out.push_back(std::move(p));
    }
    return out;
}

int ProgramRegistry::reloadAll() {
    std::erase_if(programs_, [](const auto& weak) { return weak.expired(); });
    int reloaded = 0;
    for (auto& p : live()) {
        (void)p->reload();
        ++reloaded;
    }
    return reloaded;
}

int ProgramRegistry::reloadChanged() {
    std::erase_if(programs_, [](const auto& weak) { return weak.expired(); });
    int reloaded = 0;
    for (auto& p : live()) reloaded += p->reloadIfChanged() ? 1 : 0;
    return reloaded;
}

std::vector<std::string> ProgramRegistry::errors() const {
    std::vector<std::string> out;
    for (auto& p : live()) {
        if (!p->error.empty()) out.push_back(p->error);
    }
    return out;
}

std::optional<std::string> ProgramRegistry::firstUnusable() const {
    for (auto& p : live()) {
        if (!p->program) return p->error.empty() ? "a program did not build" : p->error;
    }
    return std::nullopt;
}

std::size_t ProgramRegistry::size() const {
    return live().size();
}

}  // namespace fx::gl
