#pragma once
// One full-screen fragment shader built once per set of compile-time choices, each the first time a
// frame asks for it. Why choices are #defines and not uniforms: llvmpipe shades a whole block of pixels
// with one instruction stream and runs both sides of a branch under a mask, even when the condition is
// a uniform every pixel shares, so a filter chosen by `if (filters == 2)` costs as much as all the
// filters together (measured on the bloom chain: docs/bench.md). A GPU skips a uniform branch, but
// also gains from the dead code its compiler removes. The programs join the runner's registry like
// any other, so F5 and a saved file rebuild them.
//
//   FullscreenVariants up("effects/bloom/upsample.frag", "bloom upsample", bloomShaderDefines());
//   const FullscreenPass& pass = up.get({{"BLOOM_FILTERS", 1}, {"BLOOM_WIDE", 0}});
#include <initializer_list>
#include <map>
#include <memory>
#include <string>
#include <utility>

#include "effects/post/fullscreen_pass.hpp"

namespace fx {

// A compile-time choice: `#define name value`.
using ShaderChoice = std::pair<const char*, int>;

// The lines that make `choices` #defines ("#define BLOOM_FILTERS 2\n..."), for a program built with one
// fixed set of choices.
std::string shaderDefines(std::initializer_list<ShaderChoice> choices);

class FullscreenVariants {
public:
    // `defines` go into every variant (limits shared with the C++ side). Nothing is built until get().
    FullscreenVariants(std::string fragmentShader, std::string label, std::string defines = {});

    // The program for these choices, built on first use; its label names them ("bloom upsample
    // (BLOOM_FILTERS 1, BLOOM_WIDE 0)"). A build that fails stays unusable with its error, like any
    // FullscreenPass (a pass that draws with it is switched off with its error), and is not retried
    // until the file changes (the registry reloads it).
    const FullscreenPass& get(std::initializer_list<ShaderChoice> choices) const;

    // Variants built so far (tests, and what a frame costs to start).
    std::size_t built() const { return built_ ? built_->size() : 0; }

private:
    std::string shader_;
    std::string label_;
    std::string defines_;
    // Behind a pointer, so moving the variants keeps every pass where a frame's pass bodies point.
    std::unique_ptr<std::map<std::string, FullscreenPass>> built_;
};

}  // namespace fx
