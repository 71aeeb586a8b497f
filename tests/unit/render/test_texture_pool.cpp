#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "fake_gpu.hpp"
#include "render/texture_pool.hpp"

namespace fx {
namespace {

using test::FakeAllocator;

const TextureSpec kHdr{1280, 720, TextureFormat::RGBA16F, 1};
const TextureSpec kQuarter{320, 180, TextureFormat::RGBA16F, 1};

TEST(TexturePool, ReleasedTextureServesTheNextRequestWithTheSameKey) {
    FakeAllocator gpu;
    TexturePool pool(gpu);
    NativeTexture a = pool.acquire(kHdr, "a");
    pool.release(a);
    NativeTexture b = pool.acquire(kHdr, "b");
    EXPECT_EQ(a, b);
    EXPECT_EQ(gpu.created.size(), 1u);
    // Both names, in order: a debugger keeps one label a texture, and it must be true for both uses.
    ASSERT_EQ(gpu.relabelled.size(), 1u);
    EXPECT_EQ(gpu.relabelled[0], (std::pair<NativeTexture, std::string>{a, "a | b"}));
}

TEST(TexturePool, ASharedTextureKeepsEveryNameItHoldsAndAFrameLikeTheLastRelabelsNothing) {
    FakeAllocator gpu;
    TexturePool pool(gpu);
    auto frame = [&](std::vector<std::string> names) {
        NativeTexture used = 0;
        for (const std::string& name : names) {
            used = pool.acquire(kHdr, name);
            pool.release(used);
        }
        pool.endFrame();
        return used;
    };
    NativeTexture t = frame({"bloom.down[0]", "bloom.flicker"});
    ASSERT_EQ(gpu.relabelled.size(), 1u);
    EXPECT_EQ(gpu.relabelled[0].second, "bloom.down[0] | bloom.flicker");
    // Frame after frame the same: the label is set, and no capture sees it change.
    EXPECT_EQ(frame({"bloom.down[0]", "bloom.flicker"}), t);
    EXPECT_EQ(frame({"bloom.down[0]", "bloom.flicker"}), t);
    EXPECT_EQ(gpu.relabelled.size(), 1u);
    // Another step: a name no longer held leaves the label at the frame's end.
    EXPECT_EQ(frame({"bloom.down[0]"}), t);
    ASSERT_EQ(gpu.relabelled.size(), 2u);
    EXPECT_EQ(gpu.relabelled[1], (std::pair<NativeTexture, std::string>{t, "bloom.down[0]"}));
    EXPECT_EQ(gpu.created.size(), 1u);
}

TEST(TexturePool, ATextureHeldAcrossFramesKeepsItsName) {
    FakeAllocator gpu;
    TexturePool pool(gpu);
    NativeTexture held = pool.acquire(kHdr, "history");
    pool.endFrame();
    pool.endFrame();
    pool.release(held);
    EXPECT_EQ(pool.acquire(kHdr, "history"), held);
    EXPECT_TRUE(gpu.relabelled.empty());
}

TEST(TexturePool, DifferentKeysOrOverlappingUseGetDifferentTextures) {
    FakeAllocator gpu;
    TexturePool pool(gpu);
    NativeTexture a = pool.acquire(kHdr, "a");
    NativeTexture b = pool.acquire(kHdr, "b");  // a still in use
    NativeTexture c = pool.acquire(kQuarter, "c");
    pool.release(a);
    NativeTexture d = pool.acquire({1280, 720, TextureFormat::RGBA8, 1}, "d");    // other format
    NativeTexture e = pool.acquire({1280, 720, TextureFormat::RGBA16F, 2}, "e");  // other mip count
    EXPECT_NE(a, b);
    EXPECT_NE(c, a);
    EXPECT_NE(d, a);
    EXPECT_NE(e, a);
    EXPECT_EQ(gpu.created.size(), 5u);
    EXPECT_EQ(gpu.created[2].spec, kQuarter);
    EXPECT_EQ(gpu.created[2].label, "c");
}

TEST(TexturePool, PrefersTheTextureThatAlreadyHasTheLabel) {
    FakeAllocator gpu;
    TexturePool pool(gpu);
    NativeTexture a = pool.acquire(kHdr, "a");
    NativeTexture b = pool.acquire(kHdr, "b");
    pool.release(a);
    pool.release(b);
    pool.endFrame();
    EXPECT_EQ(pool.acquire(kHdr, "b"), b);
    EXPECT_EQ(pool.acquire(kHdr, "a"), a);
    EXPECT_TRUE(gpu.relabelled.empty());
}

TEST(TexturePool, EvictsAfterNUnusedFrames) {
    FakeAllocator gpu;
    TexturePool pool(gpu, 2);
    NativeTexture a = pool.acquire(kHdr, "a");
    pool.release(a);
    pool.endFrame();  // frame 0: used
    pool.endFrame();  // frame 1: unused once
    EXPECT_TRUE(gpu.destroyed.empty());
    EXPECT_EQ(pool.stats().liveTextures, 1u);
    pool.endFrame();  // frame 2: unused twice
    ASSERT_EQ(gpu.destroyed.size(), 1u);
    EXPECT_EQ(gpu.destroyed[0], a);
    EXPECT_EQ(pool.liveBytes(), 0u);
}

TEST(TexturePool, UseResetsTheEvictionClock) {
    FakeAllocator gpu;
    TexturePool pool(gpu, 2);
    for (int frame = 0; frame < 6; ++frame) {
        if (frame % 2 == 0) pool.release(pool.acquire(kHdr, "a"));
        pool.endFrame();
    }
    EXPECT_TRUE(gpu.destroyed.empty());
    EXPECT_EQ(gpu.created.size(), 1u);
}

TEST(TexturePool, NeverEvictsATextureInUse) {
    FakeAllocator gpu;
    TexturePool pool(gpu, 1);
    pool.acquire(kHdr, "held");
    for (int i = 0; i < 5; ++i) pool.endFrame();
    EXPECT_TRUE(gpu.destroyed.empty());
}

TEST(TexturePool, CountsLiveInUseAndPeakBytes) {
    FakeAllocator gpu;
    TexturePool pool(gpu, 1);
    const std::uint64_t hdr = 1280u * 720u * 8u;
    const TextureSpec mips{1279, 719, TextureFormat::RGBA16F, 11};
    NativeTexture a = pool.acquire(kHdr, "a");
    NativeTexture b = pool.acquire(mips, "b");
    EXPECT_EQ(pool.liveBytes(), hdr + 9'798'824u);
    EXPECT_EQ(pool.inUseBytes(), hdr + 9'798'824u);
    pool.release(b);
    EXPECT_EQ(pool.liveBytes(), hdr + 9'798'824u);
    EXPECT_EQ(pool.inUseBytes(), hdr);
    pool.release(a);
    pool.endFrame();
    pool.endFrame();
    EXPECT_EQ(pool.liveBytes(), 0u);
    EXPECT_EQ(pool.peakBytes(), hdr + 9'798'824u);
    pool.resetPeak();
    EXPECT_EQ(pool.peakBytes(), 0u);
}

TEST(TexturePool, DestroysEverythingWhenItGoes) {
    FakeAllocator gpu;
    {
        TexturePool pool(gpu);
        pool.acquire(kHdr, "a");
        pool.release(pool.acquire(kQuarter, "b"));
    }
    EXPECT_EQ(gpu.destroyed.size(), 2u);
}

TEST(TexturePool, IgnoresAReleaseOfSomethingItDidNotHandOut) {
    FakeAllocator gpu;
    TexturePool pool(gpu);
    NativeTexture a = pool.acquire(kHdr, "a");
    pool.release(a + 100);
    pool.release(a);
    pool.release(a);  // twice
    EXPECT_EQ(pool.inUseBytes(), 0u);
    EXPECT_EQ(pool.stats().liveTextures, 1u);
}

}  // namespace
}  // namespace fx
