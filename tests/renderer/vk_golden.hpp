#pragma once
// Golden-image comparison for renderer tests (after Filament's renderdiff): exact match
// first, then a tolerance, lavapipe being the reference device.
//
// Tolerance: a pixel fails when any channel differs by more than 3/255; the comparison
// fails when more than 0.5 % of the pixels fail or any channel differs by more than 64/255.
// On failure the actual image and an amplified difference image are written to
// <build>/tests/renderer/golden-out/ and their paths printed.
//
// Regenerating: SIGNSTIM_UPDATE_GOLDEN=1 ./signstim_renderer_vk_tests writes the actual
// images over tests/renderer/golden/*.png (look at them before committing).
#include "renderer/image.hpp"

#include <string>

namespace signstim::render::testing {

// Empty string when `image` matches tests/renderer/golden/<name>.png, else the reason.
std::string compareWithGolden(const Image& image, const std::string& name);

// Writes an 8-bit RGBA image as PNG (tests only; the product's writer is renderer/image_io).
void writePng(const Image& image, const std::string& path);

}  // namespace signstim::render::testing
