#include "render/graph_dot.hpp"

#include <map>
#include <string_view>

#include "base/log.hpp"

namespace fx {
namespace {

constexpr std::string_view kRanFill = "#dbe8f6";
constexpr std::string_view kTextureFill = "#fdf3d8";
constexpr std::string_view kCulledFill = "#eeeeee";
constexpr std::string_view kCulledLine = "#9a9a9a";
constexpr std::size_t kWrapColumn = 36;
constexpr std::string_view kInheritedLine = "#c0392b";
constexpr std::size_t kInheritedListed = 2;
constexpr std::string_view kLeftToRight = "rankdir=LR";

// "depth test: off (inherited)" -> "depth test: off": the label already says "inherits".
std::string withoutSuffix(std::string_view item) {
    constexpr std::string_view suffix = " (inherited)";
    if (item.ends_with(suffix)) item.remove_suffix(suffix.size());
    return std::string(item);
}

// A dot string literal's content: quotes and backslashes escaped, newlines as dot's centred \n.
std::string quoted(std::string_view text) {
    std::string out = "\"";
    for (char c : text) {
        if (c == '"' || c == '\\') out += '\\';
        if (c == '\n') {
            out += "\\n";
            continue;
        }
        out += c;
    }
    return out + "\"";
}

// Breaks a long reason into lines at spaces, so a grey box does not become a banner.
std::string wrapped(std::string_view text) {
    std::string out;
    std::size_t column = 0;
    std::size_t start = 0;
    while (start < text.size()) {
        std::size_t space = text.find(' ', start);
        std::string_view word =
            text.substr(start, space == std::string_view::npos ? std::string_view::npos : space - start);
        if (column > 0 && column + 1 + word.size() > kWrapColumn) {
            out += '\n';
            column = 0;
        } else if (column > 0) {
            out += ' ';
            ++column;
        }
        out += word;
        column += word.size();
        if (space == std::string_view::npos) break;
        start = space + 1;
    }
    return out;
}

std::string ordinal(std::size_t n) {
    std::string_view suffix = "th";
    if (n % 100 < 11 || n % 100 > 13) {
        if (n % 10 == 1) suffix = "st";
        if (n % 10 == 2) suffix = "nd";
        if (n % 10 == 3) suffix = "rd";
    }
    return cat(n, suffix);
}

std::string passNode(std::size_t index) {
    return cat("pass", index);
}

std::string textureNode(std::size_t index) {
    return cat("texture", index);
}

std::string passStatement(const PassRecord& pass, std::size_t node, std::size_t ranPosition) {
    if (pass.status == PassStatus::Runs) {
        std::string label =
            cat(ranPosition, ". ", pass.name, "\n(declared ", ordinal(pass.declaredIndex + 1), ")");
        std::string attributes = cat("style=\"rounded,filled\", fillcolor=\"", kRanFill, "\"");
        if (!pass.stateInherited.empty()) {
            // The state check's finding (lesson 03's bug): named when short, counted when long.
            std::string all;
            for (const std::string& item : pass.stateInherited)
                all += cat(all.empty() ? "" : "\n", withoutSuffix(item));
            label += pass.stateInherited.size() <= kInheritedListed
                         ? cat("\ninherits ", all)
                         : cat("\ninherits ", pass.stateInherited.size(), " settings");
            attributes += cat(", color=\"", kInheritedLine,
                              "\", penwidth=2, tooltip=", quoted(cat("inherits:\n", all)));
        }
        return cat("  ", passNode(node), " [shape=box, label=", quoted(label), ", ", attributes, "];\n");
    }
    // "output unused: ..." names its status itself; "scene has no particle emitter" does not.
    std::string_view status = toString(pass.status);
    std::string why = pass.reason.starts_with(status) ? pass.reason
                      : pass.reason.empty()           ? std::string(status)
                                                      : cat(status, ": ", pass.reason);
    return cat("  ", passNode(node), " [shape=box, label=", quoted(cat(pass.name, "\n", wrapped(why))),
               ", style=\"rounded,filled,dashed\", fillcolor=\"", kCulledFill, "\", color=\"", kCulledLine,
               "\", fontcolor=\"", kCulledLine, "\", tooltip=", quoted(why), "];\n");
}

std::string textureStatement(const TextureRecord& texture, std::size_t node) {
    const bool culled = texture.origin == TextureOrigin::Transient && !texture.allocated;
    std::string label =
        cat(texture.name, "\n", toString(texture.spec.size()), " ", toString(texture.spec.format));
    if (texture.spec.mipLevels > 1) label += cat(", ", texture.spec.mipLevels, " mips");
    if (texture.origin != TextureOrigin::Transient) label += cat("\n", toString(texture.origin));
    std::string marks;
    if (texture.inspected) marks += "inspected";
    if (texture.captured) marks += marks.empty() ? "captured" : ", captured";
    if (!marks.empty()) label += cat("\n[", marks, "]");
    if (culled && !texture.reason.empty())
        label += cat("\n", wrapped(cat("not allocated: ", texture.reason)));

    std::string attributes = cat("shape=ellipse, label=", quoted(label));
    if (culled) {
        attributes += cat(", style=\"filled,dashed\", fillcolor=\"", kCulledFill, "\", color=\"", kCulledLine,
                          "\", fontcolor=\"", kCulledLine, "\"");
        if (!texture.reason.empty()) attributes += cat(", tooltip=", quoted(texture.reason));
    } else {
        attributes += cat(", style=filled, fillcolor=\"", kTextureFill, "\"");
    }
    if (!marks.empty()) attributes += ", peripheries=2";
    return cat("  ", textureNode(node), " [", attributes, "];\n");
}

}  // namespace

std::string topToBottom(std::string dot) {
    if (auto at = dot.find(kLeftToRight); at != std::string::npos)
        dot.replace(at, kLeftToRight.size(), "rankdir=TB");
    return dot;
}

std::string toDot(const FrameReport& report) {
    std::map<std::string, std::size_t, std::less<>> textureIndex;
    for (std::size_t t = 0; t < report.textures.size(); ++t) textureIndex.emplace(report.textures[t].name, t);

    std::string out = "digraph frame {\n";
    out += cat("  graph [", kLeftToRight, ", bgcolor=\"white\", fontname=\"Helvetica\", labelloc=t, label=",
               quoted(cat("frame at ", toString(report.outputSize),
                          report.errors.empty() ? std::string()
                                                : cat(", ", report.errors.size(), " error(s): nothing ran"))),
               "];\n");
    out += "  node [fontname=\"Helvetica\", fontsize=10];\n";
    out += "  edge [fontname=\"Helvetica\", fontsize=9];\n";

    std::size_t ranPosition = 0;
    for (std::size_t p = 0; p < report.passes.size(); ++p) {
        const PassRecord& pass = report.passes[p];
        if (pass.status == PassStatus::Runs) ++ranPosition;
        out += passStatement(pass, p, ranPosition);
    }
    for (std::size_t t = 0; t < report.textures.size(); ++t) out += textureStatement(report.textures[t], t);

    for (std::size_t p = 0; p < report.passes.size(); ++p) {
        const PassRecord& pass = report.passes[p];
        const std::string grey = pass.status == PassStatus::Runs
                                     ? std::string()
                                     : cat(" [color=\"", kCulledLine, "\", style=dashed]");
        for (const TextureUseRecord& read : pass.reads) {
            auto it = textureIndex.find(read.texture);
            if (it == textureIndex.end()) continue;
            out += cat("  ", textureNode(it->second), " -> ", passNode(p), grey, ";\n");
        }
        for (const TextureUseRecord& write : pass.writes) {
            auto it = textureIndex.find(write.texture);
            if (it == textureIndex.end()) continue;
            // A modify reads what is there and adds to it: one edge with arrows at both ends.
            std::string attributes = write.alsoRead ? "dir=both, label=\"modify\"" : std::string();
            if (pass.status != PassStatus::Runs) {
                attributes +=
                    cat(attributes.empty() ? "" : ", ", "color=\"", kCulledLine, "\", style=dashed");
            }
            out += cat("  ", passNode(p), " -> ", textureNode(it->second),
                       attributes.empty() ? std::string() : cat(" [", attributes, "]"), ";\n");
        }
    }
    out += "}\n";
    return out;
}

}  // namespace fx
