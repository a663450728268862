#version 450
// Posed mesh: rigid (one world matrix) or skinned (GPU linear-blend skinning: four joint
// matrices world[joint] * inverseBind, weighted). All matrices of a frame live in one
// storage buffer; the push constants say where this draw's start. Rigid and skinned draws
// are separate pipelines (specialisation constant SKINNED): on CPU devices (lavapipe) a
// uniform branch still costs both sides, and the rigid side is the common one.

layout(constant_id = 0) const bool SKINNED = false;

layout(location = 0) in vec3 inPosition;
layout(location = 1) in vec3 inNormal;
layout(location = 2) in vec2 inUv;
layout(location = 3) in uvec4 inJoints;
layout(location = 4) in vec4 inWeights;

// Rigid draws: matrices[matrixBase] is the world matrix and matrices[matrixBase + 1] its
// normal matrix (transpose of the inverse, upper 3x3), computed once per node on the CPU.
layout(std430, set = 0, binding = 0) readonly buffer Matrices { mat4 matrices[]; };

layout(push_constant) uniform Push {
    mat4 viewProjection;
    vec4 cameraPosition;
    uint matrixBase;
    uint jointCount;  // 0: rigid draw
} pc;

// The fragment shader needs the direction to the camera; camera - world is linear in the
// world position, so interpolating it equals interpolating the position and subtracting.
layout(location = 0) out vec3 outToCamera;
layout(location = 1) out vec3 outNormal;
layout(location = 2) out vec2 outUv;

mat4 jointMatrix(uint joint) { return matrices[pc.matrixBase + min(joint, pc.jointCount - 1u)]; }

void main() {
    vec4 world;
    if (SKINNED) {
        mat4 model = inWeights.x * jointMatrix(inJoints.x) + inWeights.y * jointMatrix(inJoints.y) +
                     inWeights.z * jointMatrix(inJoints.z) + inWeights.w * jointMatrix(inJoints.w);
        world = model * vec4(inPosition, 1.0);
        outNormal = transpose(inverse(mat3(model))) * inNormal;
    } else {
        world = matrices[pc.matrixBase] * vec4(inPosition, 1.0);
        outNormal = mat3(matrices[pc.matrixBase + 1u]) * inNormal;
    }
    outToCamera = pc.cameraPosition.xyz - world.xyz;
    outUv = inUv;
    gl_Position = pc.viewProjection * world;
}
