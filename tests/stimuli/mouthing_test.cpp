// Mouthing of English words (issue 23 §4; stimuli/story/mouthing.hpp, docs/mouthing.md): lip
// shapes from espeak-ng's phonemes, timed to the span.
#include "stimuli/story/mouthing.hpp"

#include "common/error.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <functional>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

namespace signstim::stimuli {
namespace {

const NonManualTrack* findTrack(const std::vector<NonManualTrack>& tracks, const std::string& channel) {
    for (const NonManualTrack& track : tracks)
        if (track.channel == channel) return &track;
    return nullptr;
}

double valueAt(const std::vector<NonManualTrack>& tracks, const std::string& channel, double t) {
    const NonManualTrack* track = findTrack(tracks, channel);
    return track != nullptr ? sampleNonManual(*track, t) : 0.0;
}

// Where a viseme is shown inside the span: the spoken word's milliseconds stretched to it.
struct Span {
    double start, end;
};
double centreOf(const std::vector<MouthingViseme>& visemes, std::size_t i, Span span) {
    const double scale = (span.end - span.start) / visemes.back().endMs;
    return span.start + 0.5 * (visemes[i].startMs + visemes[i].endMs) * scale;
}

// How far apart the lips are: the jaw opens them, mouthClose brings the lower lip back up by
// as much (ARKit: mouthClose is used with jawOpen).
double lipGap(const std::vector<NonManualTrack>& tracks, double t) {
    return valueAt(tracks, "jawOpen", t) - valueAt(tracks, "mouthClose", t);
}

bool sameTracks(const std::vector<NonManualTrack>& a, const std::vector<NonManualTrack>& b) {
    if (a.size() != b.size()) return false;
    for (std::size_t i = 0; i < a.size(); ++i) {
        if (a[i].channel != b[i].channel || a[i].keys.size() != b[i].keys.size()) return false;
        for (std::size_t k = 0; k < a[i].keys.size(); ++k)
            if (a[i].keys[k].timeSeconds != b[i].keys[k].timeSeconds || a[i].keys[k].value != b[i].keys[k].value)
                return false;
    }
    return true;
}

TEST(Mouthing, MamaClosesTheLipsAtEachMAndOpensThemAtEachVowel) {
    const Span span{1.0, 1.6};
    const auto visemes = mouthingVisemes("mama");
    const auto tracks = mouthingTracks("mama", span.start, span.end, 1.0);
    int closures = 0, vowels = 0;
    for (std::size_t i = 0; i < visemes.size(); ++i) {
        const double t = centreOf(visemes, i, span);
        if (visemes[i].phoneme == "m") {
            ++closures;
            EXPECT_NEAR(lipGap(tracks, t), 0.0, 1e-9) << "the lips meet at the m at " << t;
            EXPECT_GT(valueAt(tracks, "mouthPressLeft", t), 0.3);
            EXPECT_EQ(valueAt(tracks, "mouthPressLeft", t), valueAt(tracks, "mouthPressRight", t));
        } else if (visemes[i].viseme == "aa" || visemes[i].viseme == "E") {
            ++vowels;
            EXPECT_GT(lipGap(tracks, t), 0.25) << visemes[i].phoneme << " at " << t;
            EXPECT_LT(valueAt(tracks, "mouthPressLeft", t), valueAt(tracks, "mouthPressLeft", centreOf(visemes, 0, span)));
        }
    }
    EXPECT_EQ(closures, 2);
    EXPECT_EQ(vowels, 2);
}

TEST(Mouthing, WhoAndYouRoundTheLipsAndTeaDoesNot) {
    const Span span{0.0, 0.5};
    auto roundingAtVowel = [&](const std::string& word) {
        const auto visemes = mouthingVisemes(word);
        const auto tracks = mouthingTracks(word, span.start, span.end, 1.0);
        const std::size_t last = visemes.size() - 1;  // u: in "who" and "you", i: in "tea"
        const double t = centreOf(visemes, last, span);
        return std::vector<double>{valueAt(tracks, "mouthPucker", t), valueAt(tracks, "mouthFunnel", t)};
    };
    for (const std::string word : {"who", "you"}) {
        const auto rounding = roundingAtVowel(word);
        EXPECT_GT(rounding[0], 0.5) << word;
        EXPECT_GT(rounding[1], 0.2) << word;
    }
    const auto tea = roundingAtVowel("tea");
    EXPECT_LT(tea[0], 0.05);
    EXPECT_LT(tea[1], 0.05);
}

TEST(Mouthing, NoOpensTheJawAtItsVowel) {
    const Span span{2.0, 2.4};
    const auto visemes = mouthingVisemes("no");
    ASSERT_GE(visemes.size(), 2u);
    EXPECT_EQ(visemes[0].viseme, "nn");
    EXPECT_EQ(visemes[1].viseme, "oh");
    const auto tracks = mouthingTracks("no", span.start, span.end, 1.0);
    const double atN = valueAt(tracks, "jawOpen", centreOf(visemes, 0, span));
    const double atO = valueAt(tracks, "jawOpen", centreOf(visemes, 1, span));
    EXPECT_GT(atO, 0.35);
    EXPECT_GT(atO, atN + 0.1);
}

TEST(Mouthing, FAndVTuckTheLowerLipAndThHasTheTongueOut) {
    const Span span{0.0, 0.7};
    const auto visemes = mouthingVisemes("father");
    const auto tracks = mouthingTracks("father", span.start, span.end, 1.0);
    ASSERT_EQ(visemes[0].viseme, "FF");
    EXPECT_GE(valueAt(tracks, "mouthRollLower", centreOf(visemes, 0, span)), 0.6);
    EXPECT_LT(valueAt(tracks, "mouthRollLower", centreOf(visemes, 1, span)), 0.2) << "released at the vowel";
    int dentals = 0;
    for (std::size_t i = 0; i < visemes.size(); ++i) {
        if (visemes[i].viseme != "TH") continue;
        ++dentals;
        EXPECT_GT(valueAt(tracks, "tongueOut", centreOf(visemes, i, span)), 0.3);
    }
    EXPECT_EQ(dentals, 1);
}

TEST(Mouthing, LingualConsonantsTakeTheRoundingOfTheNextVowel) {
    // Cohen & Massaro's coarticulation: the lips of s give way to the vowel after it.
    const Span span{0.0, 0.6};
    const auto soonVisemes = mouthingVisemes("soon");
    const auto seenVisemes = mouthingVisemes("seen");
    ASSERT_EQ(soonVisemes[0].viseme, "SS");
    ASSERT_EQ(seenVisemes[0].viseme, "SS");
    const double soon = valueAt(mouthingTracks("soon", span.start, span.end, 1.0), "mouthPucker", centreOf(soonVisemes, 0, span));
    const double seen = valueAt(mouthingTracks("seen", span.start, span.end, 1.0), "mouthPucker", centreOf(seenVisemes, 0, span));
    EXPECT_GT(soon, seen + 0.1);
}

TEST(Mouthing, TracksFillTheSpanStartAndEndAtZeroAndStayWithinTheIntensity) {
    for (const std::string word : {"mama", "who", "thank you", "church", "father", "lovely"}) {
        for (const Span span : {Span{0.25, 0.55}, Span{3.0, 5.5}}) {
            for (const double intensity : {1.0, 0.6}) {
                const auto tracks = mouthingTracks(word, span.start, span.end, intensity);
                ASSERT_FALSE(tracks.empty()) << word;
                std::vector<std::string> channels;
                double peak = 0.0;
                for (const NonManualTrack& track : tracks) {
                    channels.push_back(track.channel);
                    ASSERT_GE(track.keys.size(), 3u);
                    EXPECT_EQ(track.keys.front().timeSeconds, span.start);
                    EXPECT_EQ(track.keys.front().value, 0.0);
                    EXPECT_EQ(track.keys.back().timeSeconds, span.end);
                    EXPECT_EQ(track.keys.back().value, 0.0);
                    for (std::size_t k = 0; k < track.keys.size(); ++k) {
                        if (k > 0) {
                            EXPECT_GT(track.keys[k].timeSeconds, track.keys[k - 1].timeSeconds) << word;
                        }
                        EXPECT_GE(track.keys[k].value, 0.0);
                        EXPECT_LE(track.keys[k].value, intensity);
                        peak = std::max(peak, track.keys[k].value);
                    }
                    EXPECT_EQ(sampleNonManual(track, span.start - 0.01), 0.0);
                    EXPECT_EQ(sampleNonManual(track, span.end + 0.01), 0.0);
                }
                EXPECT_GT(peak, 0.3 * intensity) << word << ": the mouth moves";
                std::sort(channels.begin(), channels.end());
                EXPECT_EQ(std::adjacent_find(channels.begin(), channels.end()), channels.end()) << "one track a channel";
            }
        }
    }
}

TEST(Mouthing, StretchingTheSpanStretchesTheTimingAlike) {
    const auto shortTracks = mouthingTracks("mama", 0.0, 0.4, 1.0);
    const auto longTracks = mouthingTracks("mama", 10.0, 11.2, 1.0);
    const auto visemes = mouthingVisemes("mama");
    ASSERT_GE(visemes.size(), 4u);
    EXPECT_EQ(visemes.front().startMs, 0.0);
    const NonManualTrack* shortClose = findTrack(shortTracks, "mouthPressLeft");
    const NonManualTrack* longClose = findTrack(longTracks, "mouthPressLeft");
    ASSERT_NE(shortClose, nullptr);
    ASSERT_NE(longClose, nullptr);
    ASSERT_EQ(shortClose->keys.size(), longClose->keys.size());
    for (std::size_t k = 0; k < shortClose->keys.size(); ++k)
        EXPECT_NEAR((longClose->keys[k].timeSeconds - 10.0) / 1.2, shortClose->keys[k].timeSeconds / 0.4, 1e-9);
    // The second m begins at its nominal share of the word (after the stressed vowel).
    const double share = visemes[2].startMs / visemes.back().endMs;
    EXPECT_GT(share, 0.3);
    EXPECT_LT(share, 0.8);
}

TEST(Mouthing, SameWordGivesIdenticalTracksWhateverWasMouthedBefore) {
    const auto first = mouthingTracks("grandmother", 0.5, 1.3, 0.8);
    for (const std::string other : {"who", "hello world", "church", "a", "zebra"}) mouthingTracks(other, 0.0, 1.0, 1.0);
    EXPECT_TRUE(sameTracks(first, mouthingTracks("grandmother", 0.5, 1.3, 0.8)));
}

TEST(Mouthing, TwoThreadsGetTheSameTracksAsOne) {
    const std::vector<std::string> words = {"mama", "who", "no", "thank you", "finish", "church", "you", "father"};
    std::vector<std::vector<NonManualTrack>> expected;
    for (const std::string& word : words) expected.push_back(mouthingTracks(word, 0.0, 0.7, 1.0));
    std::vector<std::vector<NonManualTrack>> resultsA(words.size()), resultsB(words.size());
    auto run = [&words](std::vector<std::vector<NonManualTrack>>& results, bool reversed) {
        for (int round = 0; round < 5; ++round)
            for (std::size_t n = 0; n < words.size(); ++n) {
                const std::size_t i = reversed ? words.size() - 1 - n : n;
                results[i] = mouthingTracks(words[i], 0.0, 0.7, 1.0);
            }
    };
    std::thread a(run, std::ref(resultsA), false);
    std::thread b(run, std::ref(resultsB), true);
    a.join();
    b.join();
    for (std::size_t i = 0; i < words.size(); ++i) {
        EXPECT_TRUE(sameTracks(resultsA[i], expected[i])) << words[i];
        EXPECT_TRUE(sameTracks(resultsB[i], expected[i])) << words[i];
    }
}

TEST(Mouthing, WordsWithoutLettersGiveNoTracks) {
    for (const std::string word : {"", "   ", "123", "?!", "--", "\xE2\x80\x94"}) {
        EXPECT_TRUE(mouthingTracks(word, 0.0, 1.0, 1.0).empty()) << word;
        EXPECT_TRUE(mouthingVisemes(word).empty()) << word;
    }
    EXPECT_TRUE(mouthingTracks("mama", 0.0, 1.0, 0.0).empty()) << "intensity 0";
}

TEST(Mouthing, CaseAndPunctuationDoNotChangeTheWord) {
    const auto no = mouthingTracks("no", 0.0, 0.5, 1.0);
    for (const std::string word : {"NO", "No", "no!", "\"no.\"", "(no)"}) EXPECT_TRUE(sameTracks(mouthingTracks(word, 0.0, 0.5, 1.0), no)) << word;
    // Characters that are not ASCII letters are word breaks, never passed to espeak-ng.
    EXPECT_TRUE(sameTracks(mouthingTracks("thank\xC3\xA9you", 0.0, 0.8, 1.0), mouthingTracks("thank you", 0.0, 0.8, 1.0)));
    EXPECT_TRUE(sameTracks(mouthingTracks("mother-in-law", 0.0, 0.8, 1.0), mouthingTracks("mother in law", 0.0, 0.8, 1.0)));
    // The apostrophe is part of the word: "don't" ends in n, t.
    const auto dont = mouthingVisemes("don't");
    ASSERT_FALSE(dont.empty());
    EXPECT_EQ(dont.back().viseme, "DD");
}

TEST(Mouthing, RefusesABadSpanAnIntensityOutOfRangeAndTooManyLetters) {
    EXPECT_THROW(mouthingTracks("no", 1.0, 1.0, 1.0), std::invalid_argument);
    EXPECT_THROW(mouthingTracks("no", 1.0, 0.5, 1.0), std::invalid_argument);
    EXPECT_THROW(mouthingTracks("no", 0.0, std::nan(""), 1.0), std::invalid_argument);
    EXPECT_THROW(mouthingTracks("no", 0.0, 1.0, 1.5), std::invalid_argument);
    EXPECT_THROW(mouthingTracks("no", 0.0, 1.0, -0.1), std::invalid_argument);
    EXPECT_THROW(mouthingTracks(std::string(kMouthedLetters + 1, 'a'), 0.0, 1.0, 1.0), InputError);
    EXPECT_NO_THROW(mouthingTracks(std::string(kMouthedLetters, 'a'), 0.0, 1.0, 1.0));
}

TEST(Mouthing, MissingEspeakDataIsAnEnvironmentErrorNamingWhatIsMissing) {
    try {
        loadMouthingSynthesizer("/nonexistent/signstim-no-espeak-data");
        FAIL() << "no error";
    } catch (const EnvironmentError& error) {
        EXPECT_NE(std::string(error.what()).find("/nonexistent/signstim-no-espeak-data"), std::string::npos) << error.what();
        EXPECT_NE(std::string(error.what()).find("espeak-ng-data"), std::string::npos) << error.what();
    }
    // A folder without espeak-ng's files: the first missing file is named.
    const std::filesystem::path empty = std::filesystem::path(::testing::TempDir()) / "signstim-mouthing-empty-data";
    std::filesystem::create_directories(empty);
    try {
        loadMouthingSynthesizer(empty.string());
        FAIL() << "no error";
    } catch (const EnvironmentError& error) {
        EXPECT_NE(std::string(error.what()).find("phontab"), std::string::npos) << error.what();
    }
    // The failed loads left nothing behind: mouthing still works from the default data.
    EXPECT_FALSE(mouthingTracks("no", 0.0, 0.5, 1.0).empty());
    std::filesystem::remove_all(empty);
}

TEST(Mouthing, PrintsNothing) {
    ::testing::internal::CaptureStdout();
    ::testing::internal::CaptureStderr();
    loadMouthingSynthesizer();
    mouthingTracks("hello world", 0.0, 1.0, 1.0);
    mouthingTracks("xyzzy", 0.0, 1.0, 1.0);
    const std::string out = ::testing::internal::GetCapturedStdout();
    const std::string err = ::testing::internal::GetCapturedStderr();
    EXPECT_EQ(out, "");
    EXPECT_EQ(err, "");
}

}  // namespace
}  // namespace signstim::stimuli
