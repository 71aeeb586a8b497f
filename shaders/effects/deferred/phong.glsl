// The lecture's three lighting terms for the scene's directional light, per pixel: ambient
// k_amb * l_amb, diffuse max(n.l, 0) * k_diff * l_diff, specular max(n.h, 0)^shininess * k_spec * l_spec
// (no specular where n.l <= 0). The light and camera come from scene_uniforms.glsl.
struct PhongTerms {
    vec3 ambient;
    vec3 diffuse;
    vec3 specular;
};

const float kPhongSpecular = 0.3;   // k_spec: a grey highlight on every material
const float kPhongShininess = 40.0; // the lecture's object shininess

PhongTerms phongTerms(vec3 normal, vec3 worldPosition, vec3 albedo) {
    PhongTerms t;
    t.ambient = albedo * ambientLight;
    float len = length(normal);
    vec3 n = len > 1e-6 ? normal / len : vec3(0.0);  // a zero normal gets ambient light only
    float lambert = max(dot(n, toLight), 0.0);
    t.diffuse = albedo * lightColor * lambert;
    vec3 toEye = cameraPosition - worldPosition;
    float eyeDistance = length(toEye);
    vec3 v = eyeDistance > 1e-6 ? toEye / eyeDistance : n;
    vec3 h = toLight + v;
    float hLength = length(h);  // 0 when the light is exactly behind the surface on the eye ray
    float nh = hLength > 1e-6 ? max(dot(n, h / hLength), 0.0) : 0.0;
    t.specular = lambert > 0.0 ? kPhongSpecular * lightColor * pow(nh, kPhongShininess) : vec3(0.0);
    return t;
}
