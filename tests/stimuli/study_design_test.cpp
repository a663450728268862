// The study design's properties (SPEC §4.4), each checked for the default 12 x 4 design and
// for other designs that divide.
#include "stimuli/study/study_design.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <set>

namespace signstim::stimuli {
namespace {

std::vector<StudyDesignSpec> designs() {
    std::vector<StudyDesignSpec> all;
    for (auto [stories, versions, trials] : {std::tuple{12, 4, 8}, std::tuple{8, 4, 4}, std::tuple{16, 4, 8},
                                             std::tuple{12, 3, 6}, std::tuple{15, 5, 5}, std::tuple{10, 5, 0}}) {
        StudyDesignSpec spec;
        spec.stories = static_cast<std::size_t>(stories);
        spec.versions = static_cast<std::size_t>(versions);
        spec.likertTrials = static_cast<std::size_t>(trials);
        spec.participants = 4 * spec.versions;
        spec.seed = 20151;
        all.push_back(spec);
    }
    return all;
}

TEST(StudyDesign, EachScheduleIsAPermutationOfTheStoriesWithEveryVersionEquallyOften) {
    for (const StudyDesignSpec& spec : designs()) {
        for (std::size_t p = 0; p < spec.participants; ++p) {
            const ParticipantSchedule s = participantSchedule(spec, p);
            ASSERT_EQ(s.phase1.size(), spec.stories);
            std::set<std::size_t> stories;
            std::map<std::size_t, std::size_t> perVersion;
            for (const Phase1Trial& t : s.phase1) {
                stories.insert(t.story);
                ++perVersion[t.version];
            }
            EXPECT_EQ(stories.size(), spec.stories) << "a story seen twice";
            ASSERT_EQ(perVersion.size(), spec.versions);
            for (const auto& [version, count] : perVersion) EXPECT_EQ(count, spec.stories / spec.versions);
        }
    }
}

TEST(StudyDesign, EveryParticipantSeesEachVersionThreeTimesInTheDefaultDesign) {
    const StudyDesignSpec spec;  // 12 stories x 4 versions
    for (std::size_t p = 0; p < 40; ++p) {
        std::map<std::size_t, int> perVersion;
        for (const Phase1Trial& t : participantSchedule(spec, p).phase1) ++perVersion[t.version];
        for (std::size_t v = 0; v < 4; ++v) EXPECT_EQ(perVersion[v], 3);
    }
}

TEST(StudyDesign, TheGroupsCoverEveryStoryVersionCellExactlyOnce) {
    for (const StudyDesignSpec& spec : designs()) {
        std::map<std::pair<std::size_t, std::size_t>, int> cells;
        for (std::size_t g = 0; g < spec.versions; ++g)
            for (std::size_t s = 0; s < spec.stories; ++s) ++cells[{s, phase1Version(spec, s, g)}];
        EXPECT_EQ(cells.size(), spec.stories * spec.versions);
        for (const auto& [cell, count] : cells) EXPECT_EQ(count, 1);
    }
}

TEST(StudyDesign, EveryBlockOfParticipantsCoversAllGroups) {
    for (const StudyDesignSpec& spec : designs())
        for (std::size_t block = 0; block < 25; ++block) {
            std::set<std::size_t> groups;
            for (std::size_t i = 0; i < spec.versions; ++i) groups.insert(participantGroup(spec, block * spec.versions + i));
            EXPECT_EQ(groups.size(), spec.versions);
        }
}

TEST(StudyDesign, BlocksDoNotAllAssignGroupsInTheSameOrder) {
    const StudyDesignSpec spec;
    std::set<std::vector<std::size_t>> orders;
    for (std::size_t block = 0; block < 10; ++block) {
        std::vector<std::size_t> order;
        for (std::size_t i = 0; i < 4; ++i) order.push_back(participantGroup(spec, block * 4 + i));
        orders.insert(order);
    }
    EXPECT_GE(orders.size(), 4u);
}

bool sameSchedule(const ParticipantSchedule& a, const ParticipantSchedule& b) {
    if (a.group != b.group || a.phase1.size() != b.phase1.size() || a.phase2.size() != b.phase2.size()) return false;
    for (std::size_t i = 0; i < a.phase1.size(); ++i)
        if (a.phase1[i].story != b.phase1[i].story || a.phase1[i].version != b.phase1[i].version) return false;
    for (std::size_t i = 0; i < a.phase2.size(); ++i)
        if (a.phase2[i].sentence != b.phase2[i].sentence || a.phase2[i].panelVersion != b.phase2[i].panelVersion)
            return false;
    return true;
}

TEST(StudyDesign, SameSeedAndParticipantGiveTheSameScheduleWhateverTheNumberOfParticipants) {
    StudyDesignSpec few;
    few.participants = 8;
    StudyDesignSpec many = few;
    many.participants = 800;
    for (std::size_t p = 0; p < 8; ++p) {
        EXPECT_TRUE(sameSchedule(participantSchedule(few, p), participantSchedule(few, p)));
        EXPECT_TRUE(sameSchedule(participantSchedule(few, p), participantSchedule(many, p)));
    }
    StudyDesignSpec otherSeed = few;
    otherSeed.seed = few.seed + 1;
    int differ = 0;
    for (std::size_t p = 0; p < 8; ++p) differ += !sameSchedule(participantSchedule(few, p), participantSchedule(otherSeed, p));
    EXPECT_GE(differ, 6);
}

TEST(StudyDesign, OrdersVaryBetweenParticipants) {
    const StudyDesignSpec spec;
    std::set<std::vector<std::size_t>> storyOrders, trialOrders;
    for (std::size_t p = 0; p < 24; ++p) {
        const ParticipantSchedule s = participantSchedule(spec, p);
        std::vector<std::size_t> stories, trials;
        for (const Phase1Trial& t : s.phase1) stories.push_back(t.story);
        for (const Phase2Trial& t : s.phase2) trials.push_back(t.sentence);
        storyOrders.insert(stories);
        trialOrders.insert(trials);
    }
    EXPECT_EQ(storyOrders.size(), 24u);  // 12! orders: a repeat among 24 would be a bug
    EXPECT_GE(trialOrders.size(), 23u);  // 8! = 40320 orders: a repeat is possible but rare
}

TEST(StudyDesign, PanelsAreAPermutationOfTheVersionsAndBalancedAcrossTrials) {
    for (const StudyDesignSpec& spec : designs()) {
        if (spec.likertTrials == 0) continue;
        std::map<std::pair<std::size_t, std::size_t>, std::size_t> versionInPanel;
        for (std::size_t t = 0; t < spec.likertTrials; ++t) {
            const std::vector<std::size_t> panels = likertPanels(spec, t);
            ASSERT_EQ(panels.size(), spec.versions);
            EXPECT_EQ(std::set<std::size_t>(panels.begin(), panels.end()).size(), spec.versions);
            for (std::size_t k = 0; k < panels.size(); ++k) ++versionInPanel[{k, panels[k]}];
        }
        EXPECT_EQ(versionInPanel.size(), spec.versions * spec.versions);
        for (const auto& [cell, count] : versionInPanel) EXPECT_EQ(count, spec.likertTrials / spec.versions);
        // Every participant sees each sentence once, with the clip's own arrangement.
        const ParticipantSchedule s = participantSchedule(spec, 3);
        std::set<std::size_t> sentences;
        for (const Phase2Trial& t : s.phase2) {
            sentences.insert(t.sentence);
            EXPECT_EQ(t.panelVersion, likertPanels(spec, t.sentence));
        }
        EXPECT_EQ(sentences.size(), spec.likertTrials);
    }
}

TEST(StudyDesign, ImpossibleDesignsAreRefusedSayingWhatWouldWork) {
    StudyDesignSpec spec;
    spec.stories = 10;
    EXPECT_NE(designProblem(spec).find("multiple of 4 stories such as 8 or 12"), std::string::npos) << designProblem(spec);
    EXPECT_THROW(participantSchedule(spec, 0), std::invalid_argument);
    spec = {};
    spec.likertTrials = 6;
    EXPECT_NE(designProblem(spec).find("multiple of 4"), std::string::npos);
    spec = {};
    spec.versions = 5;
    EXPECT_NE(designProblem(spec).find("such as 10 or 15"), std::string::npos) << designProblem(spec);
    spec = {};
    spec.versions = 1;
    EXPECT_FALSE(designProblem(spec).empty());
    EXPECT_TRUE(designProblem(StudyDesignSpec{}).empty());
}

// Pins the default design's first participant: the generator and shuffle are ours, so this
// holds on every compiler and standard library. If it changes, every published schedule
// made with an earlier version changes too: say so in the release notes.
TEST(StudyDesign, TheDefaultScheduleIsPinned) {
    const ParticipantSchedule s = participantSchedule(StudyDesignSpec{}, 0);
    std::string order;
    for (const Phase1Trial& t : s.phase1) order += std::to_string(t.story) + ":" + std::to_string(t.version) + " ";
    for (const Phase2Trial& t : s.phase2) order += std::to_string(t.sentence) + " ";
    EXPECT_EQ(s.group, 1u);
    EXPECT_EQ(order, "0:1 5:2 7:0 1:2 8:1 9:2 3:0 6:3 4:1 11:0 10:3 2:3 0 4 2 6 1 5 7 3 ");
}


// ---- order: "balanced" (a Williams-type phase-1 order) -------------------------------------

namespace balanced {

std::vector<StudyDesignSpec> designs() {
    std::vector<StudyDesignSpec> all = signstim::stimuli::designs();
    for (StudyDesignSpec& spec : all) {
        spec.order = StoryOrder::Balanced;
        spec.participants = 3 * williamsRows(spec.versions);  // three complete blocks
    }
    return all;
}

}  // namespace balanced

TEST(StudyDesignBalancedOrder, EachVersionSitsAtEachTrialPositionEquallyOftenAcrossABlock) {
    for (const StudyDesignSpec& spec : balanced::designs()) {
        const std::size_t block = williamsRows(spec.versions);
        for (std::size_t first = 0; first < spec.participants; first += block) {
            std::map<std::pair<std::size_t, std::size_t>, std::size_t> count;  // (position, version)
            for (std::size_t p = first; p < first + block; ++p) {
                const ParticipantSchedule s = participantSchedule(spec, p);
                for (std::size_t i = 0; i < s.phase1.size(); ++i) ++count[{i, s.phase1[i].version}];
            }
            for (std::size_t i = 0; i < spec.stories; ++i)
                for (std::size_t v = 0; v < spec.versions; ++v)
                    EXPECT_EQ((count[{i, v}]), block / spec.versions)
                        << spec.stories << "x" << spec.versions << ", block from participant " << first << ", position "
                        << i << ", version " << v;
        }
    }
}

TEST(StudyDesignBalancedOrder, RandomOrderLeavesTrialPositionsUnevenWhereBalancedDoesNot) {
    // The contrast the review page shows: the default study's random order does not balance
    // versions over positions (the issue saw 1 to 11 where 6 is expected), the balanced one does.
    StudyDesignSpec spec;  // 12 x 4, 24 participants
    spec.seed = 20151;
    const auto spread = [&](StoryOrder order) {
        spec.order = order;
        std::map<std::pair<std::size_t, std::size_t>, std::size_t> count;
        for (std::size_t p = 0; p < spec.participants; ++p) {
            const ParticipantSchedule s = participantSchedule(spec, p);
            for (std::size_t i = 0; i < s.phase1.size(); ++i) ++count[{i, s.phase1[i].version}];
        }
        std::size_t low = spec.participants, high = 0;
        for (std::size_t i = 0; i < spec.stories; ++i)
            for (std::size_t v = 0; v < spec.versions; ++v) {
                low = std::min(low, count[{i, v}]);
                high = std::max(high, count[{i, v}]);
            }
        return std::pair{low, high};
    };
    EXPECT_EQ(spread(StoryOrder::Balanced), (std::pair<std::size_t, std::size_t>{6, 6}));
    const auto random = spread(StoryOrder::Random);
    EXPECT_LT(random.first, random.second);
}

TEST(StudyDesignBalancedOrder, SchedulesStayPermutationsWithEveryVersionEquallyOftenAndTheGroupsVersions) {
    for (const StudyDesignSpec& spec : balanced::designs()) {
        for (std::size_t p = 0; p < spec.participants; ++p) {
            const ParticipantSchedule s = participantSchedule(spec, p);
            ASSERT_EQ(s.phase1.size(), spec.stories);
            std::set<std::size_t> stories;
            std::map<std::size_t, std::size_t> perVersion;
            for (const Phase1Trial& t : s.phase1) {
                stories.insert(t.story);
                ++perVersion[t.version];
                EXPECT_EQ(t.version, phase1Version(spec, t.story, s.group)) << "the Latin square is kept";
            }
            EXPECT_EQ(stories.size(), spec.stories) << "a story seen twice";
            ASSERT_EQ(perVersion.size(), spec.versions);
            for (const auto& entry : perVersion) EXPECT_EQ(entry.second, spec.stories / spec.versions);
        }
    }
    // The default design: every version 3 times.
    StudyDesignSpec spec;
    spec.order = StoryOrder::Balanced;
    for (std::size_t p = 0; p < spec.participants; ++p) {
        std::map<std::size_t, int> perVersion;
        for (const Phase1Trial& t : participantSchedule(spec, p).phase1) ++perVersion[t.version];
        for (std::size_t v = 0; v < 4; ++v) EXPECT_EQ(perVersion[v], 3);
    }
}

TEST(StudyDesignBalancedOrder, WilliamsRowsBalanceWhichVersionFollowsWhich) {
    for (std::size_t versions = 2; versions <= 8; ++versions) {
        std::map<std::pair<std::size_t, std::size_t>, int> pairs;
        const std::size_t rows = williamsRows(versions);
        for (std::size_t r = 0; r < rows; ++r) {
            const std::vector<std::size_t> row = williamsRow(versions, r);
            EXPECT_EQ(std::set<std::size_t>(row.begin(), row.end()).size(), versions) << "row " << r << " repeats";
            for (std::size_t j = 0; j + 1 < versions; ++j) ++pairs[{row[j], row[j + 1]}];
        }
        EXPECT_EQ(pairs.size(), versions * (versions - 1)) << versions << " versions";
        for (const auto& entry : pairs) EXPECT_EQ(entry.second, static_cast<int>(rows / versions)) << versions;
    }
}

TEST(StudyDesignBalancedOrder, IsDeterministicAndIndependentOfTheParticipantCount) {
    for (const StudyDesignSpec& spec : balanced::designs()) {
        StudyDesignSpec more = spec;
        more.participants = spec.participants * 2;
        for (std::size_t p = 0; p < spec.participants; ++p) {
            const ParticipantSchedule a = participantSchedule(spec, p), b = participantSchedule(more, p),
                                      c = participantSchedule(spec, p);
            ASSERT_EQ(a.phase1.size(), b.phase1.size());
            for (std::size_t i = 0; i < a.phase1.size(); ++i) {
                EXPECT_EQ(a.phase1[i].story, b.phase1[i].story);
                EXPECT_EQ(a.phase1[i].story, c.phase1[i].story);
            }
        }
    }
}

TEST(StudyDesignBalancedOrder, TheRandomOrderIsTheDefaultAndUnchanged) {
    StudyDesignSpec random;
    StudyDesignSpec balancedSpec;
    balancedSpec.order = StoryOrder::Balanced;
    EXPECT_EQ(StudyDesignSpec{}.order, StoryOrder::Random);
    bool differs = false;
    for (std::size_t p = 0; p < 8; ++p) {
        const ParticipantSchedule a = participantSchedule(random, p), b = participantSchedule(balancedSpec, p);
        EXPECT_EQ(a.group, b.group) << "the groups do not depend on the order";
        for (std::size_t i = 0; i < a.phase1.size(); ++i) differs = differs || a.phase1[i].story != b.phase1[i].story;
    }
    EXPECT_TRUE(differs);
}

}  // namespace
}  // namespace signstim::stimuli
