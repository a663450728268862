#version 450
// Raw baseline of `signstim bench render`: the least a draw of a lit mesh needs.
layout(location = 0) in vec3 inPosition;
layout(location = 1) in vec3 inNormal;
layout(push_constant) uniform Push { mat4 viewProjection; } pc;
layout(location = 0) out vec3 outNormal;
void main() {
    outNormal = inNormal;
    gl_Position = pc.viewProjection * vec4(inPosition, 1.0);
}
