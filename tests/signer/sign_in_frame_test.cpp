// Both hands, fingertips included, inside the camera frame (issue 21: for every preset and
// aspect, 4:3 and 16:9) for lexicon signs signed alone in citation form, as `signstim sign GLOSS
// --out` signs them: every frame at 30 fps, each hand's screen box (signer/screen_regions.hpp:
// every bone of the hand, the fingers and their tips included, grown by kScreenRegionMarginMm)
// inside the waist-up view, the preset that shows the hands (the face preset frames the head
// alone). BABY, SON and DAUGHTER cradle the arms across the body (issue 22).
#include "signer/clip.hpp"
#include "signer/screen_regions.hpp"
#include "signer/signer.hpp"
#include "signer/timeline_clip.hpp"
#include "stimuli/story/story.hpp"
#include "stimuli/story/story_world.hpp"
#include "stimuli/story/timeline_builder.hpp"
#include "tests/signer/hands_in_frame.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

using namespace signstim;

namespace {

const std::filesystem::path kScenes = std::filesystem::path(SIGNSTIM_SOURCE_DIR) / "scenes";

struct World {
    signer::Signer signer{kScenes};
    stimuli::StoryWorld story{kScenes.string(), ""};
    signer::ScreenRegionModel regions{signer.avatar(), signer.rig()};
};
const World& world() {
    static const World w;
    return w;
}

// One sign alone in citation form, as `signstim sign GLOSS` signs it (rests of 0.3 s, rate 1).
stimuli::Timeline signAlone(const std::string& gloss) {
    const World& w = world();
    stimuli::Story story;
    story.file = "sign " + gloss;
    stimuli::StorySentence sentence;
    stimuli::StoryItem item;
    item.kind = stimuli::StoryItemKind::Sign;
    item.gloss = gloss;
    sentence.gloss = gloss;
    sentence.items.push_back(item);
    story.sentences.push_back(sentence);
    stimuli::TimelineOptions timing;
    timing.signScale = 1.0;
    timing.restSeconds = 0.3;
    return stimuli::buildTimeline(story, stimuli::VerbVersion::Point, w.story.sources(story), timing);
}

// Frames of the moves in and out where a hand leaves the frame, held at what they are (a
// transition's detour takes the left hand under the right as the arms uncross, below the
// resting hands, which the waist-up view shows a few pixels above its bottom edge; alone, 14
// of the lexicon's 211 signs leave the 4:3 frame only so, 1-6 frames each, and 5 more in their
// own keys too, 2026-11-26). BABY's were 9, SON's 4, DAUGHTER's 3 before
// the cradle drew each elbow to its own side; then 4, 2, 2 before a detour was kept above the
// resting wrists' height (signer/transition_route.cpp, 2026-11-27): BABY's 3 are left, in the
// move in. Since then 11 of the 211 leave the 4:3 frame alone: 6 only in the moves (BUSY 1,
// LATE 2, BABY 3, LOVE 1, TABLE 1, ENGLISH 6 frames) and PARENTS, MAD, UNCLE, GRANDFATHER,
// FATHER in their keys too (the fingertips past the top). Once the waist-up view was kept at
// least 1.65 m wide (signer/avatar_render.cpp: a 4:3 view 1.24 m high), BABY's 3 are at 16:9
// only (its left hand past the bottom at 0.37 s). Lower a count when it falls.
struct KnownOut {
    const char* sign;
    int frames;
};
const KnownOut kLeavesInTransitions[] = {{"BABY", 3}, {"SON", 0}, {"DAUGHTER", 0}};

}  // namespace

TEST(SignInFrame, TheCradledArmsKeepBothHandsInsideTheWaistUpFrameAtEveryAspect) {
    // Inside the sign's own keys no frame may lose a hand; in the moves in and out no more
    // frames than kLeavesInTransitions holds.
    const World& w = world();
    const signer::SignerRig& rig = w.signer.rig();
    struct Aspect {
        const char* name;
        std::uint32_t width, height;
    };
    const Aspect aspects[] = {{"4:3", 640, 480}, {"16:9", 640, 360}};
    std::string out;
    for (const KnownOut& known : kLeavesInTransitions) {
        const char* gloss = known.sign;
        ASSERT_TRUE(w.story.lexicon.find(gloss)) << gloss;
        const signer::TimelineClip clip(rig, signAlone(gloss));
        const signer::ClipPoser poser(rig, clip);
        double keysStart = 0.0, keysEnd = 0.0;
        for (const stimuli::TimelineSpan& span : clip.timeline().spans)
            if (span.kind == stimuli::SpanKind::Sign) keysStart = span.keysStartSeconds, keysEnd = span.keysEndSeconds;
        ASSERT_LT(keysStart, keysEnd) << gloss;
        for (const Aspect& a : aspects) {
            const render::Camera camera = signer::clipCamera(w.signer.avatar(), rig, a.width, a.height, 1, 1);
            const render::ViewCell cell = render::viewCell(a.width, a.height, 1, 1, 0);
            int frames = 0, outside = 0, outsideInKeys = 0;
            double first = -1.0;
            std::string firstWhere;
            const int total = static_cast<int>(std::floor(clip.durationSeconds() * 30.0 + 1e-9));
            for (int f = 0; f <= total; ++f) {
                const double t = f / 30.0;
                const std::array<signer::ScreenBox, 4> boxes = w.regions.boxes(poser.next(t), camera, cell);
                ++frames;
                const std::string where = test::handsOutOfFrame(boxes, a.width, a.height);
                if (where.empty()) continue;
                if (t >= keysStart && t <= keysEnd) ++outsideInKeys;
                if (outside++ == 0) first = t, firstWhere = where;
            }
            EXPECT_GT(frames, 30) << gloss;
            if (outsideInKeys > 0 || outside > known.frames) {
                char line[200];
                std::snprintf(line, sizeof line, "\n  %s at %s: %d of %d frames (%d in its keys; held at %d), first at %.3f s:",
                              gloss, a.name, outside, frames, outsideInKeys, known.frames, first);
                out += line + firstWhere;
            }
        }
    }
    EXPECT_TRUE(out.empty()) << "a hand (fingertips included) leaves the waist-up frame:" << out;
}
