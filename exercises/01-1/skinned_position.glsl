// Exercise 01-1: the skinning product (lessons/01_program_objects/lesson.md, step 4).
// A vertex follows four joints: their matrices are blended by the vertex's weights into one J, and the
// vertex goes to the world as T * (J * p), where T is the object's model matrix and p the position as
// a point. `./fxlab check 01 1` puts many vertices, joints and weights through both functions.

// J = w.x joints[0] + w.y joints[1] + w.z joints[2] + w.w joints[3] (the weights sum to 1).
mat4 blendJoints(mat4 joints[4], vec4 weights) {
    // TODO
    return mat4(1.0);
}

// The vertex in the world: the model matrix after the blended joints. What is p's fourth coordinate?
vec4 skinnedWorld(mat4 model, mat4 blended, vec3 position) {
    // TODO
    return vec4(position, 1.0);
}
