#version 450
// Lighting for sign-language video: hands and face evenly lit. A key light from front-above,
// a softer fill from the other side, a rim light from behind that separates the signer from
// the background, and a sky/ground ambient term. Metallic-roughness is approximated with
// Lambert diffuse plus a normalised Blinn-Phong lobe whose exponent follows roughness.

layout(location = 0) in vec3 inWorldPosition;
layout(location = 1) in vec3 inNormal;
layout(location = 2) in vec2 inUv;

layout(std140, set = 0, binding = 1) uniform Lighting {
    vec4 keyDirection;   // xyz: direction light travels, w: intensity
    vec4 fillDirection;
    vec4 rimDirection;
    vec4 ambient;        // x: intensity
} lighting;

layout(std140, set = 1, binding = 0) uniform MaterialBlock {
    vec4 baseColorFactor;
    vec4 emissive;
    vec4 parameters;     // metallic, roughness, alpha cutoff, alpha mode (0 opaque, 1 mask, 2 blend)
    vec4 textureFlags;
} material;
layout(set = 1, binding = 1) uniform sampler2D baseColorTexture;
layout(set = 1, binding = 2) uniform sampler2D metallicRoughnessTexture;

layout(push_constant) uniform Push {
    mat4 viewProjection;
    vec4 cameraPosition;
    uint matrixBase;
    uint jointCount;
} pc;

layout(location = 0) out vec4 outColor;

const float PI = 3.14159265;

vec3 lightContribution(vec3 direction, float intensity, vec3 n, vec3 v, vec3 diffuse,
                       vec3 f0, float shininess) {
    vec3 l = normalize(-direction);
    float nDotL = max(dot(n, l), 0.0);
    vec3 h = normalize(l + v);
    float specular = (shininess + 8.0) / (8.0 * PI) * pow(max(dot(n, h), 0.0), shininess);
    return intensity * nDotL * (diffuse / PI + f0 * specular);
}

void main() {
    vec4 base = material.baseColorFactor * texture(baseColorTexture, inUv);
    float alphaMode = material.parameters.w;
    if (alphaMode < 0.5) {
        base.a = 1.0;
    } else if (alphaMode < 1.5) {
        if (base.a < material.parameters.z) discard;
        base.a = 1.0;
    }
    vec4 mr = texture(metallicRoughnessTexture, inUv);
    float metallic = clamp(material.parameters.x * mr.b, 0.0, 1.0);
    float roughness = clamp(material.parameters.y * mr.g, 0.04, 1.0);

    vec3 n = normalize(inNormal);
    if (!gl_FrontFacing) n = -n;  // double-sided materials light their back faces
    vec3 v = normalize(pc.cameraPosition.xyz - inWorldPosition);

    vec3 diffuse = base.rgb * (1.0 - metallic);
    vec3 f0 = mix(vec3(0.04), base.rgb, metallic);
    float alpha = roughness * roughness;
    float shininess = clamp(2.0 / (alpha * alpha) - 2.0, 1.0, 2048.0);

    vec3 color = vec3(0.0);
    color += lightContribution(lighting.keyDirection.xyz, lighting.keyDirection.w, n, v,
                               diffuse, f0, shininess);
    color += lightContribution(lighting.fillDirection.xyz, lighting.fillDirection.w, n, v,
                               diffuse, f0, shininess);
    color += lightContribution(lighting.rimDirection.xyz, lighting.rimDirection.w, n, v,
                               diffuse, f0, shininess);
    float hemisphere = mix(0.6, 1.0, n.y * 0.5 + 0.5);  // sky above, darker ground bounce
    color += lighting.ambient.x * hemisphere * (diffuse + f0 * 0.5);
    color += material.emissive.rgb;
    outColor = vec4(color, base.a);
}
