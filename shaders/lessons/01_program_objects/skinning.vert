#version 450 core
// Step 4: the skinning product of the chapter on a mesh with many vertices. J blends four joint
// matrices; PARENTHESISED chooses T*(J*p) (two mat4*vec4: 32 mul, 24 add) over (T*J)*p
// (mat4*mat4 then mat4*vec4: 80 mul, 60 add). The result is the same; the cost is not.
#include "../../common/scene_uniforms.glsl"
#include "skinning_bindings.glsl"
layout(location = 0) in vec3 position;
layout(location = 2) in vec3 normal;
layout(location = kJointsLocation) uniform mat4 joints[4];
layout(location = kSpheresPerRowLocation) uniform int spheresPerRow;
layout(location = 2) out vec3 worldNormal;
void main() {
    // Weights from the vertex position: smooth, sum to 1, different for every vertex.
    vec4 w = abs(vec4(position.x, position.y, position.z, 0.5));
    w /= max(w.x + w.y + w.z + w.w, 1e-6);
    mat4 J = w.x * joints[0] + w.y * joints[1] + w.z * joints[2] + w.w * joints[3];
    vec4 p = vec4(position, 1.0);
#ifdef PARENTHESISED
    vec4 world = modelMatrix * (J * p);
#else
    vec4 world = modelMatrix * J * p;
#endif
    // Instances stand in a square grid so that vertex work, not pixels, dominates the pass time.
    int row = max(spheresPerRow, 1);
    vec2 cell = vec2(gl_InstanceID % row, gl_InstanceID / row) - 0.5 * float(row - 1);
    world.xy += vec2(cell.x, -cell.y) * (3.0 / float(row));
    worldNormal = mat3(modelMatrix) * normal;
    gl_Position = viewProjectionMatrix * world;
}
