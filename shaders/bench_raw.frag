#version 450
layout(location = 0) in vec3 inNormal;
layout(location = 0) out vec4 outColor;
void main() {
    float light = max(dot(normalize(inNormal), normalize(vec3(0.3, 0.5, 1.0))), 0.0);
    outColor = vec4(vec3(0.2 + 0.8 * light), 1.0);
}
