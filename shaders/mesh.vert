#version 450
// Posed mesh: rigid (one world matrix) or skinned (GPU linear-blend skinning: four joint
// matrices world[joint] * inverseBind, weighted). All matrices of a frame live in one
// storage buffer; the push constants say where this draw's start.

layout(location = 0) in vec3 inPosition;
layout(location = 1) in vec3 inNormal;
layout(location = 2) in vec2 inUv;
layout(location = 3) in uvec4 inJoints;
layout(location = 4) in vec4 inWeights;

layout(std430, set = 0, binding = 0) readonly buffer Matrices { mat4 matrices[]; };

layout(push_constant) uniform Push {
    mat4 viewProjection;
    vec4 cameraPosition;
    uint matrixBase;
    uint jointCount;  // 0: rigid draw
} pc;

layout(location = 0) out vec3 outWorldPosition;
layout(location = 1) out vec3 outNormal;
layout(location = 2) out vec2 outUv;

mat4 jointMatrix(uint joint) { return matrices[pc.matrixBase + min(joint, pc.jointCount - 1u)]; }

void main() {
    mat4 model;
    if (pc.jointCount == 0u) {
        model = matrices[pc.matrixBase];
    } else {
        model = inWeights.x * jointMatrix(inJoints.x) + inWeights.y * jointMatrix(inJoints.y) +
                inWeights.z * jointMatrix(inJoints.z) + inWeights.w * jointMatrix(inJoints.w);
    }
    vec4 world = model * vec4(inPosition, 1.0);
    outWorldPosition = world.xyz;
    outNormal = transpose(inverse(mat3(model))) * inNormal;
    outUv = inUv;
    gl_Position = pc.viewProjection * world;
}
