#pragma once
// The generated textures. Rows run bottom-up like every fx::ByteImage (the PNG writer flips them).
#include "image/image.hpp"

namespace fx::assetgen {

// res/textures/ground_checker.png: 256x256 RGB, sRGB-encoded albedo. 8x8 checks in two warm greys
// with a faint darker seam between them and a little per-check variation; tiles seamlessly.
ByteImage groundChecker();

// res/textures/cloud_density.png: 512x512 grey, tileable fBm with the statistics of the Clouds chapter's
// density texture (stored values: mean about 0.45, sd about 0.18, median 0.47, max 230/255; blobs 40 to 60
// px across). The values are sRGB-encoded: sample the texture through an sRGB format (or decode
// v^2.2) to get the lesson's scattered clouds rather than an overcast sky.
ByteImage cloudDensity();

// The quantiles the cloud density is shaped to: (fraction of texels, stored value / 255).
struct Quantile {
    float fraction;
    float value;
};
extern const Quantile kCloudQuantiles[8];

// res/textures/fire_sprite.png: 256x256 RGBA. RGB is a warm white; alpha is a soft teardrop flame
// (round base around v = 0.27, tapering to a point near v = 0.95, v = 0 at the bottom) whose edge
// falls off over the outer 15 % of its half-width. Only the alpha shapes the particle (Shader effects §3.8).
ByteImage fireSprite();

// res/textures/crate_planks.png: 256x256 RGB wooden planks with a frame, for the crate prop.
ByteImage cratePlanks();

// res/textures/suit_fabric.png: 256x256 RGB light woven pattern that the character's suit colour
// multiplies; tiles seamlessly.
ByteImage suitFabric();

// res/textures/cutout_lattice.png: 128x128 RGBA lattice for an alpha-tested (cut-out) material: 2x2
// square holes of alpha 0 (48 texels across) between opaque bars 16 texels wide, RGB a pale wicker
// colour. No partly transparent texels, so any cutoff in (0, 1] cuts the same holes (Shader effects §2).
ByteImage cutoutLattice();

}  // namespace fx::assetgen
