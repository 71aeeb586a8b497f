// FrameReport::executedPasses: the order a lesson compares with its chapter's (lessons 03 and 06).
#include <gtest/gtest.h>

#include "render/frame_report.hpp"

namespace fx {
namespace {

TEST(FrameReport, ExecutedPassesAreThoseThatRanInTheirOrder) {
    FrameReport report;
    for (auto [name, ran] : {std::pair{"shadow map", true},
                             {"scene", true},
                             {"radial blur offsets", false},
                             {"output transform", true}}) {
        PassRecord p;
        p.name = name;
        p.executed = ran;
        report.passes.push_back(p);
    }
    EXPECT_EQ(report.executedPasses(), (std::vector<std::string>{"shadow map", "scene", "output transform"}));
    EXPECT_EQ(joinedNames(report.executedPasses()), "shadow map, scene, output transform");
    EXPECT_EQ(joinedNames({}), "");
}

}  // namespace
}  // namespace fx
