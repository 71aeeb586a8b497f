// The frame graph's CPU cost per frame, with empty pass bodies and no GL: declare the passes and
// textures, compile (order, culling, lifetimes), execute through a do-nothing executor with a pool
// whose allocator hands out numbers, and build the report, as FrameRenderer does every frame. Then
// the overlay's bookkeeping of that report (the inspector's texture list, the pass table's total).
//
//   build/tools/graph_bench/fxlab-graph-bench                      (every size)
//   build/tools/graph_bench/fxlab-graph-bench --benchmark_filter=Frame/30
//
// The frame's shape: pass i creates two textures (a colour target and a helper, a second attachment
// of the same size in another format), reads the colour target of pass i-1 and the helper of pass
// i-2, so lifetimes overlap and the pool reuses textures the way a post chain does; the sizes cycle
// through 1/1 to 1/8 of the output; the last pass writes the output. 30 passes make 60 textures.
// A frame that does not compile stops the benchmark: timing the error path would measure nothing
// the lessons run.
#include <benchmark/benchmark.h>

#include <string>
#include <vector>

#include "render/frame_graph.hpp"
#include "render/texture_allocator.hpp"
#include "render/texture_pool.hpp"
#include "ui/inspector_list.hpp"
#include "ui/pass_table.hpp"

namespace {

using namespace fx;

// Hands out texture names without a GPU.
struct CountingAllocator final : TextureAllocator {
    NativeTexture next = 1;
    NativeTexture create(const TextureSpec&, std::string_view) override { return next++; }
    void destroy(NativeTexture) override {}
    void relabel(NativeTexture, std::string_view) override {}
};

// Names made once: a frame's own string building is the lesson's cost, not the graph's.
struct Names {
    std::vector<std::string> passes, colours, helpers;
    explicit Names(int n) {
        for (int i = 0; i < n; ++i) {
            passes.push_back("pass " + std::to_string(i));
            colours.push_back("chain.colour[" + std::to_string(i) + "]");
            helpers.push_back("chain.helper[" + std::to_string(i) + "]");
        }
    }
};

// The frame's report, or its error.
Result<FrameReport> runFrame(const Names& names, int passes, TexturePool& pool, PassExecutor& executor) {
    FrameGraph graph({.size = {1280, 720}});
    std::vector<TextureHandle> colour, helper;
    for (int i = 0; i < passes; ++i) {
        Pass& pass = graph.addPass(names.passes[std::size_t(i)], [](PassContext&) {});
        const int divisor = 1 << (i % 4);
        colour.push_back(pass.create(names.colours[std::size_t(i)],
                                     {TextureSize::outputFraction(1, divisor), TextureFormat::RGBA16F, 1},
                                     TextureUsage::ColorAttachment));
        helper.push_back(pass.create(names.helpers[std::size_t(i)],
                                     {TextureSize::outputFraction(1, divisor), TextureFormat::RG16F, 1},
                                     TextureUsage::ColorAttachment));
        if (i >= 1) pass.read(colour[std::size_t(i - 1)]);
        if (i >= 2) pass.read(helper[std::size_t(i - 2)]);
    }
    graph.addPass("present", [](PassContext&) {})
        .read(colour.back())
        .read(helper.back())
        .writeColor(graph.output());
    if (Status status = graph.execute(pool, executor); !status) return Error{status.error()};
    return graph.report();
}

void Frame(benchmark::State& state) {
    const int passes = int(state.range(0));
    const Names names(passes);
    CountingAllocator allocator;
    TexturePool pool(allocator);
    PassExecutor executor;  // does nothing: empty pass bodies, no GL
    for (auto _ : state) {
        Result<FrameReport> report = runFrame(names, passes, pool, executor);
        if (!report) {
            state.SkipWithError(report.error().c_str());
            break;
        }
        benchmark::DoNotOptimize(*report);
    }
    state.counters["passes"] = passes + 1;
    state.counters["textures"] = 2 * passes;
}

void FrameAndOverlayBookkeeping(benchmark::State& state) {
    const int passes = int(state.range(0));
    const Names names(passes);
    CountingAllocator allocator;
    TexturePool pool(allocator);
    PassExecutor executor;
    for (auto _ : state) {
        Result<FrameReport> report = runFrame(names, passes, pool, executor);
        if (!report) {
            state.SkipWithError(report.error().c_str());
            break;
        }
        auto entries = listTextures(*report);
        double total = totalPassMs(*report);
        benchmark::DoNotOptimize(entries);
        benchmark::DoNotOptimize(total);
    }
    state.counters["passes"] = passes + 1;
    state.counters["textures"] = 2 * passes;
}

}  // namespace

BENCHMARK(Frame)->Arg(30)->Arg(100)->Arg(1000)->Unit(benchmark::kMicrosecond);
BENCHMARK(FrameAndOverlayBookkeeping)->Arg(30)->Arg(100)->Arg(1000)->Unit(benchmark::kMicrosecond);

BENCHMARK_MAIN();
