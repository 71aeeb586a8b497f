// The shaders' sRGB encoding (shaders/common/srgb.glsl): a square-root fit instead of pow(), because
// llvmpipe builds pow() from two polynomials per channel. Read back as floats on the GPU, across the
// whole of [0, 1]: it stays within 5e-5 of the exact curve (1/80 of an 8-bit step), never falls as the
// light rises, and meets the linear toe and the white point.
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <vector>

#include <unistd.h>

#include "gl/object.hpp"
#include "gl/program.hpp"
#include "gl_test.hpp"

using namespace fx;
namespace fs = std::filesystem;

namespace {

double exactSrgb(double c) {
    return c <= 0.0031308 ? 12.92 * c : 1.055 * std::pow(c, 1.0 / 2.4) - 0.055;
}

class SrgbEncoding : public GlTest {
protected:
    fs::path dir;
    void SetUp() override {
        GlTest::SetUp();
        dir = fs::temp_directory_path() / ("fx_srgb_" + std::to_string(::getpid()));
        fs::create_directories(dir);
    }
    void TearDown() override {
        fs::remove_all(dir);
        GlTest::TearDown();
    }

    // Runs srgbEncode on every value of `input` (a compute shader that includes the shipped file).
    std::vector<float> encode(const std::vector<float>& input) {
        fs::path shader = dir / "encode.comp";
        std::ofstream(shader) << "#version 450 core\n"
                                 "#include \"common/srgb.glsl\"\n"
                                 "layout(local_size_x = 64) in;\n"
                                 "layout(std430, binding = 0) buffer Values { float v[]; };\n"
                                 "layout(location = 0) uniform uint count;\n"
                                 "void main() {\n"
                                 "    uint i = gl_GlobalInvocationID.x;\n"
                                 "    if (i < count) v[i] = srgbEncode(vec3(v[i])).g;\n"
                                 "}\n";
        auto program = gl::Program::build({{}, {}, shader, {}, "test sRGB encoding"});
        if (!program.ok()) {
            ADD_FAILURE() << program.error();
            return {};
        }
        gl::BufferName buffer = gl::createBuffer("test sRGB values");
        const auto bytes = GLsizeiptr(input.size() * sizeof(float));
        glNamedBufferStorage(buffer.name(), bytes, input.data(), GL_DYNAMIC_STORAGE_BIT);
        glUseProgram(program->name());
        glProgramUniform1ui(program->name(), 0, GLuint(input.size()));
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, buffer.name());
        glDispatchCompute(GLuint((input.size() + 63) / 64), 1, 1);
        glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
        std::vector<float> out(input.size());
        glGetNamedBufferSubData(buffer.name(), 0, bytes, out.data());
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, 0);
        glUseProgram(0);
        return out;
    }
};

}  // namespace

TEST_F(SrgbEncoding, StaysWithinOneEightiethOfAnEightBitStepOfTheExactCurveAndNeverFalls) {
    // Every step of 1/65536 across [0, 1], and the points either side of the toe's end.
    std::vector<float> input;
    for (int i = 0; i <= 65536; ++i) input.push_back(float(i) / 65536.0f);
    for (float c : {0.0031307f, 0.0031308f, 0.0031309f}) input.push_back(c);
    std::vector<float> out = encode(input);
    ASSERT_EQ(out.size(), input.size());
    ASSERT_EQ(glGetError(), GLenum(GL_NO_ERROR));

    double worst = 0, worstAt = 0;
    int falls = 0;
    for (std::size_t i = 0; i < input.size(); ++i) {
        double error = std::abs(double(out[i]) - exactSrgb(input[i]));
        if (error > worst) worst = error, worstAt = input[i];
        if (i > 0 && i <= 65536 && out[i] < out[i - 1]) ++falls;
    }
    std::printf("largest error %.3g at %.6f (%.4f of an 8-bit step)\n", worst, worstAt, worst * 255.0);
    EXPECT_LT(worst, 5e-5) << "at linear " << worstAt;
    EXPECT_EQ(falls, 0) << "the encoding must not fall as the light rises";
    EXPECT_EQ(out[0], 0.0f);              // black stays black
    EXPECT_LE(out[65536], 1.0f);          // white does not overshoot...
    EXPECT_GT(out[65536], 1.0f - 5e-5f);  // ...nor fall short
    // The toe joins the curve without a visible step: both sides within the bound of each other.
    EXPECT_NEAR(out[65537 + 1], out[65537], 1e-4f);
    EXPECT_NEAR(out[65537 + 2], out[65537 + 1], 1e-4f);
}
