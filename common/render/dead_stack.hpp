#pragma once
// Pass bodies run in FrameGraph::execute, after the function that declared them (a lesson's
// buildFrame, an effect's declare) has returned. A body that captured one of that function's locals
// by reference (`[&]`) then reads stack memory that is no longer its own: usually the old value
// is still there and the bug stays hidden until an unrelated change moves it.
//
// execute() therefore first fills the stack below its caller, where those returned frames were, with
// a poison word. A dangling reference then reads the poison instead of a plausible leftover:
// a texture handle reads kDeadStackWord, which PassContext recognises and stops the program on with
// the pass's name; a float reads NaN (the smoke tests fail on NaN); a pointer reads a non-canonical
// address and faults at once. See docs/frame-graph.md, "What a pass body may capture".
#include <cstddef>
#include <cstdint>

namespace fx {

// As a float: a NaN. Twice, as a pointer: non-canonical on x86-64. As a texture handle: no frame
// has four billion textures.
inline constexpr std::uint32_t kDeadStackWord = 0xFFF5A5A5u;
// How much stack below the caller is poisoned: far more than buildFrame and the declare functions
// it calls use.
inline constexpr std::size_t kDeadStackBytes = 32 * 1024;

namespace detail {
// The portable fill: a frame of its own filled with the poison. It misses the slot right below the
// caller's return address (alignment and saved registers), which the x86-64 fill reaches.
[[gnu::noinline]] void poisonStackBelowOwnFrame();
}  // namespace detail

// Fills the kDeadStackBytes below the caller's stack pointer with kDeadStackWord. Always inlined, so
// "the caller" is the function that calls it (FrameGraph::execute is inlined too). Nothing lives
// there: a function's locals are above its stack pointer, and the only function allowed below it
// (the x86-64 red zone) is a leaf, which a caller of execute() is not.
[[gnu::always_inline]] inline void poisonDeadStack() {
#if defined(__x86_64__)
    void* end = nullptr;
    std::size_t words = kDeadStackBytes / sizeof(std::uint32_t);
    asm volatile(
        "lea -%c[bytes](%%rsp), %%rdi\n\t"
        "rep stosl"
        : "=&D"(end), "+c"(words)
        : [bytes] "i"(kDeadStackBytes), "a"(kDeadStackWord)
        : "memory");
#else
    detail::poisonStackBelowOwnFrame();
#endif
}

}  // namespace fx
