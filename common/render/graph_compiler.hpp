#pragma once
// The steps FrameGraph::compile runs, as functions over the frame's declarations, so each rule sits
// in one small file: validation (graph_validation.cpp), who writes what and in which order
// (graph_dependencies.cpp), what runs and why not (graph_culling.cpp), and when each transient
// texture is acquired and released (graph_lifetimes.cpp).
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "render/frame_report.hpp"
#include "render/graph_order.hpp"
#include "render/graph_texture.hpp"
#include "render/pass.hpp"

namespace fx {

struct GraphTexture {
    TextureView view;  // name, origin, spec (resolved at compile for transients), native handle
    TextureDesc desc;  // as declared; transients only
    // Imports: the size rule the texture follows, when it follows the output (the traffic model takes it
    // at the model's size); none: its own size.
    std::optional<TextureSize> importedSize;
    bool inspected = false;
    bool captured = false;
    // Roots keep their writers alive: imports (their content outlives the frame, the presented
    // output among them), captures and inspected textures.
    bool root() const { return view.origin != TextureOrigin::Transient || inspected || captured; }
    bool transient() const { return view.origin == TextureOrigin::Transient; }
};

using PassList = std::vector<std::unique_ptr<Pass>>;

// Who touches one texture, each list in declaration order.
struct TextureRoles {
    std::vector<std::uint32_t> creators;   // write without reading
    std::vector<std::uint32_t> modifiers;  // read and write
    std::vector<std::uint32_t> readers;    // read only
};

struct PassVerdict {
    PassStatus status = PassStatus::Runs;
    std::string reason;
};

struct CompiledGraph {
    std::vector<TextureRoles> roles;                        // per texture
    std::vector<std::optional<std::uint32_t>> producer;     // per texture: the creator that counts
    std::vector<std::uint32_t> derivedOrder;                // every pass
    std::vector<std::uint32_t> executionOrder;              // passes that run
    std::vector<PassVerdict> verdicts;                      // per pass
    std::vector<std::vector<std::uint32_t>> acquireBefore;  // per pass: transients first written there
    std::vector<std::vector<std::uint32_t>> releaseAfter;   // per pass: transients last used there
    std::vector<std::uint32_t> retained;                    // transients kept until the frame ends
};

// graph_validation.cpp: sizes, formats, attachments.
std::vector<std::string> validateTextureSizes(const std::vector<GraphTexture>& textures, Size2D output);
std::vector<std::string> validatePassTargets(const PassList& passes,
                                             const std::vector<GraphTexture>& textures, Size2D output);

// graph_dependencies.cpp
std::vector<TextureRoles> collectRoles(const PassList& passes, std::size_t textureCount);
std::vector<std::string> validateWriters(const PassList& passes, const std::vector<GraphTexture>& textures,
                                         const std::vector<TextureRoles>& roles);
std::vector<OrderConstraint> orderConstraints(const std::vector<TextureRoles>& roles);
std::string describeCycle(const TopologicalOrder& order, const PassList& passes,
                          const std::vector<GraphTexture>& textures);
// The creator whose output readers get: the one that is switched on, else the first declared.
std::optional<std::uint32_t> activeCreator(const TextureRoles& roles, const PassList& passes);

// graph_culling.cpp: fills producer, verdicts and executionOrder from derivedOrder.
void decideWhatRuns(const PassList& passes, const std::vector<GraphTexture>& textures, CompiledGraph& graph);

// graph_lifetimes.cpp: fills acquireBefore, releaseAfter and retained from executionOrder.
void planLifetimes(const PassList& passes, const std::vector<GraphTexture>& textures, CompiledGraph& graph);

// Quoted, comma-separated names ending in "and": 'a', 'b' and 'c'.
std::string quotedList(const std::vector<std::string>& names);
std::string passNames(const PassList& passes, const std::vector<std::uint32_t>& indices);

}  // namespace fx
