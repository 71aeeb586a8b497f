#include <gtest/gtest.h>

#include "render/graph_order.hpp"

namespace fx {
namespace {

using Order = std::vector<std::uint32_t>;

TEST(StableTopologicalOrder, KeepsDeclarationOrderWithoutConstraints) {
    EXPECT_EQ(stableTopologicalOrder(4, {}).order, (Order{0, 1, 2, 3}));
}

TEST(StableTopologicalOrder, MovesOnlyWhatAConstraintMoves) {
    // 0 needs 3; 1 and 2 are free and keep their places ahead of it.
    auto result = stableTopologicalOrder(4, {{3, 0, 0}});
    ASSERT_TRUE(result.ok());
    EXPECT_EQ(result.order, (Order{1, 2, 3, 0}));
}

TEST(StableTopologicalOrder, EarliestReadyNodeGoesFirst) {
    // 2 before 0, 3 before 1: after 2 runs, 0 is ready and declared before 3.
    auto result = stableTopologicalOrder(4, {{2, 0, 0}, {3, 1, 0}});
    EXPECT_EQ(result.order, (Order{2, 0, 3, 1}));
}

TEST(StableTopologicalOrder, RepeatedConstraintsAreHarmless) {
    auto result = stableTopologicalOrder(2, {{1, 0, 0}, {1, 0, 1}});
    EXPECT_EQ(result.order, (Order{1, 0}));
}

TEST(StableTopologicalOrder, FindsTheCycleInRunOrder) {
    // 0 -> 1 -> 2 -> 0 is a cycle; 3 depends on it and 4 is free.
    auto result = stableTopologicalOrder(5, {{0, 1, 10}, {1, 2, 11}, {2, 0, 12}, {2, 3, 13}});
    ASSERT_FALSE(result.ok());
    EXPECT_EQ(result.order, (Order{4}));
    EXPECT_EQ(result.cycle, (Order{0, 1, 2}));
    ASSERT_EQ(result.cycleConstraints.size(), 3u);
    EXPECT_EQ(result.cycleConstraints[0].texture, 10u);  // 0 -> 1
    EXPECT_EQ(result.cycleConstraints[1].texture, 11u);  // 1 -> 2
    EXPECT_EQ(result.cycleConstraints[2].texture, 12u);  // 2 -> 0
}

TEST(StableTopologicalOrder, FindsACycleDownstreamOfAnotherLeftover) {
    // 0 waits on the cycle 2 <-> 3 without being in it.
    auto result = stableTopologicalOrder(4, {{3, 0, 0}, {2, 3, 1}, {3, 2, 2}, {1, 0, 3}});
    ASSERT_FALSE(result.ok());
    EXPECT_EQ(result.cycle, (Order{2, 3}));
    EXPECT_EQ(result.cycleConstraints[0].texture, 1u);
    EXPECT_EQ(result.cycleConstraints[1].texture, 2u);
}

}  // namespace
}  // namespace fx
