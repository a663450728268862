// The body of shaders/mesh.vert and shaders/mesh_morph.vert (this file is #included; MORPH
// is defined in the second).
//
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

#ifdef MORPH
// Morph targets (glTF 2.0 §3.7.2.2), applied before skinning. The CPU sums the weighted
// displacements of the vertices some target moves (renderer/vk_morph.hpp): morphSlots[vertex]
// is the vertex's index among its primitive's moved vertices, or ~0u when no target moves it
// (most of a body: only the face moves); its morphed position and normal are then the pair at
// pc.morphBase + 2 * slot of this frame's buffer.
layout(std430, set = 0, binding = 1) readonly buffer Morphed { vec4 morphed[]; };
layout(std430, set = 2, binding = 0) readonly buffer MorphSlots { uint morphSlots[]; };
#endif

layout(push_constant) uniform Push {
    mat4 viewProjection;
    vec4 cameraPosition;
    uint matrixBase;
    uint jointCount;  // 0: rigid draw
    uint morphBase;   // this draw's first morphed vec4 in `morphed`
    uint morphCount;  // 1: morphed (mesh_morph.vert), 0: not
} pc;

// The fragment shader needs the direction to the camera; camera - world is linear in the
// world position, so interpolating it equals interpolating the position and subtracting.
layout(location = 0) out vec3 outToCamera;
layout(location = 1) out vec3 outNormal;
layout(location = 2) out vec2 outUv;

mat4 jointMatrix(uint joint) { return matrices[pc.matrixBase + min(joint, pc.jointCount - 1u)]; }

void main() {
    vec3 position = inPosition;
    vec3 normal = inNormal;
#ifdef MORPH
    const uint slot = morphSlots[gl_VertexIndex];  // gl_VertexIndex includes the vertex offset
    if (slot != 0xFFFFFFFFu) {
        position = morphed[pc.morphBase + 2u * slot].xyz;
        normal = morphed[pc.morphBase + 2u * slot + 1u].xyz;
    }
#endif
    vec4 world;
    if (SKINNED) {
        mat4 model = inWeights.x * jointMatrix(inJoints.x) + inWeights.y * jointMatrix(inJoints.y) +
                     inWeights.z * jointMatrix(inJoints.z) + inWeights.w * jointMatrix(inJoints.w);
        world = model * vec4(position, 1.0);
        outNormal = transpose(inverse(mat3(model))) * normal;
    } else {
        world = matrices[pc.matrixBase] * vec4(position, 1.0);
        outNormal = mat3(matrices[pc.matrixBase + 1u]) * normal;
    }
    outToCamera = pc.cameraPosition.xyz - world.xyz;
    outUv = inUv;
    gl_Position = pc.viewProjection * world;
}
