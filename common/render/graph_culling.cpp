// What runs. A pass runs when it is switched on, every texture it reads has a producer that runs,
// and something it writes reaches a root (the presented output or another import, a capture, an
// inspected texture) through passes that run. Every other pass gets a reason a person can read.
#include <algorithm>

#include "base/log.hpp"
#include "render/graph_compiler.hpp"

namespace fx {
namespace {

std::string switchedOffReason(const Pass& pass) {
    if (!pass.switchReason().empty()) return pass.switchReason();
    return pass.switchState() == PassSwitch::Disabled ? "disabled" : "not called for by the scene";
}

std::string unusedReason(const Pass& pass, const std::vector<GraphTexture>& textures) {
    std::vector<std::string> written;
    for (const auto& a : pass.accesses()) {
        if (a.writes) written.push_back(textures[a.texture.index].view.name);
    }
    if (written.empty()) return "output unused: it declares no outputs";
    return cat("output unused: ", quotedList(written), written.size() == 1 ? " reaches" : " reach",
               " no output, capture or inspected view");
}

}  // namespace

void decideWhatRuns(const PassList& passes, const std::vector<GraphTexture>& textures, CompiledGraph& graph) {
    graph.verdicts.assign(passes.size(), {});
    graph.producer.assign(textures.size(), std::nullopt);
    for (std::size_t t = 0; t < textures.size(); ++t)
        graph.producer[t] = activeCreator(graph.roles[t], passes);

    // Forward, in derived order: producers are decided before their readers.
    std::vector<bool> able(passes.size(), false);
    for (std::uint32_t p : graph.derivedOrder) {
        const Pass& pass = *passes[p];
        PassVerdict& verdict = graph.verdicts[p];
        if (pass.switchState() != PassSwitch::On) {
            verdict.status =
                pass.switchState() == PassSwitch::Disabled ? PassStatus::Disabled : PassStatus::NotCalledFor;
            verdict.reason = switchedOffReason(pass);
            continue;
        }
        for (const auto& a : pass.accesses()) {
            // An import keeps its content from before, whoever writes it this frame.
            if (!a.reads || !textures[a.texture.index].transient()) continue;
            std::optional<std::uint32_t> producer = graph.producer[a.texture.index];
            if (!producer || able[*producer]) continue;
            const std::string& producerName = passes[*producer]->name();
            verdict.status = PassStatus::MissingInput;
            verdict.reason =
                cat("needs '", textures[a.texture.index].view.name, "', which pass '", producerName,
                    "' did not produce ('", producerName, "': ", graph.verdicts[*producer].reason, ")");
            break;
        }
        able[p] = verdict.status == PassStatus::Runs;
    }

    // Backward: a pass is needed when it writes something needed; what it reads becomes needed.
    std::vector<bool> needed(textures.size(), false);
    for (std::size_t t = 0; t < textures.size(); ++t) needed[t] = textures[t].root();
    std::vector<bool> runs(passes.size(), false);
    for (auto it = graph.derivedOrder.rbegin(); it != graph.derivedOrder.rend(); ++it) {
        std::uint32_t p = *it;
        if (!able[p]) continue;
        const Pass& pass = *passes[p];
        const auto& accesses = pass.accesses();
        runs[p] = pass.keptAlive() ||
                  std::any_of(accesses.begin(), accesses.end(),
                              [&](const TextureAccess& a) { return a.writes && needed[a.texture.index]; });
        if (!runs[p]) {
            graph.verdicts[p] = {PassStatus::OutputUnused, unusedReason(pass, textures)};
            continue;
        }
        for (const auto& a : accesses) {
            if (a.reads) needed[a.texture.index] = true;
        }
    }

    graph.executionOrder.clear();
    for (std::uint32_t p : graph.derivedOrder) {
        if (runs[p]) graph.executionOrder.push_back(p);
    }
}

}  // namespace fx
