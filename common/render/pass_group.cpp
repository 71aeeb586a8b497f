#include "render/pass_group.hpp"

#include <atomic>

#include "render/frame_graph.hpp"

namespace fx {
namespace {

std::uint32_t nextGroupId() {
    static std::atomic<std::uint32_t> next{1};
    return next++;
}

}  // namespace

PassGroup::PassGroup() : id_(nextGroupId()) {}

PassGroup& PassGroup::needing(std::string requirement) {
    requirement_ = std::move(requirement);
    return *this;
}

double PassGroup::timeMs(const FrameReport& report) const {
    double total = 0;
    for (const PassRecord& p : report.passes) {
        if (p.group == id_ && p.timeMs) total += *p.timeMs;
    }
    return total;
}

std::vector<const PassRecord*> PassGroup::records(const FrameReport& report) const {
    std::vector<const PassRecord*> out;
    for (const PassRecord& p : report.passes) {
        if (p.group == id_) out.push_back(&p);
    }
    return out;
}

std::vector<std::string> PassGroup::passes(const FrameReport& report) const {
    std::vector<std::string> names;
    for (const PassRecord& p : report.passes) {
        if (p.group == id_) names.push_back(p.name);
    }
    return names;
}

std::vector<std::string> PassGroup::textures(const FrameReport& report) const {
    std::vector<std::string> names;
    for (const TextureRecord& t : report.textures) {
        if (t.group == id_) names.push_back(t.name);
    }
    return names;
}

PassGroup::Scope::Scope(FrameGraph& graph, const PassGroup& group)
    : graph_(graph), outer_(graph.openGroup(&group)) {}

PassGroup::Scope::~Scope() {
    graph_.openGroup(outer_);
}

}  // namespace fx
