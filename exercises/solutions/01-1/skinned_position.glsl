// Exercise 01-1, a solution. The weights blend the matrices (a weighted sum), and a position is a
// point: w = 1, so the joints' and the model's translations reach it.
mat4 blendJoints(mat4 joints[4], vec4 weights) {
    return weights.x * joints[0] + weights.y * joints[1] + weights.z * joints[2] + weights.w * joints[3];
}

vec4 skinnedWorld(mat4 model, mat4 blended, vec3 position) {
    return model * (blended * vec4(position, 1.0));  // two mat4 x vec4, never a mat4 x mat4
}
