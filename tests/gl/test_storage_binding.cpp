// The joint matrices' storage-buffer binding (Shader effects chapter, §2 and its goal 2): the C++ side's
// binding point is the one every skinning shader declares (the chapter's bpJointMatrices must equal the
// shader's binding = 0), and a storage buffer bound once belongs to the context, so every program that
// declares the block reads it without an upload of its own, unlike a uniform.
#include <array>
#include <filesystem>
#include <fstream>
#include <vector>

#include <unistd.h>
#include <glm/gtc/matrix_transform.hpp>

#include "effects/scene/joint_buffer.hpp"
#include "effects/shadow/shadow_map.hpp"
#include "gl/program.hpp"
#include "gl_test.hpp"

using namespace fx;
namespace fs = std::filesystem;

namespace {

GLint jointBlockBinding(GLuint program) {
    GLuint block = glGetProgramResourceIndex(program, GL_SHADER_STORAGE_BLOCK, "JointDataBlock");
    if (block == GL_INVALID_INDEX) return -1;
    const GLenum property = GL_BUFFER_BINDING;
    GLint binding = -1;
    glGetProgramResourceiv(program, GL_SHADER_STORAGE_BLOCK, block, 1, &property, 1, nullptr, &binding);
    return binding;
}

// A compute program that includes the shipped skinning.glsl and writes, at `slot` of the buffer at
// binding 2, the translation joint 1 gives and the joint count the bound range holds.
gl::Program jointReader(const fs::path& dir, int slot) {
    fs::path shader = dir / ("reader" + std::to_string(slot) + ".comp");
    std::ofstream(shader) << "#version 450 core\n"
                             "#include \"common/skinning.glsl\"\n"
                             "layout(local_size_x = 1) in;\n"
                             "layout(std430, binding = 2) buffer Seen { vec4 seen[]; };\n"
                             "void main() {\n"
                             "    mat4 m = skinMatrix(uvec4(1u, 0u, 0u, 0u), vec4(1.0, 0.0, 0.0, 0.0));\n"
                             "    seen["
                          << slot
                          << "] = vec4(m[3].xyz, float(jointMatrices.length()));\n"
                             "}\n";
    auto program = gl::Program::build({{}, {}, shader, {}, "test joint reader " + std::to_string(slot)});
    EXPECT_TRUE(program.ok()) << (program.ok() ? "" : program.error());
    return program.ok() ? std::move(*program) : gl::Program{};
}

}  // namespace

class StorageBinding : public GlTest {};

TEST_F(StorageBinding, EverySkinningProgramDeclaresTheJointBlockAtTheBindingTheCppSideBinds) {
    ShadowMap shadows;
    ASSERT_TRUE(programsBuilt());
    auto pose = gl::Program::build({"effects/scene/pose.vert", {}, {}, {}, "test pose"});
    ASSERT_TRUE(pose.ok()) << pose.error();
    const std::array<std::pair<const char*, GLuint>, 3> programs = {{
        {"skinned shadow, T*(J*p)", shadows.skinnedProgram(SkinningProduct::parenthesised).name()},
        {"skinned shadow, (T*J)*p", shadows.skinnedProgram(SkinningProduct::grouped).name()},
        {"pose (transform feedback)", pose->name()},
    }};
    for (const auto& [what, program] : programs) {
        EXPECT_EQ(jointBlockBinding(program), GLint(glsl::kJointMatricesBinding)) << what;
    }
}

TEST_F(StorageBinding, ABufferBoundOnceIsReadByEveryProgramThatDeclaresTheBlock) {
    fs::path dir = fs::temp_directory_path() / ("fx_storage_binding_" + std::to_string(::getpid()));
    fs::create_directories(dir);
    gl::Program first = jointReader(dir, 0), second = jointReader(dir, 1);
    fs::remove_all(dir);
    ASSERT_TRUE(first && second);

    JointMatrixBuffer joints("test joints");
    const std::vector<glm::mat4> matrices = {glm::mat4(1.0f), glm::translate(glm::mat4(1.0f), {1, 2, 3})};
    joints.upload(matrices);
    joints.bind();  // once, before either program is in use
    gl::BufferName seen = gl::createBuffer("test joints seen");
    const std::vector<glm::vec4> zeros(2, glm::vec4(-1.0f));
    glNamedBufferStorage(seen.name(), GLsizeiptr(zeros.size() * sizeof(glm::vec4)), zeros.data(), 0);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 2, seen.name());
    for (const gl::Program* program : {&first, &second}) {
        glUseProgram(program->name());
        glDispatchCompute(1, 1, 1);
    }
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    std::vector<glm::vec4> back(2);
    glGetNamedBufferSubData(seen.name(), 0, GLsizeiptr(back.size() * sizeof(glm::vec4)), back.data());
    glUseProgram(0);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 2, 0);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, glsl::kJointMatricesBinding, 0);
    for (int i = 0; i < 2; ++i) {
        EXPECT_EQ(back[std::size_t(i)], glm::vec4(1, 2, 3, 2))
            << "program " << i << ": joint 1's translation and the joint count";
    }
}
