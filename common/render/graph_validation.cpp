// Checks that need no ordering: every texture has a size, and every pass writes formats its usage
// can take and attachments GL can put in one framebuffer.
#include <algorithm>

#include "base/log.hpp"
#include "render/graph_compiler.hpp"

namespace fx {
namespace {

// GL 4.5 guarantees GL_MAX_COLOR_ATTACHMENTS and GL_MAX_DRAW_BUFFERS of at least 8.
constexpr std::size_t kMaxColorAttachments = 8;

bool isWindowFramebuffer(const GraphTexture& t) {
    return t.view.origin == TextureOrigin::PresentedOutput && t.view.native == 0;
}

std::string formatError(const Pass& pass, const GraphTexture& t, TextureUsage usage) {
    TextureFormat format = t.view.spec.format;
    std::string_view problem;
    switch (usage) {
        case TextureUsage::ColorAttachment:
            if (!isColorRenderable(format)) problem = "is not colour-renderable";
            break;
        case TextureUsage::DepthAttachment:
            if (!isDepth(format)) problem = "is not a depth format";
            break;
        case TextureUsage::Storage:
            if (!isStorageCompatible(format)) problem = "cannot be used for image load/store";
            break;
        case TextureUsage::Sampled:
            break;
    }
    if (problem.empty()) return {};
    return cat("pass '", pass.name(), "' writes '", t.view.name, "' as a ", toString(usage),
               ", but its format ", toString(format), " ", problem);
}

}  // namespace

std::vector<std::string> validateTextureSizes(const std::vector<GraphTexture>& textures, Size2D output) {
    std::vector<std::string> errors;
    for (const auto& t : textures) {
        if (!t.transient()) continue;
        const TextureSize& size = t.desc.size;
        if (size.relativeToOutput() && size.second() <= 0) {
            errors.push_back(cat("texture '", t.view.name, "' is sized ", size.first(), "/", size.second(),
                                 " of the output; the denominator must be positive"));
            continue;
        }
        const TextureSpec& spec = t.view.spec;
        if (!output.empty() && (spec.width <= 0 || spec.height <= 0)) {
            errors.push_back(cat("texture '", t.view.name, "' (", toString(size), ") resolves to ",
                                 spec.width, "x", spec.height, " at output ", toString(output),
                                 "; a texture needs at least 1x1"));
        }
    }
    return errors;
}

std::vector<std::string> validatePassTargets(const PassList& passes,
                                             const std::vector<GraphTexture>& textures, Size2D output) {
    std::vector<std::string> errors;
    auto nameOf = [&](TextureHandle h) { return textures[h.index].view.name; };
    for (const auto& passPtr : passes) {
        const Pass& pass = *passPtr;
        std::vector<TextureHandle> attachments;
        std::vector<TextureHandle> depth;
        const GraphTexture* window = nullptr;
        for (const auto& a : pass.accesses()) {
            const GraphTexture& t = textures[a.texture.index];
            if (a.writes) {
                std::string error = formatError(pass, t, a.usage);
                if (!error.empty()) errors.push_back(std::move(error));
            }
            // GL leaves sampling a texture attached to the bound framebuffer undefined (a feedback
            // loop): the draw may read what it is writing, or what it wrote a moment ago. A modify
            // reads through blending, which is defined; only a sampled read is refused.
            if (a.sampled && a.writes && !a.otherLevel &&
                (a.usage == TextureUsage::ColorAttachment || a.usage == TextureUsage::DepthAttachment)) {
                errors.push_back(cat(
                    "pass '", pass.name(), "' samples '", t.view.name, "' and renders into it as its ",
                    toString(a.usage),
                    ": a feedback loop, undefined in GL. Render into another texture, or declare readOtherLevel if the pass samples another mip level than it writes"));
            }
            if (isWindowFramebuffer(t)) {
                window = &t;
                if (a.onlyReads()) {
                    errors.push_back(cat("pass '", pass.name(), "' samples '", t.view.name,
                                         "', the window's framebuffer, which cannot be read as a texture"));
                } else if (a.usage == TextureUsage::Storage) {
                    errors.push_back(
                        cat("pass '", pass.name(), "' writes '", t.view.name,
                            "', the window's framebuffer, as a storage image, which GL cannot do"));
                }
            }
            if (a.writes && a.usage == TextureUsage::DepthAttachment) depth.push_back(a.texture);
            if (a.writes &&
                (a.usage == TextureUsage::ColorAttachment || a.usage == TextureUsage::DepthAttachment)) {
                attachments.push_back(a.texture);
            }
        }
        std::size_t colourCount = attachments.size() - depth.size();
        if (colourCount > kMaxColorAttachments) {
            errors.push_back(cat("pass '", pass.name(), "' has ", colourCount,
                                 " colour attachments; GL 4.5 guarantees ", kMaxColorAttachments));
        }
        if (depth.size() > 1) {
            errors.push_back(cat("pass '", pass.name(), "' has ", depth.size(), " depth attachments ('",
                                 nameOf(depth[0]), "', '", nameOf(depth[1]), "'); a framebuffer has one"));
        }
        if (window != nullptr && attachments.size() > 1) {
            for (TextureHandle h : attachments) {
                if (&textures[h.index] == window) continue;
                errors.push_back(
                    cat("pass '", pass.name(), "' draws into '", window->view.name,
                        "', the window's framebuffer, and also into '", nameOf(h),
                        "'; the window's framebuffer cannot share a pass with texture attachments"));
                break;
            }
        }
        // GL would draw only where all attachments overlap; in a lesson that is always a mistake.
        if (!output.empty() && attachments.size() > 1) {
            const TextureView& first = textures[attachments[0].index].view;
            for (TextureHandle h : attachments) {
                const TextureView& other = textures[h.index].view;
                if (other.size() == first.size()) continue;
                errors.push_back(cat("pass '", pass.name(), "' draws into '", first.name, "' (",
                                     toString(first.size()), ") and '", other.name, "' (",
                                     toString(other.size()),
                                     "); the attachments of one pass must have one size"));
                break;
            }
        }
    }
    return errors;
}

}  // namespace fx
