#pragma once
// Lesson 01: program objects (the Shader effects chapter, §1 and its learning goals).
#include <cstdint>
#include <memory>

#include "app/lesson.hpp"
#include "effects/post/fullscreen_pass.hpp"
#include "effects/scene/gpu_mesh.hpp"
#include "effects/scene/scene_meshes.hpp"
#include "gl/program.hpp"

namespace lesson01 {

class ProgramObjectsLesson final : public fx::Lesson {
public:
    fx::LessonInfo info() const override;
    std::vector<std::string> steps() const override;
    void declareParams(fx::ParamSet& params) override;
    fx::Status init(const fx::Scene& scene) override;
    void buildFrame(fx::FrameGraph& graph, const fx::FrameInfo& frame) override;
    void drawPanel(const fx::FrameInfo& frame) override;
    int benchStep() const override { return Parentheses; }
    void facts(fx::Facts& out, const fx::FrameInfo& frame) const override;

    enum Step { CopyPasted, CheckedPrograms, CachedLocations, Parentheses, LiveReload };
    enum Broken { NotBroken, SyntaxError, UndeclaredName, LinkError };

private:
    // Parameters.
    // Steps 1 and 2 start with the chapter's typo in the normals program: step 1 shows what it does
    // unchecked, step 2 the check that catches it. "none" shows both steps working.
    int broken_ = SyntaxError;
    bool lookupEveryDraw_ = false;
    int gridSize_ = 20;
    int productOrder_ = 1;  // 0: (T*J)*p, 1: T*(J*p)
    int meshDetail_ = 128;  // sphere segments for step 4
    int spheres_ = 16;      // instances for step 4

    fx::Gpu<fx::GpuMesh> gridBox_{fx::makeBox({0.18f, 0.18f, 0.18f}), "grid box"};
    fx::GpuMesh denseSphere_;
    int denseSphereDetail_ = 0;

    // Step 1: raw names, built without checks (again whenever broken_shader changes).
    fx::gl::ProgramName rawLit_, rawUnlit_, rawNormals_;
    int rawBuiltWith_ = -1;
    std::int64_t rawErrorsLastFrame_ = 0;  // GL errors step 1's draws raised (none checks them)
    // Steps 2 to 5: checked, reloadable program objects.
    fx::gl::ReloadableProgram lit_, unlit_, normals_;
    // Step 2: the normals program rebuilt from the broken file, checked; only while step 2 shows it.
    fx::gl::ReloadableProgram brokenAttempt_;
    int brokenBuilt_ = -1;  // the broken_shader it was built for (-1: none built)
    fx::gl::ReloadableProgram skinGrouped_, skinParenthesised_;
    fx::Gpu<fx::FullscreenPass> present_{"common/copy.frag", "copy"};

    // Step 3's measurements (CPU side, per frame).
    int lookupsLastFrame_ = 0;
    double lookupMsLastFrame_ = 0;
    // Step 4's two skinning passes, timed side by side.
    fx::PassGroup groupedPass_, parenthesisedPass_;

    void drawScene(GLuint program, const fx::FrameInfo& frame) const;
    // The chapter's picture of several programs: the box unlit, the sphere in the normals program,
    // the rest lit.
    void drawThreePrograms(GLuint lit, GLuint unlit, GLuint normals, const fx::FrameInfo& frame) const;
    void updateRawPrograms();
    void drawGrid(GLuint program, const fx::FrameInfo& frame);
    void buildSkinningComparison(fx::FrameGraph& graph, const fx::FrameInfo& frame);
    void updateBrokenAttempt(int step);
};

}  // namespace lesson01
