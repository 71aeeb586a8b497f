#include "image/pfm_file.hpp"

#include <bit>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <string>
#include <string_view>

#include "base/file_io.hpp"
#include "base/log.hpp"

namespace fx {
namespace {

constexpr bool kHostIsLittleEndian = std::endian::native == std::endian::little;

std::uint32_t swapBytes(std::uint32_t v) {
    return (v >> 24) | ((v >> 8) & 0x0000ff00u) | ((v << 8) & 0x00ff0000u) | (v << 24);
}

// Copies one float's bits in the requested byte order. Going through uint32_t rather than float
// keeps signalling NaNs exactly as they were.
void appendFloatBits(std::string& out, const float& value, bool littleEndian) {
    std::uint32_t bits = 0;
    std::memcpy(&bits, &value, sizeof bits);
    if (littleEndian != kHostIsLittleEndian) bits = swapBytes(bits);
    char bytes[4];
    std::memcpy(bytes, &bits, sizeof bits);
    out.append(bytes, sizeof bytes);
}

// A tiny reader for the three header lines: tokens separated by whitespace.
class HeaderReader {
public:
    explicit HeaderReader(std::string_view text) : text_(text) {}

    std::string_view token() {
        while (pos_ < text_.size() && std::isspace(static_cast<unsigned char>(text_[pos_]))) ++pos_;
        const std::size_t start = pos_;
        while (pos_ < text_.size() && !std::isspace(static_cast<unsigned char>(text_[pos_]))) ++pos_;
        return text_.substr(start, pos_ - start);
    }
    // The header ends with exactly one whitespace character after the scale; the data follows.
    bool skipSingleSeparator() {
        if (pos_ >= text_.size() || !std::isspace(static_cast<unsigned char>(text_[pos_]))) return false;
        ++pos_;
        return true;
    }
    std::size_t position() const { return pos_; }

private:
    std::string_view text_;
    std::size_t pos_ = 0;
};

bool parsePositiveInt(std::string_view token, int& value) {
    const auto [end, ec] = std::from_chars(token.data(), token.data() + token.size(), value);
    return ec == std::errc() && end == token.data() + token.size() && value > 0;
}

}  // namespace

Status writePfm(const std::filesystem::path& path, const FloatImage& image) {
    if (Status shape = checkShape(image, "PFM image"); !shape)
        return Error{cat(path.string(), ": ", shape.error())};
    if (image.empty())
        return Error{cat(path.string(), ": cannot write an empty image (", describeShape(image), ")")};

    const bool grey = image.channels == 1;
    std::string out = cat(grey ? "Pf" : "PF", "\n", image.width, " ", image.height, "\n-1.0\n");
    const std::size_t count = image.texelCount();
    out.reserve(out.size() + count * (grey ? 4 : 12));
    const auto channels = static_cast<std::size_t>(image.channels);
    constexpr float kZero = 0.0f;
    for (std::size_t i = 0; i < count; ++i) {
        const float* texel = &image.texels[i * channels];
        if (grey) {
            appendFloatBits(out, texel[0], true);
            continue;
        }
        appendFloatBits(out, texel[0], true);
        appendFloatBits(out, texel[1], true);
        appendFloatBits(out, channels >= 3 ? texel[2] : kZero, true);  // a 4th channel (alpha) is dropped
    }
    return writeFileAtomically(path, std::string_view(out));
}

Result<FloatImage> readPfm(const std::filesystem::path& path) {
    auto file = readFile(path, file_limits::pfm);
    if (!file) return Error{file.error()};
    const std::string& bytes = *file;
    const std::string where = path.string();

    HeaderReader header(bytes);
    const std::string_view magic = header.token();
    int channels = 0;
    if (magic == "PF")
        channels = 3;
    else if (magic == "Pf")
        channels = 1;
    else
        return Error{cat(where, ": not a PFM file (it starts with neither \"PF\" nor \"Pf\")")};

    int width = 0, height = 0;
    const std::string_view widthToken = header.token(), heightToken = header.token();
    if (!parsePositiveInt(widthToken, width) || !parsePositiveInt(heightToken, height))
        return Error{cat(where, ": bad PFM size \"", widthToken, " ", heightToken, "\"")};

    const std::string scaleToken(header.token());
    char* scaleEnd = nullptr;
    const double scale = std::strtod(scaleToken.c_str(), &scaleEnd);
    if (scaleToken.empty() || *scaleEnd != '\0' || scale == 0.0 || !std::isfinite(scale))
        return Error{cat(where, ": bad PFM scale \"", scaleToken, "\" (a non-zero number is needed)")};
    if (!header.skipSingleSeparator())
        return Error{cat(where, ": PFM header does not end with a line break")};
    const bool littleEndian = scale < 0.0;

    const std::size_t valueCount =
        static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * channels;
    const std::size_t available = bytes.size() - header.position();
    if (available / 4 < valueCount)
        return Error{cat(where, ": PFM data is truncated (", width, "x", height, "x", channels,
                         " floats need ", valueCount * 4, " bytes, the file has ", available, ")")};

    FloatImage image = makeFloatImage(width, height, channels);
    const char* data = bytes.data() + header.position();
    for (std::size_t i = 0; i < valueCount; ++i) {
        std::uint32_t bits = 0;
        std::memcpy(&bits, data + i * 4, sizeof bits);
        if (littleEndian != kHostIsLittleEndian) bits = swapBytes(bits);
        std::memcpy(&image.texels[i], &bits, sizeof bits);
    }
    return image;
}

}  // namespace fx
