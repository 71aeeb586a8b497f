#pragma once
// Execution order from "A must run before B" constraints: a stable topological sort. Among passes
// whose predecessors have all run, the one declared first goes next, so independent passes keep the
// order the lesson wrote them in and only real dependencies move a pass.
#include <cstdint>
#include <vector>

namespace fx {

struct OrderConstraint {
    std::uint32_t before = 0;
    std::uint32_t after = 0;
    std::uint32_t texture = 0;  // the texture that causes it, to explain a cycle
};

struct TopologicalOrder {
    std::vector<std::uint32_t> order;  // every node, when there is no cycle
    // When there is one: the nodes of one cycle in run order (cycle[i] must run before cycle[i+1],
    // the last before the first) and the constraint behind each of those steps.
    std::vector<std::uint32_t> cycle;
    std::vector<OrderConstraint> cycleConstraints;
    bool ok() const { return cycle.empty(); }
};

// Nodes are 0..nodeCount-1 in declaration order. Constraints may repeat.
TopologicalOrder stableTopologicalOrder(std::uint32_t nodeCount,
                                        const std::vector<OrderConstraint>& constraints);

}  // namespace fx
