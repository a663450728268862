// Issue 22: every lexicon sign realizes its claimed code — judged on the hands as the signer's
// arms pose them (app/sign_alone.hpp, as `signstim sign GLOSS` judges them): each contact event
// reached within kContactReachedMm by the posed hand at its moment, and each posed hand within
// kPosedOrientationDeg of the orientation its motion asks. The requested pose alone is judged by
// tests/stimuli/sign_notation_test.cpp; a wrist at its limits, or a touch settled to the surface
// (signer/timeline_clip.hpp), can leave the posed hand short of what the notation reaches.
#include "app/sign_alone.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <optional>
#include <string>
#include <vector>

using namespace signstim;

namespace {

const std::filesystem::path kScenes = std::filesystem::path(SIGNSTIM_SOURCE_DIR) / "scenes";

// Signs of the default lexicon whose posed hands do not yet keep the rule, each held at what
// it does now (the posed contact's worst distance, mm; the posed hand's worst turn from the
// asked orientation, degrees; 0 where that part keeps the rule); remove a line when the sign's
// data is fixed. Measured with `signstim sign GLOSS` (its "posed" lines).
// Mirrored signs whose hands meet each other on the midline (FAMILY was fixed, 2026-11-27: its
// palms now face each other, the F thumbs meeting tip to tip; palms forward, this hand model's
// F thumbs cross below the circles). The touch settles the hands apart until their capsules
// meet, and what settling finds deep is not the contact's points but the rest of the hand:
// (HOW was fixed, 2026-11-27, 52.0 mm -> 5.2: hand:finger-back lay halfway along the chord from
// the knuckle to the middle fingertip, inside a C's curve, so putting the two places together
// put the fingers into each other; on the finger's back surface the bent fingers' backs meet.)
// (CHANGE was fixed, 2026-11-27, 17.7 mm -> 6.8: palm to palm its X fists lay in each other
// when the hooked index tips met, and one above the other the tips stayed a fingertip's
// thickness apart; palms down, the index fingers' thumb sides meet (hand:radial) and the hands
// twist together.)
// (GET was fixed, 2026-11-27, 10.7 mm -> 6.0: side by side, its S fists lay in each other at the
// thumbs and curled fingers; it now stacks them as the entry does, the right fist's little-finger
// edge on the left's thumb side, the left hand offset below its mirror image by leftOffset.)
// Keeping mirror-image hands on the side-to-side line when settling (so that neither ends
// ahead of or above the other) changed none of them: GET and LOSE settled along it already, HOW
// and CHANGE found no way out along it, and FAMILY's old pose needed 53.5 mm along it.
struct KnownPosed {
    const char* sign;
    double contactMm, orientationDeg;
};
// None now; add {sign, contactMm, orientationDeg} with its measured cause above.
const std::vector<KnownPosed> kKnownPosed{};

std::optional<KnownPosed> known(const std::string& gloss) {
    for (const KnownPosed& k : kKnownPosed)
        if (gloss == k.sign) return k;
    return std::nullopt;
}

}  // namespace

TEST(SignNotation, EverySignOfTheDefaultLexiconRealizesItsClaimedCodeOnThePosedHands) {
    stimuli::StoryWorld world(kScenes.string(), "");
    const signer::Signer signer(kScenes);
    std::string failures, figures, improved;
    int checked = 0;
    for (const stimuli::LexiconSign& sign : world.lexicon.signs) {
        if (!sign.notation) continue;
        const signer::TimelineClip clip = app::signAlone(world, signer, sign);
        double contact = 0.0, orientation = 0.0;
        int posedContacts = 0;
        for (const stimuli::NotationCheck& c :
             stimuli::checkSignNotation(sign, world.lexicon, world.shapes, world.handModel, app::posedHands(signer, clip, sign))) {
            if (c.name.rfind("posed ", 0) != 0) {
                EXPECT_TRUE(c.ok) << sign.gloss << ": " << c.name << ": " << c.detail;
                continue;
            }
            const double figure = std::atof(c.detail.c_str());  // "12.3 mm at ...", "25 degrees from ..."
            if (c.name.rfind("posed contact ", 0) == 0) ++posedContacts, contact = std::max(contact, c.ok ? 0.0 : figure);
            else orientation = std::max(orientation, c.ok ? 0.0 : figure);
        }
        EXPECT_EQ(posedContacts, static_cast<int>(sign.contactEvents.size())) << sign.gloss;
        ++checked;
        const std::optional<KnownPosed> k = known(sign.gloss);
        const bool worse = contact > (k ? k->contactMm + 0.5 : 0.0) || orientation > (k ? k->orientationDeg + 0.5 : 0.0);
        char line[160];
        std::snprintf(line, sizeof line, "\n    {\"%s\", %.1f, %.0f},", sign.gloss.c_str(), contact, orientation);
        if (contact > 0.0 || orientation > 0.0) figures += line;
        if (worse) failures += line;
        // A known sign that now does better by more than the tolerance: its line must follow it
        // down, or a later regression back to the old figure would pass unseen.
        if (k && (contact < k->contactMm - 0.5 || orientation < k->orientationDeg - 0.5))
            improved += line;
    }
    EXPECT_GT(checked, 200);
    EXPECT_TRUE(failures.empty()) << "posed hands that miss a contact by more than " << stimuli::kContactReachedMm
                                  << " mm or turn more than " << stimuli::kPosedOrientationDeg
                                  << " degrees from the asked orientation (sign, contact mm, degrees):" << failures
                                  << "\n  all that miss now:" << figures;
    EXPECT_TRUE(improved.empty()) << "signs of kKnownPosed that now do better; lower or remove their lines:" << improved
                                  << "\n  all that miss now:" << figures;
}
