#version 450
// Lighting for sign-language video: hands and face evenly lit. A key light from front-above,
// a softer fill from the other side, a rim light from behind that separates the signer from
// the background, and a sky/ground ambient term. Metallic-roughness is approximated with
// Lambert diffuse plus a normalised Blinn-Phong lobe (key light only) whose exponent follows
// roughness.
//
// On CPU devices (lavapipe) fragment work dominates the frame, and every uniform-buffer or
// push-constant read costs a bounds-checked scalar load per shader invocation (measured: the
// ~30 such reads of the former uniform-block version cost as much as the lighting itself).
// So the lighting (fixed per Renderer) and the material factors (fixed per material) are
// specialisation constants, folded into each material's pipeline; for untextured materials
// the diffuse/specular/ambient colours and the lobe exponent are precomputed on the CPU
// (vk::materialConstants, same formulas as the textured path below). Specialisation also
// drops texture fetches and the alpha-mask `discard` (which would disable early depth) for
// materials that do not need them. Ids match vk::FragmentConstants (renderer/vk_scene.hpp).

layout(constant_id = 0) const bool HAS_BASE_COLOR_TEXTURE = false;
layout(constant_id = 1) const bool HAS_METALLIC_ROUGHNESS_TEXTURE = false;
layout(constant_id = 2) const bool ALPHA_MASK = false;
layout(constant_id = 3) const bool ALPHA_BLEND = false;
// Material factors.
layout(constant_id = 4) const float BASE_R = 1.0;
layout(constant_id = 5) const float BASE_G = 1.0;
layout(constant_id = 6) const float BASE_B = 1.0;
layout(constant_id = 7) const float BASE_A = 1.0;
layout(constant_id = 8) const float EMISSIVE_R = 0.0;
layout(constant_id = 9) const float EMISSIVE_G = 0.0;
layout(constant_id = 10) const float EMISSIVE_B = 0.0;
layout(constant_id = 11) const float METALLIC = 1.0;
layout(constant_id = 12) const float ROUGHNESS = 1.0;
layout(constant_id = 13) const float ALPHA_CUTOFF = 0.5;
// Derived from the factors (untextured materials only).
layout(constant_id = 14) const float DIFFUSE_OVER_PI_R = 0.0;  // base * (1 - metallic) / PI
layout(constant_id = 15) const float DIFFUSE_OVER_PI_G = 0.0;
layout(constant_id = 16) const float DIFFUSE_OVER_PI_B = 0.0;
layout(constant_id = 17) const float SPECULAR_R = 0.0;  // f0 * (shininess + 8) / (8 PI)
layout(constant_id = 18) const float SPECULAR_G = 0.0;
layout(constant_id = 19) const float SPECULAR_B = 0.0;
layout(constant_id = 20) const float EXPONENT = 1.0;    // shininess * log2(e)
layout(constant_id = 21) const float AMBIENT_COLOR_R = 0.0;  // diffuse + f0 / 2
layout(constant_id = 22) const float AMBIENT_COLOR_G = 0.0;
layout(constant_id = 23) const float AMBIENT_COLOR_B = 0.0;
// Lighting: unit directions towards the lights and intensities.
layout(constant_id = 24) const float TO_KEY_X = 0.0;
layout(constant_id = 25) const float TO_KEY_Y = 0.0;
layout(constant_id = 26) const float TO_KEY_Z = 1.0;
layout(constant_id = 27) const float KEY_INTENSITY = 1.0;
layout(constant_id = 28) const float TO_FILL_X = 0.0;
layout(constant_id = 29) const float TO_FILL_Y = 0.0;
layout(constant_id = 30) const float TO_FILL_Z = 1.0;
layout(constant_id = 31) const float FILL_INTENSITY = 0.0;
layout(constant_id = 32) const float TO_RIM_X = 0.0;
layout(constant_id = 33) const float TO_RIM_Y = 0.0;
layout(constant_id = 34) const float TO_RIM_Z = 1.0;
layout(constant_id = 35) const float RIM_INTENSITY = 0.0;
layout(constant_id = 36) const float AMBIENT = 0.0;

const vec4 baseColorFactor = vec4(BASE_R, BASE_G, BASE_B, BASE_A);
const vec3 emissive = vec3(EMISSIVE_R, EMISSIVE_G, EMISSIVE_B);
const vec3 toKey = vec3(TO_KEY_X, TO_KEY_Y, TO_KEY_Z);
const vec3 toFill = vec3(TO_FILL_X, TO_FILL_Y, TO_FILL_Z);
const vec3 toRim = vec3(TO_RIM_X, TO_RIM_Y, TO_RIM_Z);

layout(location = 0) in vec3 inToCamera;
layout(location = 1) in vec3 inNormal;
layout(location = 2) in vec2 inUv;

layout(set = 1, binding = 1) uniform sampler2D baseColorTexture;
layout(set = 1, binding = 2) uniform sampler2D metallicRoughnessTexture;

layout(location = 0) out vec4 outColor;

const float PI = 3.14159265;

void main() {
    vec4 base = baseColorFactor;
    if (HAS_BASE_COLOR_TEXTURE) base *= texture(baseColorTexture, inUv);
    if (ALPHA_MASK) {
        if (base.a < ALPHA_CUTOFF) discard;
    }
    if (!ALPHA_BLEND) base.a = 1.0;  // opaque and mask write full coverage

    vec3 diffuseOverPi, specular, ambientColor;
    float exponent;
    if (HAS_BASE_COLOR_TEXTURE || HAS_METALLIC_ROUGHNESS_TEXTURE) {
        float metallic = METALLIC;
        float roughness = ROUGHNESS;
        if (HAS_METALLIC_ROUGHNESS_TEXTURE) {
            vec4 mr = texture(metallicRoughnessTexture, inUv);
            metallic *= mr.b;
            roughness *= mr.g;
        }
        metallic = clamp(metallic, 0.0, 1.0);
        roughness = clamp(roughness, 0.04, 1.0);
        vec3 diffuse = base.rgb * (1.0 - metallic);
        vec3 f0 = mix(vec3(0.04), base.rgb, metallic);
        float alpha = roughness * roughness;
        float shininess = clamp(2.0 / (alpha * alpha) - 2.0, 1.0, 2048.0);
        diffuseOverPi = diffuse / PI;
        specular = f0 * ((shininess + 8.0) / (8.0 * PI));
        exponent = shininess * 1.4427;
        ambientColor = diffuse + f0 * 0.5;
    } else {
        diffuseOverPi = vec3(DIFFUSE_OVER_PI_R, DIFFUSE_OVER_PI_G, DIFFUSE_OVER_PI_B);
        specular = vec3(SPECULAR_R, SPECULAR_G, SPECULAR_B);
        exponent = EXPONENT;
        ambientColor = vec3(AMBIENT_COLOR_R, AMBIENT_COLOR_G, AMBIENT_COLOR_B);
    }

    vec3 n = normalize(inNormal);
    if (!gl_FrontFacing) n = -n;  // double-sided materials light their back faces
    vec3 v = normalize(inToCamera);

    float nDotL = max(dot(n, toKey), 0.0);
    float irradiance = KEY_INTENSITY * nDotL + FILL_INTENSITY * max(dot(n, toFill), 0.0) +
                       RIM_INTENSITY * max(dot(n, toRim), 0.0);
    vec3 color = diffuseOverPi * irradiance;
    // Key-light highlight; pow(x, s) ~ exp2(s * 1.4427 * (x - 1)) (spherical Gaussian).
    float nDotH = max(dot(n, normalize(toKey + v)), 0.0);
    color += specular * (KEY_INTENSITY * nDotL * exp2(exponent * (nDotH - 1.0)));
    // Sky above, darker ground bounce: mix(0.6, 1.0, n.y * 0.5 + 0.5) = 0.8 + 0.2 n.y.
    color += (AMBIENT * (0.8 + 0.2 * n.y)) * ambientColor;
    color += emissive;
    outColor = vec4(color, base.a);
}
