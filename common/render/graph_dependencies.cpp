// Who writes what, and the order that follows from it. For each texture:
//   the creator (writes without reading) runs first,
//   then the modifiers (read and write) in declaration order,
//   then every pure reader.
#include "base/log.hpp"
#include "render/graph_compiler.hpp"

namespace fx {

std::string quotedList(const std::vector<std::string>& names) {
    std::string out;
    for (std::size_t i = 0; i < names.size(); ++i) {
        if (i > 0) out += i + 1 == names.size() ? " and " : ", ";
        out += cat("'", names[i], "'");
    }
    return out;
}

std::string passNames(const PassList& passes, const std::vector<std::uint32_t>& indices) {
    std::vector<std::string> names;
    for (std::uint32_t i : indices) names.push_back(passes[i]->name());
    return quotedList(names);
}

std::vector<TextureRoles> collectRoles(const PassList& passes, std::size_t textureCount) {
    std::vector<TextureRoles> roles(textureCount);
    for (const auto& pass : passes) {
        for (const auto& a : pass->accesses()) {
            TextureRoles& r = roles[a.texture.index];
            auto& list = a.creates() ? r.creators : a.modifies() ? r.modifiers : r.readers;
            list.push_back(pass->declaredIndex());
        }
    }
    return roles;
}

std::optional<std::uint32_t> activeCreator(const TextureRoles& roles, const PassList& passes) {
    for (std::uint32_t c : roles.creators) {
        if (passes[c]->switchState() == PassSwitch::On) return c;
    }
    if (!roles.creators.empty()) return roles.creators.front();
    return std::nullopt;
}

std::vector<std::string> validateWriters(const PassList& passes, const std::vector<GraphTexture>& textures,
                                         const std::vector<TextureRoles>& roles) {
    std::vector<std::string> errors;
    for (std::size_t t = 0; t < textures.size(); ++t) {
        const TextureRoles& r = roles[t];
        const std::string& name = textures[t].view.name;

        // Passes switched off by the lesson do not count: a step may swap one creator for another.
        std::vector<std::uint32_t> switchedOn;
        for (std::uint32_t c : r.creators) {
            if (passes[c]->switchState() == PassSwitch::On) switchedOn.push_back(c);
        }
        if (switchedOn.size() > 1) {
            errors.push_back(cat(
                "'", name, "' is written without being read by ", passNames(passes, switchedOn),
                ", so their order is undefined; only one pass may create a texture, and the others must modify it (read and write) to come after it"));
        }

        if (!textures[t].transient() || !r.creators.empty()) continue;
        if (!r.modifiers.empty()) {
            errors.push_back(
                cat(passNames(passes, r.modifiers), r.modifiers.size() == 1 ? " modifies '" : " modify '",
                    name, "', but no pass creates it (writes it without reading it) and it is not imported"));
        } else if (!r.readers.empty()) {
            errors.push_back(cat(passNames(passes, r.readers), r.readers.size() == 1 ? " reads '" : " read '",
                                 name, "', which no pass writes and which is not imported"));
        }
    }
    return errors;
}

std::vector<OrderConstraint> orderConstraints(const std::vector<TextureRoles>& roles) {
    std::vector<OrderConstraint> constraints;
    for (std::size_t t = 0; t < roles.size(); ++t) {
        const TextureRoles& r = roles[t];
        auto texture = static_cast<std::uint32_t>(t);
        auto add = [&](std::uint32_t before, std::uint32_t after) {
            constraints.push_back({before, after, texture});
        };
        // The last writer in the chain hands the texture to the readers.
        std::vector<std::uint32_t> lastWriters = r.creators;
        for (std::uint32_t m : r.modifiers) {
            for (std::uint32_t w : lastWriters) add(w, m);
            lastWriters = {m};
        }
        for (std::uint32_t reader : r.readers) {
            for (std::uint32_t w : lastWriters) add(w, reader);
        }
    }
    return constraints;
}

std::string describeCycle(const TopologicalOrder& order, const PassList& passes,
                          const std::vector<GraphTexture>& textures) {
    std::string loop;
    for (std::uint32_t p : order.cycle) loop += cat("'", passes[p]->name(), "' -> ");
    loop += cat("'", passes[order.cycle.front()]->name(), "'");

    std::string why;
    for (const OrderConstraint& c : order.cycleConstraints) {
        const Pass& before = *passes[c.before];
        const Pass& after = *passes[c.after];
        const std::string& texture = textures[c.texture].view.name;
        bool afterReads = false;
        bool beforeCreates = false;
        for (const auto& a : after.accesses()) {
            if (a.texture.index == c.texture) afterReads = a.onlyReads();
        }
        for (const auto& a : before.accesses()) {
            if (a.texture.index == c.texture) beforeCreates = a.creates();
        }
        if (!why.empty()) why += "; ";
        if (afterReads) {
            why += cat("'", after.name(), "' reads '", texture, "' written by '", before.name(), "'");
        } else if (beforeCreates) {
            why += cat("'", after.name(), "' modifies '", texture, "' created by '", before.name(), "'");
        } else {
            why += cat("'", after.name(), "' modifies '", texture, "' after '", before.name(),
                       "' (modifiers follow declaration order)");
        }
    }
    return cat("passes form a cycle: ", loop, " (", why, ")");
}

}  // namespace fx
