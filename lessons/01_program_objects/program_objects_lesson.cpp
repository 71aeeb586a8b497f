// Lesson 01: program objects (the Shader effects chapter, §1 and its learning goals).
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <memory>
#include <optional>

#include <imgui.h>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "app/lesson.hpp"
#include "app/runner.hpp"
#include "base/log.hpp"
#include "effects/post/copy_pass.hpp"
#include "effects/scene/camera_matrices.hpp"
#include "effects/scene/gpu_mesh.hpp"
#include "effects/scene/hdr_scene_pass.hpp"
#include "effects/scene/scene_meshes.hpp"
#include "effects/shadow/shadow_map.hpp"
#include "gl/debug_output.hpp"
#include "gl/program.hpp"
#include "raw_programs.hpp"

namespace fx::glsl {
#include "shaders/lessons/01_program_objects/skinning_bindings.glsl"
}  // namespace fx::glsl

namespace lesson01 {

using namespace fx;

class ProgramObjectsLesson final : public Lesson {
public:
    std::vector<std::string> steps() const override;
    void declareParams(ParamSet& params) override;
    Status init(const Scene& scene) override;
    void buildFrame(FrameGraph& graph, const FrameInfo& frame) override;
    void drawPanel(const FrameInfo& frame) override;
    int benchStep() const override { return Parentheses; }
    void facts(Facts& out, const FrameInfo& frame) const override;

    enum Step { CopyPasted, CheckedPrograms, CachedLocations, Parentheses, LiveReload };
    enum Broken { NotBroken, SyntaxError, UndeclaredName, LinkError };

private:
    // Parameters.
    // Steps 1 and 2 start with the chapter's typo in the normals program: step 1 shows what it does
    // unchecked, step 2 the check that catches it. "none" shows both steps working.
    Choice<Broken> broken_{SyntaxError};
    bool lookupEveryDraw_ = false;
    int gridSize_ = 20;
    int productOrder_ = 1;  // 0: (T*J)*p, 1: T*(J*p)
    int meshDetail_ = 128;  // sphere segments for step 4
    int spheres_ = 16;      // instances for step 4

    Gpu<GpuMesh> gridBox_{makeBox({0.18f, 0.18f, 0.18f}), "grid box"};
    GpuMesh denseSphere_;
    int denseSphereDetail_ = 0;

    // Step 1: raw names, built without checks (again whenever broken_shader changes).
    gl::ProgramName rawLit_, rawUnlit_, rawNormals_;
    int rawBuiltWith_ = -1;
    std::int64_t rawErrorsLastFrame_ = 0;  // GL errors step 1's draws raised (none checks them)
    // Steps 2 to 5: checked, reloadable program objects.
    gl::ReloadableProgram lit_, unlit_, normals_;
    // Step 2: the normals program rebuilt from the broken file, checked; only while step 2 shows it.
    gl::ReloadableProgram brokenAttempt_;
    int brokenBuilt_ = -1;  // the broken_shader it was built for (-1: none built)
    gl::ReloadableProgram skinGrouped_, skinParenthesised_;
    Gpu<CopyPass> present_{"copy"};

    // Step 3's measurements (CPU side, per frame).
    int lookupsLastFrame_ = 0;
    double lookupMsLastFrame_ = 0;
    // Step 4's two skinning passes, timed side by side.
    PassGroup groupedPass_, parenthesisedPass_;

    void drawScene(GLuint program, const FrameInfo& frame) const;
    // The chapter's picture of several programs: the box unlit, the sphere in the normals program,
    // the rest lit.
    void drawThreePrograms(GLuint lit, GLuint unlit, GLuint normals, const FrameInfo& frame) const;
    void updateRawPrograms();
    void drawGrid(GLuint program, const FrameInfo& frame);
    void buildSkinningComparison(FrameGraph& graph, const FrameInfo& frame);
    void updateBrokenAttempt(int step);
};

namespace {

const char* kDir = "lessons/01_program_objects/";
std::string shader(const char* name) {
    return std::string(kDir) + name;
}

// The chapter's operation counts per vertex (section 2.2), the ones lesson 02 shows.
const OperationCount kGrouped = operationCount(SkinningProduct::grouped);              // (T*J)*p
const OperationCount kParenthesised = operationCount(SkinningProduct::parenthesised);  // T*(J*p)

}  // namespace

std::vector<std::string> ProgramObjectsLesson::steps() const {
    return {
        "Copy-pasted programs",           "A program object with error checks",
        "Look uniform locations up once", "Parentheses in the skinning product",
        "Reload while running",
    };
}

void ProgramObjectsLesson::declareParams(ParamSet& params) {
    // Each parameter is listed in the steps it acts in.
    params.addChoice("broken_shader", &broken_, {"none", "syntax_error", "undeclared_name", "link_error"})
        .inSteps({CopyPasted, CheckedPrograms});
    params.addBool("lookup_every_draw", &lookupEveryDraw_).inSteps({CachedLocations});
    params.addInt("grid_size", &gridSize_, 1, 64).inSteps({CachedLocations});
    Param& order =
        params.addChoice("product_order", &productOrder_, {"(T*J)*p", "T*(J*p)"}).inSteps({Parentheses});
    order.knob = Knob{{0, 1}, 1, "order"};
    params.addInt("spheres", &spheres_, 1, 256).inSteps({Parentheses});
    Param& detail = params.addInt("mesh_detail", &meshDetail_, 8, 512).inSteps({Parentheses});
    detail.knob = Knob{{16, 32, 64, 128, 256}, 256, "segments"};
}

Status ProgramObjectsLesson::init(const Scene&) {
    lit_ = gl::ReloadableProgram({shader("lit.vert"), shader("lit.frag"), {}, {}, "lit"});
    unlit_ = gl::ReloadableProgram({shader("lit.vert"), shader("unlit.frag"), {}, {}, "unlit"});
    normals_ = gl::ReloadableProgram({shader("lit.vert"), shader("normals.frag"), {}, {}, "normals"});
    skinGrouped_ =
        gl::ReloadableProgram({shader("skinning.vert"), shader("lit.frag"), {}, {}, "skinning (T*J)*p"});
    skinParenthesised_ = gl::ReloadableProgram(
        {shader("skinning.vert"), shader("lit.frag"), {}, "#define PARENTHESISED 1", "skinning T*(J*p)"});
    return Status::success();
}

namespace {

// The deliberately broken fragment shaders, by Broken value (shaders/lessons/01_program_objects/).
const char* brokenFile(ProgramObjectsLesson::Broken broken) {
    switch (broken) {
        case ProgramObjectsLesson::SyntaxError:
            return "broken_syntax.frag";
        case ProgramObjectsLesson::UndeclaredName:
            return "broken_undeclared.frag";
        case ProgramObjectsLesson::LinkError:
            return "broken_link.frag";
        case ProgramObjectsLesson::NotBroken:
            break;
    }
    return "normals.frag";
}

// The objects drawn with a program of their own (scenes/01_program_objects.json).
constexpr const char* kUnlitObject = "box";
constexpr const char* kNormalsObject = "sphere";

}  // namespace

void ProgramObjectsLesson::updateRawPrograms() {
    if (rawBuiltWith_ == *broken_) return;
    rawBuiltWith_ = *broken_;
    // The typo lands in the normals program, as a typo lands in one file: nothing here looks at the
    // compile or link status, so the program is kept, unusable, and used.
    rawLit_ = buildProgramWithoutChecks(shader("lit.vert"), shader("lit.frag"), "raw lit");
    rawUnlit_ = buildProgramWithoutChecks(shader("lit.vert"), shader("unlit.frag"), "raw unlit");
    rawNormals_ = buildProgramWithoutChecks(shader("lit.vert"), shader(brokenFile(*broken_)), "raw normals");
}

void ProgramObjectsLesson::updateBrokenAttempt(int step) {
    // Only step 2 keeps the failed build: every program built joins the run's registry, whose errors
    // the overlay shows in red, and F5 rebuilds; in the other steps nothing is broken on purpose.
    const int wanted = step == CheckedPrograms && *broken_ != NotBroken ? int(*broken_) : -1;
    if (brokenBuilt_ == wanted) return;
    brokenBuilt_ = wanted;
    if (wanted < 0) {
        brokenAttempt_ = {};
        return;
    }
    // The checked build fails and says why; the sphere keeps drawing with the good normals program.
    brokenAttempt_ = gl::ReloadableProgram({shader("lit.vert"),
                                            shader(brokenFile(*broken_)),
                                            {},
                                            {},
                                            cat("normals (", brokenFile(*broken_), ")")});
}

void ProgramObjectsLesson::drawThreePrograms(GLuint lit, GLuint unlit, GLuint normals,
                                             const FrameInfo& frame) const {
    CameraMatrices camera = cameraMatrices(frame.world.scene().camera, frame.size.width, frame.size.height);
    for (GLuint p : {lit, unlit, normals}) SceneMeshes::setFrameUniforms(p, frame.world.scene(), camera);
    auto named = [](const char* name) { return [name](const SceneObject& o) { return o.name == name; }; };
    MeshDrawOptions rest;
    rest.only = [](const SceneObject& o) { return o.name != kUnlitObject && o.name != kNormalsObject; };
    frame.world.draw(lit, rest);
    MeshDrawOptions box;
    box.only = named(kUnlitObject);
    frame.world.draw(unlit, box);
    // glUseProgram with a program that did not link fails and leaves the program bound before it in
    // use: what the object looks like then depends on what ran last (the chapter's engine drew it
    // black). Unbinding first makes it the same every frame: no program, nothing drawn.
    glUseProgram(0);
    MeshDrawOptions sphere;
    sphere.only = named(kNormalsObject);
    frame.world.draw(normals, sphere);
}

void ProgramObjectsLesson::drawScene(GLuint program, const FrameInfo& frame) const {
    CameraMatrices camera = cameraMatrices(frame.world.scene().camera, frame.size.width, frame.size.height);
    SceneMeshes::setFrameUniforms(program, frame.world.scene(), camera);
    frame.world.draw(program);
}

void ProgramObjectsLesson::drawGrid(GLuint program, const FrameInfo& frame) {
    CameraMatrices camera = cameraMatrices(frame.world.scene().camera, frame.size.width, frame.size.height);
    SceneMeshes::setFrameUniforms(program, frame.world.scene(), camera);
    glUseProgram(program);
    int n = gridSize_;
    lookupsLastFrame_ = 0;
    double lookupSeconds = 0;
    for (int z = 0; z < n; ++z) {
        for (int x = 0; x < n; ++x) {
            GLint modelLocation = glsl::kModelLocation;
            GLint colorLocation = glsl::kBaseColorLocation;
            if (lookupEveryDraw_) {
                // What the chapter warns against: a string comparison per uniform per draw.
                auto start = std::chrono::steady_clock::now();
                modelLocation = glGetUniformLocation(program, "modelMatrix");
                colorLocation = glGetUniformLocation(program, "baseColor");
                lookupSeconds +=
                    std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
                lookupsLastFrame_ += 2;
            }
            float fx_ = (float(x) + 0.5f) / float(n) - 0.5f, fz = (float(z) + 0.5f) / float(n) - 0.5f;
            glm::mat4 model = glm::translate(glm::mat4(1.0f), glm::vec3(fx_ * 6.0f, 0.15f, fz * 6.0f));
            glm::vec3 color(0.3f + 0.7f * (fx_ + 0.5f), 0.4f, 0.3f + 0.7f * (fz + 0.5f));
            glProgramUniformMatrix4fv(program, modelLocation, 1, GL_FALSE, glm::value_ptr(model));
            glProgramUniform3fv(program, colorLocation, 1, glm::value_ptr(color));
            glProgramUniform3f(program, glsl::kEmissiveLocation, 0, 0, 0);
            gridBox_->draw();
        }
    }
    lookupMsLastFrame_ = lookupSeconds * 1000.0;
}

void ProgramObjectsLesson::buildSkinningComparison(FrameGraph& graph, const FrameInfo& frame) {
    if (denseSphereDetail_ != meshDetail_) {
        denseSphere_ = GpuMesh(makeSphere(1.2f, meshDetail_, meshDetail_ / 2), "dense sphere");
        denseSphereDetail_ = meshDetail_;
    }
    TextureDesc colorDesc{TextureSize::output(), TextureFormat::RGBA8, 1};
    TextureDesc depthDesc{TextureSize::output(), TextureFormat::Depth32F, 1};
    auto drawSphere = [this, frame](GLuint program) {
        CameraMatrices camera =
            cameraMatrices(frame.world.scene().camera, frame.size.width, frame.size.height);
        SceneMeshes::setFrameUniforms(program, frame.world.scene(), camera);
        // Four joints swaying with time (wrapped, so the angle stays small after hours).
        float phase = float(std::fmod(frame.seconds, 4.0) / 4.0 * 6.2831853);
        glm::mat4 joints[4];
        for (int j = 0; j < 4; ++j) {
            joints[j] = glm::rotate(glm::mat4(1.0f), 0.3f * std::sin(phase + float(j)),
                                    glm::vec3(0, 1, 0.3f * float(j)));
        }
        glProgramUniformMatrix4fv(program, glsl::kJointsLocation, 4, GL_FALSE, glm::value_ptr(joints[0]));
        int row = std::max(1, int(std::lround(std::sqrt(double(spheres_)))));
        float scale = 1.0f / float(row);
        glm::mat4 model =
            glm::scale(glm::translate(glm::mat4(1.0f), glm::vec3(0, 1.3f, 0)), glm::vec3(scale));
        glProgramUniform1i(program, glsl::kSpheresPerRowLocation, row);
        glProgramUniformMatrix4fv(program, glsl::kModelLocation, 1, GL_FALSE, glm::value_ptr(model));
        glProgramUniform3f(program, glsl::kBaseColorLocation, 0.8f, 0.55f, 0.3f);
        glProgramUniform3f(program, glsl::kEmissiveLocation, 0, 0, 0);
        glUseProgram(program);
        denseSphere_.draw(row * row);
    };
    // The opaque scene's state, on a near-black background of its own so the two products stand out.
    PassState sceneState = hdrSceneState(frame.world.scene());
    sceneState.clearColor = ClearColor{0.02f, 0.02f, 0.03f, 1.0f};
    TextureHandle grouped[2], parenthesised[2];
    auto& a = graph
                  .addPass("skinning (T*J)*p",
                           [this, drawSphere](PassContext&) { drawSphere(skinGrouped_.name()); })
                  .joinGroup(groupedPass_);
    grouped[0] = a.create("skinning.grouped.color", colorDesc, TextureUsage::ColorAttachment);
    grouped[1] = a.create("skinning.grouped.depth", depthDesc, TextureUsage::DepthAttachment);
    a.setState(sceneState).setTaps(0);  // this lesson's shaders sample no texture
    auto& b = graph
                  .addPass("skinning T*(J*p)",
                           [this, drawSphere](PassContext&) { drawSphere(skinParenthesised_.name()); })
                  .joinGroup(parenthesisedPass_);
    parenthesised[0] = b.create("skinning.parenthesised.color", colorDesc, TextureUsage::ColorAttachment);
    parenthesised[1] = b.create("skinning.parenthesised.depth", depthDesc, TextureUsage::DepthAttachment);
    b.setState(sceneState).setTaps(0);
    // Both products run every frame so their times stand side by side; the knob picks which is shown.
    // A bench frame keeps only the shown one: the graph culls the other.
    if (!frame.benchmark) {
        graph.inspect("skinning.grouped.color");
        graph.inspect("skinning.parenthesised.color");
    }
    TextureHandle shown = productOrder_ == 0 ? grouped[0] : parenthesised[0];
    present_->declare(graph, "present", shown);
}

void ProgramObjectsLesson::buildFrame(FrameGraph& graph, const FrameInfo& frame) {
    updateBrokenAttempt(frame.step);
    if (frame.step == Parentheses) {
        buildSkinningComparison(graph, frame);
        return;
    }
    if (frame.step == CopyPasted) updateRawPrograms();
    PassState sceneState = hdrSceneState(frame.world.scene());
    graph
        .addPass(
            "scene",
            [this, frame](PassContext&) {
                switch (frame.step) {
                    case CopyPasted: {
                        // A broken program raises GL_INVALID_OPERATION at every use, and nothing in
                        // step 1 asks: the debug output counts them as expected here.
                        std::optional<gl::ExpectedErrorScope> expected;
                        if (*broken_ != NotBroken) expected.emplace("lesson 01 step 1: an unchecked program");
                        std::int64_t before = gl::debugCounters().errors + gl::debugCounters().expectedErrors;
                        drawThreePrograms(rawLit_.name(), rawUnlit_.name(), rawNormals_.name(), frame);
                        rawErrorsLastFrame_ =
                            gl::debugCounters().errors + gl::debugCounters().expectedErrors - before;
                        break;
                    }
                    case CheckedPrograms: {
                        // The failed build is refused; the last good normals program draws.
                        GLuint normals = brokenAttempt_.usable() ? brokenAttempt_.name() : normals_.name();
                        drawThreePrograms(lit_.name(), unlit_.name(), normals, frame);
                        break;
                    }
                    case CachedLocations:
                        drawGrid(lit_.name(), frame);
                        break;
                    default:
                        drawScene(lit_.name(), frame);
                        break;
                }
            })
        .writeColor(graph.output())
        .setState(sceneState)
        .setTaps(0);
}

void ProgramObjectsLesson::drawPanel(const FrameInfo& frame) {
    switch (frame.step) {
        case CopyPasted:
            ImGui::TextWrapped("%s", fx::say("text.rawNames", {{"lit", fx::cat(rawLit_.name())},
                                                               {"unlit", fx::cat(rawUnlit_.name())},
                                                               {"normals", fx::cat(rawNormals_.name())}})
                                         .c_str());
            if (*broken_ != NotBroken) {
                ImGui::TextWrapped("%s",
                                   fx::say("text.uncheckedBroken",
                                           {{"file", brokenFile(*broken_)},
                                            {"errors", fx::cat(static_cast<long long>(rawErrorsLastFrame_))}})
                                       .c_str());
            }
            break;
        case CheckedPrograms:
            if (*broken_ == NotBroken) {
                ImGui::TextWrapped("%s", fx::say("text.chooseBroken").c_str());
            } else {
                ImGui::TextWrapped("%s", fx::say("text.checkRefused").c_str());
                ImGui::TextColored(ImVec4(1, 0.4f, 0.4f, 1), "%s", brokenAttempt_.error().c_str());
            }
            break;
        case LiveReload:
            ImGui::TextUnformatted(fx::say("text.litBuild", {{"build", fx::cat(lit_.generation())}}).c_str());
            for (auto& f : lit_.program().sourceFiles())
                ImGui::BulletText("%s", f.filename().string().c_str());
            if (!lit_.error().empty())
                ImGui::TextColored(ImVec4(1, 0.4f, 0.4f, 1), "%s", lit_.error().c_str());
            break;
        default:
            break;
    }
}

void ProgramObjectsLesson::facts(Facts& out, const FrameInfo& frame) const {
    // Every fact goes in the report; the panel shows those of the step on screen.
    auto fact = [&](bool shown, std::string name, std::string value, const WordArgs& args = {}) {
        if (shown)
            out.add(std::move(name), std::move(value), args);
        else
            out.check(std::move(name), std::move(value));
    };
    const bool lookups = frame.step == CachedLocations, products = frame.step == Parentheses;
    fact(lookups, "uniformLookupsLastFrame", std::to_string(lookupsLastFrame_),
         {{"draws", cat(gridSize_ * gridSize_)}});
    fact(lookups, "uniformLookupMs", std::to_string(lookupMsLastFrame_));
    out.check("brokenShaderLog", brokenAttempt_.error());  // the panel shows it in colour
    // Step 1 with a broken shader exists to show GL errors (counted as expected); the smoke test
    // checks that it does, and that no other step raises any.
    out.check("expectErrorsInStep", frame.step == CopyPasted && *broken_ != NotBroken);
    fact(frame.step == CopyPasted, "uncheckedProgramGlErrorsLastFrame", std::to_string(rawErrorsLastFrame_));
    fact(products, "denseSphereVertices", std::to_string(denseSphere_.vertexCount()));
    fact(products, "spheres", std::to_string(spheres_));
    fact(products, "opsGroupedPerVertex", std::to_string(kGrouped.mul + kGrouped.add),
         {{"mul", cat(kGrouped.mul)}, {"add", cat(kGrouped.add)}});
    fact(products, "opsParenthesisedPerVertex", std::to_string(kParenthesised.mul + kParenthesised.add),
         {{"mul", cat(kParenthesised.mul)}, {"add", cat(kParenthesised.add)}});
    if (products && frame.previousFrame) {
        out.add("groupedMs", cat(groupedPass_.timeMs(*frame.previousFrame)));
        out.add("parenthesisedMs", cat(parenthesisedPass_.timeMs(*frame.previousFrame)));
    }
}

}  // namespace lesson01

FX_LESSON(lesson01::ProgramObjectsLesson, "Program objects", "scenes/01_program_objects.json")
