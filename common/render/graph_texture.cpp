#include "render/graph_texture.hpp"

namespace fx {

std::string_view toString(TextureUsage usage) {
    switch (usage) {
        case TextureUsage::Sampled:
            return "sampled texture";
        case TextureUsage::ColorAttachment:
            return "colour attachment";
        case TextureUsage::DepthAttachment:
            return "depth attachment";
        case TextureUsage::Storage:
            return "storage image";
    }
    return "?";
}

std::string_view toString(TextureOrigin origin) {
    switch (origin) {
        case TextureOrigin::Transient:
            return "transient";
        case TextureOrigin::Imported:
            return "imported";
        case TextureOrigin::PresentedOutput:
            return "presented output";
    }
    return "?";
}

}  // namespace fx
