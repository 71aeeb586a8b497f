// Diffuse light from one directional light plus ambient, in linear HDR. A zero-length normal
// (degenerate geometry) is not normalised: it gets ambient light only.
vec3 diffuseLighting(vec3 normal, vec3 albedo) {
    float len = length(normal);
    float lambert = len > 1e-6 ? max(dot(normal / len, toLight), 0.0) : 0.0;
    return albedo * (ambientLight + lightColor * lambert);
}
