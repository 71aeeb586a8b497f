// The chain strip: every level of a mip chain side by side with GL's sizes (odd sizes included),
// and every texture of a named chain such as blur[*], each drawn from the live texture.
#include "test_ui_harness.hpp"
#include "ui/texture_chain.hpp"

#include <imgui.h>

using namespace fx;
using namespace fx::test;

class UiChain : public GlTest {};

TEST(UiChainNames, ParsesIndexedNames) {
    auto n = parseIndexedName("bloom.down[3]");
    ASSERT_TRUE(n.has_value());
    EXPECT_EQ(n->base, "bloom.down");
    EXPECT_EQ(n->index, 3);
    EXPECT_FALSE(parseIndexedName("bloom.down").has_value());
    EXPECT_FALSE(parseIndexedName("bloom.down[]").has_value());
    EXPECT_FALSE(parseIndexedName("bloom.down[x]").has_value());
    EXPECT_FALSE(parseIndexedName("[3]").has_value());
}

TEST(UiChainNames, MipChainOfAnOddSizeFollowsGlsRule) {
    TextureChain chain = mipChain("t", {1279, 719, TextureFormat::RGBA16F, 11});
    const std::vector<Size2D> expected = {{1279, 719}, {639, 359}, {319, 179}, {159, 89}, {79, 44}, {39, 22},
                                          {19, 11},    {9, 5},     {4, 2},     {2, 1},    {1, 1}};
    ASSERT_EQ(chain.members.size(), expected.size());
    for (std::size_t i = 0; i < expected.size(); ++i) {
        EXPECT_EQ(chain.members[i].size, expected[i]) << "level " << i;
        EXPECT_EQ(chain.members[i].level, int(i));
    }
    EXPECT_EQ(mipChain("t", {64, 64, TextureFormat::RGBA8, 1}).kind, TextureChain::Kind::None);
}

TEST_F(UiChain, StripShowsEveryLevelOfA1279x719ChainWithItsSize) {
    UiHarness h(1279, 719);
    TestScene scene;
    auto build = [&](FrameGraph& g) { scene.declare(g); };
    h.overlay.inspector().setOpen(true);
    h.overlay.inspector().select("scene.hdr");
    h.frame(build);  // the selection is wanted from now on
    auto wanted = h.overlay.wantedTextures();
    EXPECT_NE(std::find(wanted.begin(), wanted.end(), "scene.hdr"), wanted.end());
    h.frame(build);  // scene.hdr is alive in this one

    const TextureChain& chain = h.overlay.inspector().chain();
    EXPECT_EQ(chain.kind, TextureChain::Kind::MipLevels);
    const auto& tiles = h.overlay.inspector().strip().tiles();
    const std::vector<Size2D> expected = {{1279, 719}, {639, 359}, {319, 179}, {159, 89}, {79, 44}, {39, 22},
                                          {19, 11},    {9, 5},     {4, 2},     {2, 1},    {1, 1}};
    ASSERT_EQ(tiles.size(), expected.size());
    for (std::size_t i = 0; i < tiles.size(); ++i) {
        EXPECT_EQ(tiles[i].size, expected[i]) << "level " << i;
        EXPECT_EQ(tiles[i].label, "mip " + std::to_string(i));
        EXPECT_TRUE(tiles[i].drawn) << "level " << i << " was not drawn from the live texture";
        EXPECT_GT(tiles[i].width, 0);
    }
}

TEST_F(UiChain, NamedChainListsItsTexturesInIndexOrder) {
    UiHarness h(320, 180);
    auto build = [](FrameGraph& g) {
        TextureHandle previous{};
        // Declared out of order on purpose: the strip orders by index, not by declaration.
        for (int i : {0, 2, 1}) {
            auto& p = g.addPass("blur " + std::to_string(i), [](PassContext&) {});
            TextureHandle t =
                p.create("blur[" + std::to_string(i) + "]",
                         {TextureSize::outputFraction(1, 1 << (i + 1)), TextureFormat::RGBA16F, 1},
                         TextureUsage::ColorAttachment);
            p.setState({.clearColor = ClearColor{0.2f * float(i), 0.5f, 1.0f, 1.0f}});
            previous = t;
        }
        g.addPass("present", [](PassContext&) {})
            .read(previous)
            .writeColor(g.output())
            .setState({.clearColor = ClearColor{0, 0, 0, 1}});
    };
    h.overlay.inspector().setOpen(true);
    h.overlay.inspector().select("blur[0]");
    h.frame(build);
    auto wanted = h.overlay.wantedTextures();
    for (const char* name : {"blur[0]", "blur[1]", "blur[2]"}) {
        EXPECT_NE(std::find(wanted.begin(), wanted.end(), name), wanted.end()) << name;
    }
    h.frame(build);
    const TextureChain& chain = h.overlay.inspector().chain();
    ASSERT_EQ(chain.kind, TextureChain::Kind::Named);
    ASSERT_EQ(chain.members.size(), 3u);
    EXPECT_EQ(chain.members[0].texture, "blur[0]");
    EXPECT_EQ(chain.members[1].texture, "blur[1]");
    EXPECT_EQ(chain.members[2].texture, "blur[2]");
    EXPECT_EQ(chain.members[0].size, (Size2D{160, 90}));
    EXPECT_EQ(chain.members[1].size, (Size2D{80, 45}));
    EXPECT_EQ(chain.members[2].size, (Size2D{40, 22}));
    for (const auto& tile : h.overlay.inspector().strip().tiles()) EXPECT_TRUE(tile.drawn) << tile.label;
}

// At 1280x720 with the inspector open in the presentation layout, all six levels of a bloom-like
// chain (labels as long as "bloom.down[5]") are on the screen: the tiles shrink, or wrap, to fit.
TEST_F(UiChain, ASixLevelNamedChainFitsTheInspectorAt1280x720) {
    UiHarness h(1280, 720);
    auto build = [](FrameGraph& g) {
        TextureHandle previous{};
        for (int i = 0; i < 6; ++i) {
            auto& p = g.addPass("down " + std::to_string(i), [](PassContext&) {});
            previous = p.create("bloom.down[" + std::to_string(i) + "]",
                                {TextureSize::outputFraction(1, 2 << i), TextureFormat::RGBA16F, 1},
                                TextureUsage::ColorAttachment);
            p.setState({.clearColor = ClearColor{0.1f * float(i), 0.4f, 0.8f, 1.0f}});
        }
        g.addPass("present", [](PassContext&) {})
            .read(previous)
            .writeColor(g.output())
            .setState({.clearColor = ClearColor{0, 0, 0, 1}});
    };
    h.overlay.inspector().setOpen(true);
    h.overlay.inspector().select("bloom.down[0]");
    for (int i = 0; i < 3; ++i) h.frame(build);
    const auto& tiles = h.overlay.inspector().strip().tiles();
    ASSERT_EQ(tiles.size(), 6u);
    for (const auto& tile : tiles) {
        EXPECT_TRUE(tile.drawn) << tile.label;
        EXPECT_GE(tile.screenX, 0.0f) << tile.label;
        EXPECT_LE(tile.screenX + float(tile.width), 1280.0f) << tile.label << " is off the right edge";
        EXPECT_LE(tile.screenY + float(tile.height), 720.0f) << tile.label << " is below the window";
        // Its label and size under it, inside the inspector's padding: "134x75" was cut at the
        // window's foot at the default inspector height.
        const float textBelow =
            2.0f * ImGui::GetTextLineHeightWithSpacing() + ImGui::GetStyle().WindowPadding.y;
        EXPECT_LE(tile.screenY + float(tile.height) + textBelow, 720.0f) << tile.label << "'s size is cut";
    }
    // Readable at the default layout: the first level's tile is no 24-pixel sliver.
    EXPECT_GE(tiles.front().height, 40) << "the chain strip at the default inspector height";
}
