// The inspector's texture list names each texture's producer as FrameReport::findPass does (the
// first pass of that name), through a table built once per frame instead of a search per texture.
#include <gtest/gtest.h>

#include <string>

#include "ui/inspector_list.hpp"

namespace fx {
namespace {

PassRecord passNamed(std::string name, bool executed) {
    PassRecord p;
    p.name = std::move(name);
    p.executed = executed;
    return p;
}

TextureRecord textureFrom(std::string name, std::string producer, TextureOrigin origin) {
    TextureRecord t;
    t.name = std::move(name);
    t.producer = std::move(producer);
    t.origin = origin;
    return t;
}

// A frame of a graph with errors can repeat a pass name: the first pass of that name is the producer.
TEST(InspectorList, TheProducerIsTheFirstPassOfItsName) {
    FrameReport frame;
    frame.passes = {passNamed("blur", true), passNamed("scene", false), passNamed("blur", false)};
    frame.textures = {textureFrom("output", "", TextureOrigin::PresentedOutput),
                      textureFrom("glow", "blur", TextureOrigin::Transient),
                      textureFrom("history", "", TextureOrigin::Imported),
                      textureFrom("stale", "a pass of another frame", TextureOrigin::Imported),
                      textureFrom("hdr", "scene", TextureOrigin::Imported)};
    auto entries = listTextures(frame);
    ASSERT_EQ(entries.size(), frame.textures.size());
    for (std::size_t i = 0; i < entries.size(); ++i) EXPECT_EQ(entries[i].texture, &frame.textures[i]);
    EXPECT_EQ(entries[0].producer, nullptr);
    EXPECT_TRUE(entries[0].presented);
    EXPECT_EQ(entries[1].producer, &frame.passes[0]);
    EXPECT_EQ(entries[2].producer, nullptr);
    EXPECT_TRUE(entries[2].made) << "an import nobody writes is always there";
    EXPECT_EQ(entries[3].producer, nullptr) << "a producer no pass of this frame has";
    EXPECT_EQ(entries[4].producer, &frame.passes[1]);
    EXPECT_FALSE(entries[4].made) << "an import whose producer did not run";
}

// Many passes and textures: every entry's producer is what findPass gives.
TEST(InspectorList, ProducersOfAThousandPassesMatchFindPass) {
    FrameReport frame;
    for (int i = 0; i < 1000; ++i)
        frame.passes.push_back(passNamed("pass " + std::to_string(i % 700), i % 3 != 0));
    for (int i = 0; i < 2000; ++i) {
        frame.textures.push_back(textureFrom("texture " + std::to_string(i),
                                             "pass " + std::to_string(i % 800), TextureOrigin::Transient));
    }
    auto entries = listTextures(frame);
    ASSERT_EQ(entries.size(), frame.textures.size());
    int unknown = 0;
    for (const TextureListEntry& e : entries) {
        EXPECT_EQ(e.producer, frame.findPass(e.texture->producer)) << e.texture->name;
        unknown += e.producer == nullptr ? 1 : 0;
    }
    EXPECT_EQ(unknown, 200) << "textures 700 to 799 and 1500 to 1599 name passes no frame has";
}

}  // namespace
}  // namespace fx
