// The shadow passes' own uniforms and the shadowed scene's, written once for the shaders and the C++ (effects/shadow/
// shadow_bindings.hpp). The scene uniforms they share with every lit shader are scene_bindings.glsl's.
const int kAlphaCutoffLocation = 5;      // shadow_depth.frag: texels below it are cut out (float)
const int kDepthViewRangeLocation = 0;   // shadow_depth_view.frag: near and far of the map, metres (vec2)
const int kDepthViewTargetSizeLocation = 1;  // shadow_depth_view.frag: the view's size in pixels (vec2)
const int kEncodeForDisplayLocation = 31;  // shadowed_scene.frag: 1 ends with the display encoding (int)
