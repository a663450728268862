#pragma once
// Procedural test geometry as render::Scene values (synthetic; no ASL). Used by the renderer
// tests, the benchmark and the glTF writer round trip. Every scene has one root node per
// object, a named material, and framing that suits frameBounds().
#include "renderer/scene.hpp"

#include <cstdint>

namespace signstim::render::procedural {

// A 1 m cube (24 vertices, flat normals), turned 30 deg about Y and 20 deg about X so three
// faces face a camera on +Z; warm orange, dielectric, roughness 0.5.
Scene litCube();

// A 1 m square in the XY plane facing +Z, double-sided, with an 8x8 checker texture
// (64x64 texels, generated here) sampled with linear filtering and mipmaps.
Scene texturedQuad();

// A cylinder (radius 0.15 m, 2 m along +Y) skinned to two joints: "lower" at the origin and
// "upper" 1 m above it; weights blend smoothly over 0.7..1.3 m. Animation "bend" rotates
// "upper" about +Z from 0 (t = 0 s) to 90 degrees (t = 1 s), linearly.
Scene skinnedCylinder();

// A UV sphere of radius 0.5 m with about `triangles` triangles (benchmark load).
Scene uvSphere(std::uint32_t triangles);

// The checker texture: `size` x `size` RGBA, `squares` squares per side, alternating
// light and dark.
ImageData checkerImage(std::uint32_t size, std::uint32_t squares);

}  // namespace signstim::render::procedural
