// The review page (stimuli/study/review_page.hpp) read as text: every clip referenced with its
// expected duration, every text escaped, the panel mappings and answer keys shown, nothing
// fetched from a network, the same bytes for the same listing. The browser side (it loads and
// plays in Chromium) is tests/browser/check_review_page.py, run by the review_page_browser
// tests.
#include "stimuli/study/review_page.hpp"
#include "tests/stimuli/review_page_fixture.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <regex>
#include <set>
#include <stdexcept>

namespace signstim::stimuli {
namespace {

using testing::ReviewFixtureShape;
using testing::reviewFixtureListing;

std::size_t count(const std::string& text, const std::string& what) {
    std::size_t n = 0;
    for (auto at = text.find(what); at != std::string::npos; at = text.find(what, at + what.size())) ++n;
    return n;
}

// Every value of the URL-bearing attributes (src, href, poster), in page order.
std::vector<std::string> urls(const std::string& page) {
    static const std::regex attribute(R"re(\s(src|href|poster)="([^"]*)")re");
    std::vector<std::string> found;
    for (auto it = std::sregex_iterator(page.begin(), page.end(), attribute); it != std::sregex_iterator(); ++it)
        found.push_back((*it)[2]);
    return found;
}

// Each <video ...> start tag.
std::vector<std::string> videoTags(const std::string& page) {
    std::vector<std::string> tags;
    for (auto at = page.find("<video "); at != std::string::npos; at = page.find("<video ", at + 1))
        tags.push_back(page.substr(at, page.find('>', at) - at + 1));
    return tags;
}

std::string attributeOf(const std::string& tag, const std::string& name) {
    const std::string key = " " + name + "=\"";
    const auto at = tag.find(key);
    if (at == std::string::npos) return {};
    const auto start = at + key.size();
    return tag.substr(start, tag.find('"', start) - start);
}

// The text between the element with id `id` and the end of its element (by the closing tag).
std::string elementWithId(const std::string& page, const std::string& id, const std::string& closing) {
    const auto start = page.find("id=\"" + id + "\"");
    if (start == std::string::npos) return {};
    return page.substr(start, page.find(closing, start) - start);
}

TEST(ReviewPage, EveryClipOfTheListingIsReferencedWithItsPosterAndDuration) {
    const StudyListing listing = reviewFixtureListing();
    const std::string page = reviewPageHtml(listing);
    std::vector<ListedClip> clips;
    for (const ListedStory& story : listing.stories) clips.insert(clips.end(), story.clips.begin(), story.clips.end());
    for (const ListedSentence& sentence : listing.sentences) clips.push_back(sentence.clip);
    ASSERT_EQ(clips.size(), 12u * 4u + 8u);

    std::map<std::string, std::set<std::string>> durationsBySource;
    for (const std::string& tag : videoTags(page))
        durationsBySource[attributeOf(tag, "src")].insert(attributeOf(tag, "data-expected-duration"));
    for (const ListedClip& clip : clips) {
        const auto found = durationsBySource.find(clip.video);
        ASSERT_NE(found, durationsBySource.end()) << clip.video << " has no <video>";
        char expected[32];
        std::snprintf(expected, sizeof expected, "%.3f", clip.durationSeconds);
        EXPECT_EQ(found->second, std::set<std::string>{expected}) << clip.video;
        EXPECT_NE(page.find("poster=\"" + clip.poster + "\""), std::string::npos) << clip.poster;
    }
    EXPECT_EQ(durationsBySource.size(), clips.size()) << "a <video> shows a file the listing does not name";
}

TEST(ReviewPage, EveryVideoHasControlsAPosterAnExpectedDurationAndAFrameCount) {
    const std::string page = reviewPageHtml(reviewFixtureListing());
    const std::vector<std::string> tags = videoTags(page);
    // 24 participants x (12 + 8) trials, 48 story clips, 8 side-by-side clips.
    ASSERT_EQ(tags.size(), 24u * 20u + 48u + 8u);
    const std::regex threeDecimals(R"(\d+\.\d{3})");
    for (const std::string& tag : tags) {
        EXPECT_NE(tag.find(" controls"), std::string::npos) << tag;
        EXPECT_FALSE(attributeOf(tag, "poster").empty()) << tag;
        EXPECT_TRUE(std::regex_match(attributeOf(tag, "data-expected-duration"), threeDecimals)) << tag;
        EXPECT_FALSE(attributeOf(tag, "data-frames").empty()) << tag;
    }
}

TEST(ReviewPage, ParticipantSectionsAreCollapsedAndFetchNothingUntilAClipIsPlayed) {
    const StudyListing listing = reviewFixtureListing();
    const std::string page = reviewPageHtml(listing);
    EXPECT_EQ(count(page, "<details class=\"participant\""), listing.participants.size());
    EXPECT_EQ(count(page, "<details class=\"participant\" open"), 0u);
    const auto participantsEnd = page.find("<section id=\"stories\">");
    ASSERT_NE(participantsEnd, std::string::npos);
    std::size_t none = 0, metadata = 0;
    for (const std::string& tag : videoTags(page.substr(0, participantsEnd))) {
        EXPECT_EQ(attributeOf(tag, "preload"), "none") << tag;
        ++none;
    }
    for (const std::string& tag : videoTags(page.substr(participantsEnd))) {
        EXPECT_EQ(attributeOf(tag, "preload"), "metadata") << tag;
        ++metadata;
    }
    EXPECT_EQ(none, 24u * 20u);
    EXPECT_EQ(metadata, 48u + 8u) << "one metadata preload per distinct clip";
    // Thumbnails in collapsed sections wait until the section is shown.
    const std::string lazy = "<img loading=\"lazy\" ";
    EXPECT_GT(count(page, lazy), 0u);
    EXPECT_EQ(count(page, lazy), count(page, "<img "));
}

TEST(ReviewPage, EveryTextIsEscaped) {
    StudyListing listing = reviewFixtureListing({.stories = 4, .participants = 4, .likertSentences = 4});
    listing.title = "<script>alert('title')</script>";
    listing.stories[1].title = "Tom & \"Jerry\" <b>";
    listing.stories[2].questions[0].choices[1] = "<img src=x onerror=alert(1)>";
    listing.sentences[0].gloss = "JOHN IX(0.9) <ASK> MARY";
    listing.participants[0].id = "P<1>";
    listing.designHash = "\"onmouseover=\"x";
    const std::string page = reviewPageHtml(listing);
    EXPECT_EQ(page.find("<script>alert"), std::string::npos);
    EXPECT_NE(page.find("&lt;script&gt;alert(&#39;title&#39;)&lt;/script&gt;"), std::string::npos);
    EXPECT_NE(page.find("Tom &amp; &quot;Jerry&quot; &lt;b&gt;"), std::string::npos);
    EXPECT_EQ(page.find("<img src=x"), std::string::npos);
    EXPECT_NE(page.find("&lt;img src=x onerror=alert(1)&gt;"), std::string::npos);
    EXPECT_NE(page.find("JOHN IX(0.9) &lt;ASK&gt; MARY"), std::string::npos);
    EXPECT_EQ(page.find("P<1>"), std::string::npos);
    EXPECT_EQ(page.find("\"onmouseover"), std::string::npos);
    // Only the page's own script.
    EXPECT_EQ(count(page, "<script"), 1u);
}

TEST(ReviewPage, EscapeHtmlReplacesTheFiveSpecialCharacters) {
    EXPECT_EQ(escapeHtml("a&b<c>d\"e'f"), "a&amp;b&lt;c&gt;d&quot;e&#39;f");
    EXPECT_EQ(escapeHtml("IX(-0.6) \xC3\xA9"), "IX(-0.6) \xC3\xA9");  // UTF-8 passes through
}

TEST(ReviewPage, FileNamesAreEncodedAsUrlPaths) {
    EXPECT_EQ(encodeUrlPath("clips/story-03_version-point.mp4"), "clips/story-03_version-point.mp4");
    EXPECT_EQ(encodeUrlPath("clips/a b#1?.mp4"), "clips/a%20b%231%3F.mp4");
    EXPECT_EQ(encodeUrlPath("c:x.mp4"), "c%3Ax.mp4");  // never read as a scheme
    EXPECT_EQ(encodeUrlPath("\xC3\xA9.png"), "%C3%A9.png");

    StudyListing listing = reviewFixtureListing({.stories = 4, .participants = 4, .likertSentences = 4});
    listing.stories[0].clips[0].video = "clips/story 01 & \"you\".mp4";
    const std::string page = reviewPageHtml(listing);
    EXPECT_NE(page.find("src=\"clips/story%2001%20%26%20%22you%22.mp4\""), std::string::npos);
}

TEST(ReviewPage, NothingIsFetchedFromANetworkOrOutsideTheFolder) {
    const std::string page = reviewPageHtml(reviewFixtureListing());
    EXPECT_EQ(page.find("http://"), std::string::npos);
    EXPECT_EQ(page.find("https://"), std::string::npos);
    EXPECT_EQ(page.find("<link"), std::string::npos);
    EXPECT_EQ(page.find("@import"), std::string::npos);
    EXPECT_EQ(page.find("url("), std::string::npos);
    for (const std::string& url : urls(page)) {
        if (url.starts_with("#")) continue;
        EXPECT_FALSE(url.starts_with("/")) << url;
        EXPECT_EQ(url.find("//"), std::string::npos) << url;
        EXPECT_EQ(url.find(':'), std::string::npos) << url;
        EXPECT_EQ(url.find(".."), std::string::npos) << url;
    }
}

TEST(ReviewPage, EveryInPageLinkHasATarget) {
    const std::string page = reviewPageHtml(reviewFixtureListing());
    std::set<std::string> ids;
    static const std::regex idAttribute(R"re(\sid="([^"]*)")re");
    for (auto it = std::sregex_iterator(page.begin(), page.end(), idAttribute); it != std::sregex_iterator(); ++it)
        EXPECT_TRUE(ids.insert((*it)[1]).second) << "duplicate id " << (*it)[1];
    for (const std::string& url : urls(page)) {
        if (url.starts_with("#")) {
            EXPECT_TRUE(ids.contains(url.substr(1))) << url;
        }
    }
}

TEST(ReviewPage, DuplicateIdsInTheListingStillGiveUniqueAnchors) {
    StudyListing listing = reviewFixtureListing({.stories = 4, .participants = 4, .likertSentences = 4});
    listing.stories[1].id = listing.stories[0].id;
    listing.participants[1].id = "P 1";
    listing.participants[2].id = "P-1";
    const std::string page = reviewPageHtml(listing);
    std::set<std::string> ids;
    static const std::regex idAttribute(R"re(\sid="([^"]*)")re");
    for (auto it = std::sregex_iterator(page.begin(), page.end(), idAttribute); it != std::sregex_iterator(); ++it)
        EXPECT_TRUE(ids.insert((*it)[1]).second) << "duplicate id " << (*it)[1];
}

TEST(ReviewPage, EachPanelMappingAppearsInPanelOrder) {
    const StudyListing listing = reviewFixtureListing();
    const std::string page = reviewPageHtml(listing);
    for (const ListedSentence& sentence : listing.sentences) {
        const std::string section = elementWithId(page, sentence.id, "</section>");
        ASSERT_FALSE(section.empty()) << sentence.id;
        EXPECT_NE(section.find(sentence.panelCode), std::string::npos);
        std::size_t at = section.find("<table class=\"mapping\"");
        ASSERT_NE(at, std::string::npos);
        for (std::size_t k = 0; k < sentence.panelVersion.size(); ++k) {
            const std::string row = std::string("<tr><td><strong>") + static_cast<char>('A' + k) + "</strong>";
            at = section.find(row, at);
            ASSERT_NE(at, std::string::npos) << sentence.id << " panel " << k;
            const std::string name = "<span class=\"version-name\">" + listing.versions[sentence.panelVersion[k]] + "<";
            EXPECT_EQ(section.find("<span class=\"version-name\">", at), section.find(name, at))
                << sentence.id << " panel " << k;
        }
    }
    // And in every phase-2 trial of every participant: one mapping table per trial and sentence.
    std::size_t trials = 0;
    for (const ListedParticipant& participant : listing.participants) trials += participant.phase2.size();
    EXPECT_EQ(count(page, "<table class=\"mapping\""), trials + listing.sentences.size());
}

TEST(ReviewPage, EachParticipantsTrialsAppearInPresentationOrder) {
    const StudyListing listing = reviewFixtureListing();
    const std::string page = reviewPageHtml(listing);
    for (const ListedParticipant& participant : listing.participants) {
        const std::string section = elementWithId(page, "participant-" + participant.id, "</details>");
        ASSERT_FALSE(section.empty()) << participant.id;
        std::size_t at = section.find("<table class=\"trials\">");
        for (const ListedPhase1Trial& trial : participant.phase1) {
            const ListedStory& story = listing.stories[trial.story];
            at = section.find("-trial-" + std::to_string(trial.trial) + "\"><td class=\"num\">", at);
            ASSERT_NE(at, std::string::npos) << participant.id << " trial " << trial.trial;
            const auto rowEnd = section.find("</tr>", at);
            const std::string row = section.substr(at, rowEnd - at);
            EXPECT_NE(row.find(">" + story.id + "</a>"), std::string::npos) << participant.id << " " << trial.trial;
            EXPECT_NE(row.find("src=\"" + story.clips[trial.version].video + "\""), std::string::npos);
            EXPECT_NE(row.find("<span class=\"version-name\">" + listing.versions[trial.version] + "</span>"),
                      std::string::npos);
            EXPECT_EQ(count(row, "<li class=\"answer\">"), story.questions.size());
        }
        for (const ListedPhase2Trial& trial : participant.phase2) {
            const ListedSentence& sentence = listing.sentences[trial.sentence];
            at = section.find("-likert-" + std::to_string(trial.trial) + "\"><td class=\"num\">", at);
            ASSERT_NE(at, std::string::npos) << participant.id << " phase-2 trial " << trial.trial;
            const std::string row = section.substr(at, section.find("</tr>", at) - at);
            EXPECT_NE(row.find(">" + sentence.id + "</a>"), std::string::npos);
            EXPECT_NE(row.find("src=\"" + sentence.clip.video + "\""), std::string::npos);
        }
    }
}

TEST(ReviewPage, TheAnswerKeyMarksTheRightChoice) {
    const StudyListing listing = reviewFixtureListing({.stories = 4, .participants = 4, .likertSentences = 4});
    const std::string page = reviewPageHtml(listing);
    for (const ListedStory& story : listing.stories) {
        const std::string section = elementWithId(page, story.id, "</section>");
        for (const ListedQuestion& question : story.questions) {
            const std::string answer = escapeHtml(question.choices[static_cast<std::size_t>(question.answer)]);
            EXPECT_NE(section.find("<li class=\"answer\">" + answer + "<span class=\"key\">"), std::string::npos)
                << story.id << ": " << question.text;
        }
    }
}

TEST(ReviewPage, TheHeaderNamesVersionSeedHashAndRenderSettings) {
    const StudyListing listing = reviewFixtureListing({.stories = 4, .participants = 4, .likertSentences = 4});
    const std::string page = reviewPageHtml(listing);
    const std::string header = page.substr(0, page.find("</header>"));
    EXPECT_NE(header.find("signstim 0.4.0"), std::string::npos);
    EXPECT_NE(header.find("<code>20151</code>"), std::string::npos);
    EXPECT_NE(header.find(listing.designHash), std::string::npos);
    EXPECT_NE(header.find("160x120, 15 fps, MSAA 4"), std::string::npos);
    EXPECT_NE(header.find("studies/fixture&#39;s study.json"), std::string::npos);
}

TEST(ReviewPage, TheSameListingGivesTheSameBytes) {
    const StudyListing listing = reviewFixtureListing({.withFrameFolders = true});
    const StudyListing copy = listing;
    const std::string first = reviewPageHtml(listing);
    EXPECT_EQ(first, reviewPageHtml(listing));
    EXPECT_EQ(first, reviewPageHtml(copy));
    EXPECT_NE(first.find("href=\"frames/story-01_version-point/\""), std::string::npos);
}

TEST(ReviewPage, ElementsAreClosed) {
    const std::string page = reviewPageHtml(reviewFixtureListing());
    for (const std::string element : {"details", "video", "table", "section", "figure", "ol", "tr", "script", "style"})
        EXPECT_EQ(count(page, "<" + element + ">") + count(page, "<" + element + " "), count(page, "</" + element + ">"))
            << element;
    EXPECT_TRUE(page.starts_with("<!DOCTYPE html>\n"));
    EXPECT_TRUE(page.ends_with("</html>\n"));
}

TEST(ReviewPage, AStudyWithoutParticipantsOrSentencesStillHasAPage) {
    StudyListing listing = reviewFixtureListing({.stories = 4, .participants = 0, .likertSentences = 0});
    const std::string page = reviewPageHtml(listing);
    EXPECT_NE(page.find("id=\"participants\""), std::string::npos);
    EXPECT_EQ(videoTags(page).size(), 16u);
}

TEST(ReviewPage, AListingThatNamesWhatItDoesNotHoldIsRefused) {
    StudyListing listing = reviewFixtureListing({.stories = 4, .participants = 4, .likertSentences = 4});
    StudyListing badStory = listing;
    badStory.participants[0].phase1[0].story = 4;
    EXPECT_THROW(reviewPageHtml(badStory), std::invalid_argument);
    StudyListing badSentence = listing;
    badSentence.participants[0].phase2[0].sentence = 9;
    EXPECT_THROW(reviewPageHtml(badSentence), std::invalid_argument);
    StudyListing badPanel = listing;
    badPanel.sentences[0].panelVersion[0] = 4;
    EXPECT_THROW(reviewPageHtml(badPanel), std::invalid_argument);
    StudyListing missingClip = listing;
    missingClip.stories[0].clips.pop_back();
    EXPECT_THROW(reviewPageHtml(missingClip), std::invalid_argument);
}


// ---- the counterbalancing at the top (issue 24 §7) -------------------------------------------

std::string counterbalancingSection(const std::string& page) { return elementWithId(page, "counterbalancing", "</section>"); }

TEST(ReviewPageCounterbalancing, ComesBeforeEverythingElseAndLinksTheOverviewCsv) {
    const std::string page = reviewPageHtml(reviewFixtureListing());
    const auto section = page.find("id=\"counterbalancing\"");
    ASSERT_NE(section, std::string::npos);
    EXPECT_LT(section, page.find("<nav class=\"toc\""));
    EXPECT_LT(section, page.find("id=\"participants\""));
    EXPECT_NE(counterbalancingSection(page).find("href=\"overview.csv\""), std::string::npos);
}

TEST(ReviewPageCounterbalancing, TheSquareShowsEachStorysVersionInEachGroup) {
    const StudyListing listing = reviewFixtureListing();
    const std::string section = counterbalancingSection(reviewPageHtml(listing));
    const std::string square = section.substr(section.find("<table class=\"square\""),
                                              section.find("</table>", section.find("<table class=\"square\"")) -
                                                  section.find("<table class=\"square\""));
    static const std::regex row(R"re(<tr><td class="story"><a href="#[^"]*">([^<]*)</a></td>(.*?)</tr>)re");
    static const std::regex badge(R"re(<span class="badge v\d" title="([^"]*)")re");
    std::size_t rows = 0;
    for (auto it = std::sregex_iterator(square.begin(), square.end(), row); it != std::sregex_iterator(); ++it, ++rows) {
        ASSERT_LT(rows, listing.stories.size());
        EXPECT_EQ((*it)[1], listing.stories[rows].id);
        const std::string cells = (*it)[2];
        std::vector<std::string> shown;
        for (auto b = std::sregex_iterator(cells.begin(), cells.end(), badge); b != std::sregex_iterator(); ++b)
            shown.push_back((*b)[1]);
        ASSERT_EQ(shown.size(), listing.groupVersion[rows].size());
        for (std::size_t g = 0; g < shown.size(); ++g) EXPECT_EQ(shown[g], listing.versions[listing.groupVersion[rows][g]]);
    }
    EXPECT_EQ(rows, listing.stories.size());
}

TEST(ReviewPageCounterbalancing, PositionCountsAreTheParticipantsVersionAtEachTrial) {
    StudyListing listing = reviewFixtureListing({.stories = 4, .participants = 4, .likertSentences = 4});
    // Every participant sees version 0 first: the first column reads 4, 0, 0, 0 and is marked uneven.
    for (ListedParticipant& p : listing.participants)
        for (std::size_t i = 0; i < p.phase1.size(); ++i)
            if (p.phase1[i].version == 0) std::swap(p.phase1[i], p.phase1[0]);
    for (ListedParticipant& p : listing.participants)
        for (std::size_t i = 0; i < p.phase1.size(); ++i) p.phase1[i].trial = i + 1;
    const std::string section = counterbalancingSection(reviewPageHtml(listing));
    const std::string table = section.substr(section.find("<table class=\"positions\""));
    static const std::regex row(R"re(<tr><th><span class="badge v\d" title="([^"]*)".*?</th>(.*?)</tr>)re");
    static const std::regex cell(R"re(<td class="(even|off)">(\d+)</td>)re");
    std::map<std::string, std::vector<std::pair<std::string, int>>> counts;
    for (auto it = std::sregex_iterator(table.begin(), table.end(), row); it != std::sregex_iterator(); ++it) {
        const std::string cells = (*it)[2];
        for (auto c = std::sregex_iterator(cells.begin(), cells.end(), cell); c != std::sregex_iterator(); ++c)
            counts[(*it)[1]].push_back({(*c)[1], std::stoi((*c)[2])});
    }
    ASSERT_EQ(counts.size(), listing.versions.size());
    for (std::size_t v = 0; v < listing.versions.size(); ++v) {
        const auto& shown = counts[listing.versions[v]];
        ASSERT_EQ(shown.size(), 4u);
        for (std::size_t i = 0; i < 4; ++i) {
            int expected = 0;
            for (const ListedParticipant& p : listing.participants) expected += p.phase1[i].version == v;
            EXPECT_EQ(shown[i].second, expected) << listing.versions[v] << " at " << i + 1;
            EXPECT_EQ(shown[i].first, expected == 1 ? "even" : "off");
        }
    }
    EXPECT_EQ(counts[listing.versions[0]][0].second, 4);
    EXPECT_NE(section.find("0 to 4"), std::string::npos);
}

TEST(ReviewPageCounterbalancing, StyleAndScriptAreTheEmbeddedFiles) {
    const std::string page = reviewPageHtml(reviewFixtureListing({.stories = 4, .participants = 4, .likertSentences = 4}));
    // review_page.css and review_page.js are written inline, whole (their first comments name them).
    EXPECT_NE(page.find("<style>/* signstim: the review page's stylesheet"), std::string::npos);
    EXPECT_NE(page.find("<script>// signstim: the review page's script"), std::string::npos);
    EXPECT_NE(page.find("table.positions td.off"), std::string::npos);
}

}  // namespace
}  // namespace signstim::stimuli
