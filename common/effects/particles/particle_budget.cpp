#include "effects/particles/particle_budget.hpp"

#include <algorithm>
#include <cmath>

#include "base/log.hpp"
#include "base/message_text.hpp"

namespace fx {
namespace {

std::uint64_t slotsOf(const EmitterSetup& s) {
    return std::uint64_t(std::max(s.capacity > 0 ? s.capacity : defaultCapacity(s.emitter), 1));
}

// "'fire', 'smoke' and 32 more".
std::string someNames(const std::vector<std::string>& names) {
    constexpr std::size_t kShown = 4;
    std::string list;
    for (std::size_t i = 0; i < names.size() && i < kShown; ++i)
        list += cat(i == 0 ? "" : ", ", "'", excerpt(names[i]), "'");
    if (names.size() > kShown) list += cat(" and ", names.size() - kShown, " more");
    return list;
}

}  // namespace

std::uint64_t particleSlotLimit(const gl::DeviceLimits& device, std::string* limitedBy) {
    struct Candidate {
        std::uint64_t slots;
        const char* why;
    };
    const Candidate candidates[] = {
        {kParticleSlotBudget, "the particle memory budget"},
        {std::uint64_t(std::max<std::int64_t>(device.maxTextureSize, 1)) * kParticleSlotsPerRow,
         "GL_MAX_TEXTURE_SIZE: the pool view's rows"},
        {std::uint64_t(std::max<std::int64_t>(device.maxComputeGroupsX, 1)) * kParticleSlotsPerRow,
         "GL_MAX_COMPUTE_WORK_GROUP_COUNT: the compute groups over the pool"},
        {std::uint64_t(std::max<std::int64_t>(device.maxStorageBlockBytes, 1)) / sizeof(GpuParticle),
         "GL_MAX_SHADER_STORAGE_BLOCK_SIZE: the pool buffer"},
    };
    const Candidate* least = &candidates[0];
    for (const Candidate& c : candidates)
        if (c.slots < least->slots) least = &c;
    if (limitedBy) *limitedBy = least->why;
    return least->slots;
}

ParticleBudget fitParticleBudget(std::vector<EmitterSetup>& setups, const gl::DeviceLimits& device) {
    ParticleBudget budget;
    budget.allowed = particleSlotLimit(device, &budget.limitedBy);
    for (const EmitterSetup& s : setups) {
        budget.asked += slotsOf(s);
        budget.emitters.push_back(s.emitter.name.empty() ? "(unnamed)" : s.emitter.name);
    }
    budget.granted = budget.asked;
    if (!budget.clamped()) return budget;
    // One factor for every emitter; each pool rounds down, so the sum stays within the limit.
    budget.scale = double(budget.allowed) / double(budget.asked);
    budget.granted = 0;
    for (EmitterSetup& s : setups) {
        const std::uint64_t slots =
            std::max<std::uint64_t>(1, std::uint64_t(std::floor(double(slotsOf(s)) * budget.scale)));
        s.capacity = int(slots);
        s.emitter.ratePerSecond = float(double(s.emitter.ratePerSecond) * budget.scale);
        budget.granted += slots;
    }
    return budget;
}

std::string ParticleBudget::summary() const {
    if (!clamped()) return cat(granted, " of ", allowed, " slots");
    return cat(asked, " slots asked; ", allowed, " allowed (", limitedBy, "): rates and pools x",
               formatNumber(float(scale)));
}

std::string ParticleBudget::warning() const {
    if (sceneEmitters > 0 && sceneEmitters != emitters.size()) {
        return cat(sceneEmitters, " emitter", sceneEmitters == 1 ? "" : "s", " of the scene, simulated as ",
                   emitters.size(), " (", someNames(emitters), "), ask for ", asked,
                   " particle slots together; ", allowed, " fit (", limitedBy,
                   ", docs/reliability.md): every emitter's rate and pool are scaled by ",
                   formatNumber(float(scale)), " to ", granted, " slots");
    }
    return cat(emitters.size(), " emitter", emitters.size() == 1 ? "" : "s", " (", someNames(emitters),
               ") ask for ", asked, " particle slots together; ", allowed, " fit (", limitedBy,
               ", docs/reliability.md): every emitter's rate and pool are scaled by ",
               formatNumber(float(scale)), " to ", granted, " slots");
}

}  // namespace fx
