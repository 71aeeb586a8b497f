#include "scene/scene_limits.hpp"

#include "base/log.hpp"

namespace fx::scene_limits {

std::string excerpt(std::string_view text) {
    if (text.size() <= kExcerptBytes) return std::string(text);
    std::size_t cut = kExcerptBytes;
    // Back up to the first byte of a UTF-8 character, so the excerpt does not end in half of one.
    while (cut > 0 && (static_cast<unsigned char>(text[cut]) & 0xC0) == 0x80) --cut;
    return cat(text.substr(0, cut), "... (", text.size(), " bytes)");
}

}  // namespace fx::scene_limits
