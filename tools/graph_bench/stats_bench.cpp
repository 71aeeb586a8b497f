// The inspector's statistics of a 1920x1080 RGBA16F texture, the way it worked before (the whole
// level read back as floats and counted on the CPU: analyseImage) and on the GPU (a compute reduction,
// a few hundred bytes read back: ui/gpu_texture_stats.hpp). Runs in a headless EGL context.
//
//   build/tools/graph_bench/fxlab-stats-bench
#include <benchmark/benchmark.h>

#include <cstdio>
#include <memory>
#include <vector>

#include "gl/readback.hpp"
#include "gl/texture.hpp"
#include "platform/context.hpp"
#include "ui/gpu_texture_stats.hpp"

namespace {

using namespace fx;

const TextureSpec kSpec{1920, 1080, TextureFormat::RGBA16F, 1};

gl::Texture makeTexture() {
    gl::Texture t = gl::Texture::create2D(kSpec.format, kSpec.width, kSpec.height, 1, "bench.hdr");
    std::vector<float> v;
    v.reserve(std::size_t(kSpec.width) * kSpec.height * 4);
    for (unsigned y = 0; y < unsigned(kSpec.height); ++y)
        for (unsigned x = 0; x < unsigned(kSpec.width); ++x) {
            unsigned h = x * 73856093u ^ y * 19349663u;
            for (unsigned c = 0; c < 4; ++c) v.push_back(float((h >> (c * 7)) % 1000) / 100.0f);
        }
    glTextureSubImage2D(t.name(), 0, 0, 0, kSpec.width, kSpec.height, GL_RGBA, GL_FLOAT, v.data());
    glFinish();
    return t;
}

void ReadBackAndCountOnTheCpu(benchmark::State& state) {
    gl::Texture t = makeTexture();
    for (auto _ : state) {
        TextureAnalysis a = analyseImage(gl::readTexture(t.name(), kSpec, 0), false, 0.1f, 100.0f);
        benchmark::DoNotOptimize(a);
    }
}

void CountOnTheGpu(benchmark::State& state) {
    gl::Texture t = makeTexture();
    GpuTextureStats stats = GpuTextureStats::create();
    if (!stats.usable()) {
        state.SkipWithError("the statistics program did not build");
        return;
    }
    for (auto _ : state) {
        auto a = stats.analyse(t.name(), kSpec, 0, false, 0.1f, 100.0f);
        benchmark::DoNotOptimize(a);
    }
}

}  // namespace

BENCHMARK(ReadBackAndCountOnTheCpu)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(CountOnTheGpu)->Unit(benchmark::kMillisecond)->UseRealTime();

int main(int argc, char** argv) {
    benchmark::Initialize(&argc, argv);
    ContextOptions options;
    options.size = {64, 64};
    options.debugContext = false;
    auto context = createHeadlessContext(options);
    if (!context) {
        std::fprintf(stderr, "%s\n", context.error().c_str());
        return 1;
    }
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    return 0;
}
