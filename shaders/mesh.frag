#version 450
// Lighting for sign-language video: hands and face evenly lit. A key light from front-above,
// a softer fill from the other side, a rim light from behind that separates the signer from
// the background, and a sky/ground ambient term. Metallic-roughness is approximated with
// Lambert diffuse plus a normalised Blinn-Phong lobe (key light only) whose exponent follows
// roughness. Specialisation constants drop texture fetches and the alpha-mask discard for
// materials that do not need them: on CPU devices (lavapipe) fragment work dominates, and a
// shader containing `discard` loses early depth testing.

layout(constant_id = 0) const bool HAS_BASE_COLOR_TEXTURE = false;
layout(constant_id = 1) const bool HAS_METALLIC_ROUGHNESS_TEXTURE = false;
layout(constant_id = 2) const bool ALPHA_MASK = false;

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

float diffuseTerm(vec3 direction, vec3 n) { return max(dot(n, -direction), 0.0); }

void main() {
    vec4 base = material.baseColorFactor;
    if (HAS_BASE_COLOR_TEXTURE) base *= texture(baseColorTexture, inUv);
    if (ALPHA_MASK) {
        if (base.a < material.parameters.z) discard;
    }
    if (material.parameters.w < 1.5) base.a = 1.0;  // opaque and mask write full coverage
    float metallic = material.parameters.x;
    float roughness = material.parameters.y;
    if (HAS_METALLIC_ROUGHNESS_TEXTURE) {
        vec4 mr = texture(metallicRoughnessTexture, inUv);
        metallic *= mr.b;
        roughness *= mr.g;
    }
    metallic = clamp(metallic, 0.0, 1.0);
    roughness = clamp(roughness, 0.04, 1.0);

    vec3 n = normalize(inNormal);
    if (!gl_FrontFacing) n = -n;  // double-sided materials light their back faces
    vec3 v = normalize(pc.cameraPosition.xyz - inWorldPosition);

    vec3 diffuse = base.rgb * (1.0 - metallic);
    vec3 f0 = mix(vec3(0.04), base.rgb, metallic);
    float alpha = roughness * roughness;
    float shininess = clamp(2.0 / (alpha * alpha) - 2.0, 1.0, 2048.0);

    float irradiance = lighting.keyDirection.w * diffuseTerm(lighting.keyDirection.xyz, n) +
                       lighting.fillDirection.w * diffuseTerm(lighting.fillDirection.xyz, n) +
                       lighting.rimDirection.w * diffuseTerm(lighting.rimDirection.xyz, n);
    vec3 color = diffuse * (irradiance / PI);
    // Key-light highlight; pow(x, s) ~ exp2(s * 1.4427 * (x - 1)) (spherical Gaussian).
    vec3 l = -lighting.keyDirection.xyz;
    float nDotL = max(dot(n, l), 0.0);
    float nDotH = max(dot(n, normalize(l + v)), 0.0);
    float lobe = (shininess + 8.0) / (8.0 * PI) * exp2(shininess * 1.4427 * (nDotH - 1.0));
    color += f0 * (lighting.keyDirection.w * nDotL * lobe);
    float hemisphere = mix(0.6, 1.0, n.y * 0.5 + 0.5);  // sky above, darker ground bounce
    color += lighting.ambient.x * hemisphere * (diffuse + f0 * 0.5);
    color += material.emissive.rgb;
    outColor = vec4(color, base.a);
}
