#version 450 core
// Where the sharpened picture left [0, 1]: the float target's values above 1 in red, below 0 in blue
// (brighter the further out, full at 1 beyond the range), and the 8-bit target's picture in grey
// where both agree. The RGBA8 target holds none of the red or blue: it clipped them.
// The overshoot lies along silhouettes, a pixel wide: each mark is widened to the largest value
// within a few pixels (one per 250 rows of the target), so it reads on a projector at any size.
layout(binding = 0) uniform sampler2D clipped;  // sharpen.rgba8
layout(binding = 1) uniform sampler2D kept;     // sharpen.float
layout(location = 0) out vec4 color;

void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    ivec2 size = textureSize(kept, 0);
    int reach = clamp(size.y / 250, 1, 4);
    float above = 0.0, below = 0.0;
    for (int y = -reach; y <= reach; ++y) {
        for (int x = -reach; x <= reach; ++x) {
            vec3 f = texelFetch(kept, clamp(p + ivec2(x, y), ivec2(0), size - 1), 0).rgb;
            above = max(above, clamp(max(max(f.r, f.g), f.b) - 1.0, 0.0, 1.0));
            below = max(below, clamp(-min(min(f.r, f.g), f.b), 0.0, 1.0));
        }
    }
    float grey = dot(texelFetch(clipped, p, 0).rgb, vec3(0.2126, 0.7152, 0.0722)) * 0.5;
    color = vec4(vec3(grey) + vec3(above, 0.0, below), 1.0);
}
