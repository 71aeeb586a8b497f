#include "render/dead_stack.hpp"

#include <algorithm>
#include <cstddef>
#include <iterator>

namespace fx {

namespace detail {

void poisonStackBelowOwnFrame() {
    std::uint32_t words[kDeadStackBytes / sizeof(std::uint32_t)];
    std::fill(std::begin(words), std::end(words), kDeadStackWord);
    // The array is dead after the fill, so without this the compiler may drop the stores.
    asm volatile("" : : "r"(words) : "memory");
}

}  // namespace detail
}  // namespace fx
