#pragma once
// What every fuzz target shares: the libFuzzer entry point's signature and where the shipped files
// (the seeds, and what the scene and glTF targets resolve paths against) are.
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string_view>

#include "base/paths.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size);

namespace fuzz {

inline std::string_view text(const std::uint8_t* data, std::size_t size) {
    return {reinterpret_cast<const char*>(data), size};
}

}  // namespace fuzz
