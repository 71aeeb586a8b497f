#include "image/png_file.hpp"

#include <climits>
#include <cstring>
#include <memory>
#include <string>

// stb_image and stb_image_write are compiled once in Debian's libstb (linked through
// PkgConfig::STB), so only their declarations are included here: defining the *_IMPLEMENTATION
// macros as well would put a second copy of every stbi_* symbol into the program.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wall"
#pragma GCC diagnostic ignored "-Wextra"
#pragma GCC diagnostic ignored "-Wpedantic"
#pragma GCC diagnostic ignored "-Wshadow"
#include <stb/stb_image.h>
#include <stb/stb_image_write.h>
#pragma GCC diagnostic pop

#include "base/file_io.hpp"
#include "base/log.hpp"

namespace fx {
namespace {

void appendToBuffer(void* context, void* data, int size) {
    auto* buffer = static_cast<std::vector<std::byte>*>(context);
    const auto* bytes = static_cast<const std::byte*>(data);
    buffer->insert(buffer->end(), bytes, bytes + size);
}

struct StbiFree {
    void operator()(unsigned char* pixels) const { stbi_image_free(pixels); }
};

}  // namespace

Result<std::vector<std::byte>> encodePng(const ByteImage& image) {
    if (Status shape = checkShape(image, "PNG image"); !shape) return Error{shape.error()};
    if (image.empty()) return Error{cat("cannot encode an empty image (", describeShape(image), ") as PNG")};
    const ByteImage topDown = flippedVertically(image);
    std::vector<std::byte> buffer;
    const int rowBytes = image.width * image.channels;
    const int written = stbi_write_png_to_func(appendToBuffer, &buffer, image.width, image.height,
                                               image.channels, topDown.texels.data(), rowBytes);
    if (written == 0 || buffer.empty())
        return Error{cat("PNG encoding failed for a ", describeShape(image), " image")};
    return buffer;
}

Status writePng(const std::filesystem::path& path, const ByteImage& image) {
    auto bytes = encodePng(image);
    if (!bytes) return Error{cat(path.string(), ": ", bytes.error())};
    return writeFileAtomically(path, std::span<const std::byte>(*bytes));
}

namespace {

// stb_image decodes; `kind` names what was expected in the error ("PNG image").
Result<ByteImage> decodeEncoded(std::span<const std::byte> encoded, const std::string& what,
                                const char* kind) {
    if (encoded.size() > static_cast<std::size_t>(INT_MAX)) return Error{cat(what, ": file too large")};
    int width = 0, height = 0, channelsInFile = 0;
    // The header first: a small file can claim a huge picture (a 20000 x 20000 PNG of one colour
    // compresses to kilobytes and decodes to 1.6 GB), so the size is checked before anything is decoded.
    if (stbi_info_from_memory(reinterpret_cast<const unsigned char*>(encoded.data()),
                              static_cast<int>(encoded.size()), &width, &height, &channelsInFile))
        if (Status fits = checkImagePixels(width, height, what); !fits) return Error{fits.error()};
    std::unique_ptr<unsigned char, StbiFree> pixels(
        stbi_load_from_memory(reinterpret_cast<const unsigned char*>(encoded.data()),
                              static_cast<int>(encoded.size()), &width, &height, &channelsInFile, 4));
    if (!pixels) {
        const char* reason = stbi_failure_reason();
        return Error{cat(what, ": not a readable ", kind, " (", reason ? reason : "unknown reason", ")")};
    }
    // stb gives rows top-down; fxlab's images run bottom-up like GL's.
    ByteImage topDown = makeByteImage(width, height, 4);
    std::memcpy(topDown.texels.data(), pixels.get(), topDown.texels.size());
    return flippedVertically(topDown);
}

}  // namespace

Status checkImagePixels(std::int64_t width, std::int64_t height, const std::string& what) {
    if (width * height <= kMaxImagePixels) return Status::success();
    return Error{cat(what, ": ", width, " x ", height, " pixels is over the limit for an image (",
                     kMaxImagePixels, " pixels, 8192 x 8192)")};
}

Result<ByteImage> readPng(const std::filesystem::path& path) {
    auto bytes = readFile(path, file_limits::png);
    if (!bytes) return Error{bytes.error()};
    return decodeEncoded(std::as_bytes(std::span(bytes->data(), bytes->size())), path.string(), "PNG image");
}

Result<ByteImage> decodeImage(std::span<const std::byte> encoded, const std::string& what) {
    return decodeEncoded(encoded, what, "image");
}

}  // namespace fx
