#pragma once
// Where a posed frame's hands leave the view (issue 21: both hands, fingertips included, inside
// the camera frame), shared by the in-frame tests of signs alone and of stories.
#include "signer/screen_regions.hpp"

#include <array>
#include <cstdint>
#include <string>

namespace signstim::test {

// The views issue 21 §2 checks (every aspect: 4:3 and 16:9), the same in the in-frame tests of
// stories, of signs alone and of the verb grid.
struct FrameAspect {
    const char* name;
    std::uint32_t width, height;
};
inline constexpr FrameAspect kFrameAspects[] = {{"4:3", 640, 480}, {"16:9", 640, 360}};

// " right hand past the left edge left hand past the bottom" ..., or empty when both hands'
// screen boxes (signer/screen_regions.hpp: fingertips included, with its margin) lie inside a
// width x height view. A box clipped by the view touches its edge: part of the hand is outside.
inline std::string handsOutOfFrame(const std::array<signer::ScreenBox, 4>& boxes, std::uint32_t width,
                                   std::uint32_t height) {
    std::string where;
    for (signer::ScreenRegion r : {signer::ScreenRegion::RightHand, signer::ScreenRegion::LeftHand}) {
        const signer::ScreenBox& b = boxes[static_cast<std::size_t>(r)];
        const std::string hand = r == signer::ScreenRegion::RightHand ? " right hand" : " left hand";
        if (!b.visible) where += hand + " unseen";
        if (b.x0 <= 0) where += hand + " past the left edge";
        if (b.x1 >= static_cast<int>(width)) where += hand + " past the right edge";
        if (b.y0 <= 0) where += hand + " past the top";
        if (b.y1 >= static_cast<int>(height)) where += hand + " past the bottom";
    }
    return where;
}

}  // namespace signstim::test
