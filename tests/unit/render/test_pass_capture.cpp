// A pass body runs after the function that declared it has returned. These tests declare passes in
// a function of their own, as a lesson's buildFrame does, and run the graph after it returned.
#include <gtest/gtest.h>

#include "fake_gpu.hpp"
#include "render/frame_graph.hpp"

#if defined(__SANITIZE_ADDRESS__)
#define FX_ASAN 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define FX_ASAN 1
#endif
#endif

namespace fx {
namespace {

const TextureDesc kColor{TextureSize::output(), TextureFormat::RGBA16F};

// The mistake: `color` is this function's local, and the body keeps a reference to it.
[[maybe_unused, gnu::noinline]] void declareCapturingByReference(FrameGraph& graph) {
    TextureHandle color = graph.declareTexture("leak.color", kColor);
    graph.addPass("leaky", [&](PassContext& ctx) { (void)ctx.native(color); }).writeColor(color);
    graph.addPass("present").read(color).writeColor(graph.output());
}

// The fix: the body keeps its own copy of the handle.
[[gnu::noinline]] void declareCapturingByCopy(FrameGraph& graph, NativeTexture& seen) {
    TextureHandle color = graph.declareTexture("copy.color", kColor);
    graph.addPass("copying", [color, &seen](PassContext& ctx) { seen = ctx.native(color); })
        .writeColor(color);
    graph.addPass("present").read(color).writeColor(graph.output());
}

// Unused under AddressSanitizer, whose builds skip the tests that call these.
[[maybe_unused]] void runAfterDeclaring(void (*declare)(FrameGraph&)) {
    test::FakeAllocator allocator;
    TexturePool pool(allocator);
    test::RecordingExecutor executor;
    FrameGraph graph({.size = {64, 32}});
    declare(graph);
    (void)graph.execute(pool, executor);
}

TEST(PassCapture, AHandleCapturedByReferenceStopsTheProgramNamingThePass) {
#ifdef FX_ASAN
    GTEST_SKIP() << "AddressSanitizer reports this as stack-use-after-return itself";
#else
    GTEST_FLAG_SET(death_test_style, "threadsafe");
    EXPECT_DEATH(runAfterDeclaring(declareCapturingByReference),
                 "pass 'leaky' read a texture handle from a stack frame that has returned.*\\[&\\]");
#endif
}

TEST(PassCapture, AHandleCapturedByCopyReachesTheBody) {
    test::FakeAllocator allocator;
    TexturePool pool(allocator);
    test::RecordingExecutor executor;
    FrameGraph graph({.size = {64, 32}});
    NativeTexture seen = 0;
    declareCapturingByCopy(graph, seen);
    ASSERT_TRUE(graph.execute(pool, executor).ok());
    ASSERT_EQ(allocator.created.size(), 1u);
    EXPECT_EQ(seen, allocator.created[0].texture);
}

// What execute() relies on: after a function returns, the poison reaches the locals it had.
[[maybe_unused, gnu::noinline]] const volatile std::uint32_t* addressOfALocal() {
    volatile std::uint32_t local = 7;
    const volatile std::uint32_t* address = &local;
    asm volatile("" : "+r"(address) : : "memory");  // the address escapes: the store stays
    return address;
}

TEST(PassCapture, PoisonReachesTheLocalsOfAFunctionThatReturned) {
#ifdef FX_ASAN
    GTEST_SKIP() << "AddressSanitizer moves locals off the stack";
#else
    const volatile std::uint32_t* dangling = addressOfALocal();
    poisonDeadStack();
    const std::uint32_t value = *dangling;  // read before any other call reuses the stack
    EXPECT_EQ(value, kDeadStackWord);
#endif
}

}  // namespace
}  // namespace fx
