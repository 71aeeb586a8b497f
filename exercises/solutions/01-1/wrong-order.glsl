// Exercise 01-1, a typical wrong answer: the matrices in the wrong order (the joints after the model).
mat4 blendJoints(mat4 joints[4], vec4 weights) {
    return weights.x * joints[0] + weights.y * joints[1] + weights.z * joints[2] + weights.w * joints[3];
}

vec4 skinnedWorld(mat4 model, mat4 blended, vec3 position) {
    return blended * (model * vec4(position, 1.0));
}
