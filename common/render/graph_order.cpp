#include "render/graph_order.hpp"

#include <algorithm>
#include <functional>
#include <queue>

namespace fx {
namespace {

// Every node left after Kahn's algorithm has a predecessor that is also left, so walking
// predecessors from any of them must revisit a node: that loop is a cycle.
void findCycle(const std::vector<std::vector<const OrderConstraint*>>& incoming,
               const std::vector<bool>& placed, TopologicalOrder& result) {
    auto start = static_cast<std::uint32_t>(std::find(placed.begin(), placed.end(), false) - placed.begin());
    std::vector<int> seenAt(placed.size(), -1);
    std::vector<const OrderConstraint*> walk;  // walk[i] leads from node i+1 back to node i
    std::vector<std::uint32_t> nodes{start};
    seenAt[start] = 0;
    for (;;) {
        std::uint32_t node = nodes.back();
        const OrderConstraint* step = nullptr;
        for (const OrderConstraint* c : incoming[node]) {
            if (!placed[c->before] && (step == nullptr || c->before < step->before)) step = c;
        }
        if (step == nullptr) return;  // cannot happen when called on a real leftover
        walk.push_back(step);
        if (seenAt[step->before] >= 0) {
            // nodes[k..] walked backwards from the repeated node; reverse into run order.
            auto k = static_cast<std::size_t>(seenAt[step->before]);
            std::vector<std::uint32_t> loop(nodes.begin() + static_cast<std::ptrdiff_t>(k), nodes.end());
            std::vector<const OrderConstraint*> steps(walk.begin() + static_cast<std::ptrdiff_t>(k),
                                                      walk.end());
            std::reverse(loop.begin(), loop.end());
            std::reverse(steps.begin(), steps.end());
            // After reversing, steps[i] leads into loop[i]; shift so steps[i] leads out of it.
            std::rotate(steps.begin(), steps.begin() + 1, steps.end());
            // Start the loop at its earliest-declared pass so the message is stable.
            auto first = std::min_element(loop.begin(), loop.end()) - loop.begin();
            std::rotate(loop.begin(), loop.begin() + first, loop.end());
            std::rotate(steps.begin(), steps.begin() + first, steps.end());
            result.cycle = loop;
            for (const OrderConstraint* s : steps) result.cycleConstraints.push_back(*s);
            return;
        }
        seenAt[step->before] = static_cast<int>(nodes.size());
        nodes.push_back(step->before);
    }
}

}  // namespace

TopologicalOrder stableTopologicalOrder(std::uint32_t nodeCount,
                                        const std::vector<OrderConstraint>& constraints) {
    std::vector<std::vector<std::uint32_t>> successors(nodeCount);
    std::vector<std::vector<const OrderConstraint*>> incoming(nodeCount);
    std::vector<std::uint32_t> waitingOn(nodeCount, 0);
    for (const auto& c : constraints) {
        if (c.before >= nodeCount || c.after >= nodeCount || c.before == c.after) continue;
        successors[c.before].push_back(c.after);
        incoming[c.after].push_back(&c);
        ++waitingOn[c.after];
    }

    std::priority_queue<std::uint32_t, std::vector<std::uint32_t>, std::greater<>> ready;
    for (std::uint32_t n = 0; n < nodeCount; ++n) {
        if (waitingOn[n] == 0) ready.push(n);
    }
    TopologicalOrder result;
    std::vector<bool> placed(nodeCount, false);
    while (!ready.empty()) {
        std::uint32_t n = ready.top();
        ready.pop();
        result.order.push_back(n);
        placed[n] = true;
        for (std::uint32_t next : successors[n]) {
            if (--waitingOn[next] == 0) ready.push(next);
        }
    }
    if (result.order.size() < nodeCount) findCycle(incoming, placed, result);
    return result;
}

}  // namespace fx
