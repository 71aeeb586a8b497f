// The sun's diffuse light with its shadow, plus ambient, in linear HDR. Include after
// scene_uniforms.glsl and shadow_lookup.glsl. The sun's part is scaled by shadowVisibility(); the
// ambient part is not (a shadow is where only the sky's light arrives). A zero-length normal
// (degenerate geometry) gets ambient light only.
vec3 shadowedLighting(vec3 worldNormal, vec3 worldPosition, vec3 albedo) {
    float len = length(worldNormal);
    vec3 n = len > 1e-6 ? worldNormal / len : vec3(0.0);
    float lambert = max(dot(n, toLight), 0.0);
    float visibility = lambert > 0.0 ? shadowVisibility(worldPosition, n) : 1.0;
    return albedo * (ambientLight + lightColor * lambert * visibility);
}
