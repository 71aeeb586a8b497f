#pragma once
// Passes and textures that belong together, such as "the bloom chain": the lesson (or an effect)
// opens the group on the graph while it declares them, and later asks the group, not pass names,
// what it cost and which textures it made. A group may need something outside the graph (a scene
// feature, see Pass::needs): every pass declared in it then needs it, so the graph gives all of them
// the reason when it is missing.
//
//   PassGroup bloom = PassGroup().needing("scene feature 8");  // a member: its id lasts across frames
//   { PassGroup::Scope in(graph, bloom); chain.declare(graph, ...); composite.declare(graph, ...); }
//   double ms = bloom.timeMs(*frame.previousFrame);           // every timed pass of the group, summed
#include <cstdint>
#include <string>
#include <vector>

#include "render/frame_report.hpp"

namespace fx {

class FrameGraph;

class PassGroup {
public:
    PassGroup();  // a new id, never 0 (0 means "in no group")
    std::uint32_t id() const { return id_; }
    // Every pass declared in the group needs `requirement` (Pass::needs).
    PassGroup& needing(std::string requirement);
    const std::string& requirement() const { return requirement_; }

    // The summed time of the group's timed passes in `report`; 0 when none was timed.
    double timeMs(const FrameReport& report) const;
    // The group's passes as `report` recorded them, in its order.
    std::vector<const PassRecord*> records(const FrameReport& report) const;
    // The names of the passes and textures declared in the group, in the report's order.
    std::vector<std::string> passes(const FrameReport& report) const;
    std::vector<std::string> textures(const FrameReport& report) const;

    // Every pass added and texture declared while a Scope is open joins its group. Scopes nest: the
    // innermost group wins, and the outer one is open again when the inner scope closes.
    class Scope {
    public:
        Scope(FrameGraph& graph, const PassGroup& group);
        ~Scope();
        Scope(const Scope&) = delete;
        Scope& operator=(const Scope&) = delete;

    private:
        FrameGraph& graph_;
        const PassGroup* outer_;
    };

private:
    std::uint32_t id_;
    std::string requirement_;
};

}  // namespace fx
