#version 450 core
// The engine's own user-interface queue (Shader effects chapter §3.4: drawn last, straight into the window,
// with the depth test off): a translucent panel with a light border and a sun disc. Its colours are
// display values already, so nothing after the output transform may touch them.
#include "post_bindings.glsl"

layout(location = kUiPanelLocation) uniform vec4 panel;  // x, y, width, height of the panel in window pixels
layout(location = 0) out vec4 color;

void main() {
    vec2 p = gl_FragCoord.xy - panel.xy;
    vec2 size = max(panel.zw, vec2(1.0));
    bool border = p.x < 1.0 || p.y < 1.0 || p.x >= size.x - 1.0 || p.y >= size.y - 1.0;
    color = border ? vec4(0.92, 0.92, 0.95, 0.9) : vec4(0.08, 0.09, 0.12, 0.6);
    // A sun disc on the left: the lesson is about the sun's shadows.
    float radius = 0.3 * size.y;
    if (!border && distance(p, vec2(0.5 * size.y, 0.5 * size.y)) < radius) color = vec4(1.0, 0.85, 0.45, 0.95);
}
