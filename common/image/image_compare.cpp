#include "image/image_compare.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>

#include "base/log.hpp"

namespace fx {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

template <class Texel>
Status checkComparable(const Image<Texel>& a, const Image<Texel>& b) {
    if (Status shape = checkShape(a, "first image"); !shape) return shape;
    if (Status shape = checkShape(b, "second image"); !shape) return shape;
    if (a.width != b.width || a.height != b.height || a.channels != b.channels)
        return Error{
            cat("cannot compare images of different shapes: ", describeShape(a), " and ", describeShape(b))};
    return Status::success();
}

// Returns +inf for the unbounded cases described in the header.
double valueDifference(float a, float b) {
    if (std::isnan(a) || std::isnan(b)) return kInfinity;
    if (std::isinf(a) || std::isinf(b)) return a == b ? 0.0 : kInfinity;
    return std::abs(static_cast<double>(a) - static_cast<double>(b));
}

double valueDifference(std::uint8_t a, std::uint8_t b) {
    return std::abs(int(a) - int(b));
}

template <class Texel>
Result<ImageDifference> compareImages(const Image<Texel>& a, const Image<Texel>& b, double peak) {
    if (Status comparable = checkComparable(a, b); !comparable) return Error{comparable.error()};
    ImageDifference result;
    double sumOfSquares = 0.0;
    const std::size_t count = a.texelCount();
    const auto channels = static_cast<std::size_t>(a.channels);
    for (std::size_t i = 0; i < count; ++i) {
        bool differs = false, unbounded = false;
        for (std::size_t c = 0; c < channels; ++c) {
            const double d = valueDifference(a.texels[i * channels + c], b.texels[i * channels + c]);
            if (d == 0.0) continue;
            differs = true;
            unbounded = unbounded || std::isinf(d);
            sumOfSquares += d * d;
            result.maxAbs = std::max(result.maxAbs, d);
        }
        result.differingTexels += differs ? 1 : 0;
        result.nonFiniteTexels += unbounded ? 1 : 0;
    }
    const std::size_t valueCount = count * channels;
    const double meanSquare = valueCount > 0 ? sumOfSquares / static_cast<double>(valueCount) : 0.0;
    result.rmse = std::sqrt(meanSquare);
    // meanSquare == 0 gives +inf and an infinite meanSquare gives -inf, both as intended.
    result.psnr = meanSquare == 0.0 ? kInfinity : 10.0 * std::log10(peak * peak / meanSquare);
    return result;
}

}  // namespace

Result<ImageDifference> compare(const FloatImage& a, const FloatImage& b) {
    return compareImages(a, b, 1.0);
}

Result<ImageDifference> compare(const ByteImage& a, const ByteImage& b) {
    return compareImages(a, b, 255.0);
}

Result<ByteImage> differenceImage(const ByteImage& expected, const ByteImage& actual) {
    if (Status comparable = checkComparable(expected, actual); !comparable) return Error{comparable.error()};
    const ByteImage background = toRgba(expected);
    ByteImage picture = makeByteImage(expected.width, expected.height, 4, 255);
    const std::size_t count = expected.texelCount();
    const auto channels = static_cast<std::size_t>(expected.channels);
    for (std::size_t i = 0; i < count; ++i) {
        int largest = 0;
        for (std::size_t c = 0; c < channels; ++c)
            largest = std::max(largest, std::abs(int(expected.texels[i * channels + c]) -
                                                 int(actual.texels[i * channels + c])));
        std::uint8_t* out = &picture.texels[i * 4];
        if (largest == 0) {
            // Rec. 709 luma of the expected picture at a quarter brightness: the scene stays
            // recognisable without competing with the red.
            const std::uint8_t* in = &background.texels[i * 4];
            const auto grey = static_cast<std::uint8_t>((54 * in[0] + 183 * in[1] + 19 * in[2]) / (256 * 4));
            out[0] = out[1] = out[2] = grey;
        } else {
            out[0] = static_cast<std::uint8_t>(std::min(255, 128 + largest * 8));
            out[1] = 0;
            out[2] = 0;
        }
    }
    return picture;
}

}  // namespace fx
