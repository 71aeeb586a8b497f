// The lesson kit's GL-free pieces: the facts list (one list for the panel and the report) and the
// drag helper for a point on screen.
#include <gtest/gtest.h>

#include "app/lesson_facts.hpp"
#include "app/point_drag.hpp"
#include "base/paths.hpp"
#include "base/words.hpp"

namespace fx {
namespace {

TEST(Facts, KeepsTextBoolsAndWhatThePanelShows) {
    // A shown fact's label is the lesson's words for it (lesson 05's, in English).
    auto words = Words::load(projectRoot() / "lessons" / "05_radial_blur", "en");
    ASSERT_TRUE(words) << words.error();
    useWords(std::move(*words));
    Facts facts;
    facts.add("formula", "the chapter's start distance");  // a string literal stays text
    facts.add("deliberateBug", true);
    facts.check("expectNonFiniteIn", "blur.offset, blur.result");
    ASSERT_EQ(facts.list().size(), 3u);
    EXPECT_EQ(*facts.find("formula"), "the chapter's start distance");
    EXPECT_EQ(*facts.find("deliberateBug"), "true");
    EXPECT_EQ(*facts.find("expectNonFiniteIn"), "blur.offset, blur.result");
    EXPECT_TRUE(facts.list()[0].shown);
    EXPECT_EQ(facts.list()[1].label, "deliberate bug");
    EXPECT_FALSE(facts.list()[2].shown) << "checks are for the report only";
    EXPECT_EQ(facts.find("missing"), nullptr);
}

FrameInfo pointerFrame(float x, float y, bool down, bool overUi = false) {
    FrameInfo frame;
    frame.size = {200, 100};
    frame.pointer = {true, x, y, down, overUi};
    return frame;
}

TEST(PointDrag, FollowsAPressThatStartsOnThePicture) {
    PointDrag drag;
    EXPECT_FALSE(drag.update(pointerFrame(50, 50, false)));
    auto grabbed = drag.update(pointerFrame(50, 25, true));
    ASSERT_TRUE(grabbed);
    EXPECT_FLOAT_EQ(grabbed->x, 0.25f);
    EXPECT_FLOAT_EQ(grabbed->y, 0.25f);
    // Held and moved, even over the overlay: still dragging.
    auto moved = drag.update(pointerFrame(150, 75, true, true));
    ASSERT_TRUE(moved);
    EXPECT_FLOAT_EQ(moved->x, 0.75f);
    EXPECT_FALSE(drag.update(pointerFrame(150, 75, false)));
    EXPECT_FALSE(drag.dragging());
}

TEST(PointDrag, IgnoresAPressOnTheOverlayAndAButtonHeldFromBefore) {
    PointDrag drag;
    EXPECT_FALSE(drag.update(pointerFrame(50, 50, true, true))) << "the press belongs to the overlay";
    EXPECT_FALSE(drag.update(pointerFrame(60, 50, true))) << "still the same press";
    EXPECT_FALSE(drag.update(pointerFrame(60, 50, false)));
    EXPECT_TRUE(drag.update(pointerFrame(60, 50, true))) << "a new press on the picture";
}

TEST(PointDrag, NothingToDragOnAnEmptyFrame) {
    PointDrag drag;
    FrameInfo frame = pointerFrame(1, 1, true);
    frame.size = {0, 0};
    EXPECT_FALSE(drag.update(frame));
}

}  // namespace
}  // namespace fx
