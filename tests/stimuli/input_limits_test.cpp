// Bounded input (issue 25 §10; docs/errors.md, Limits): what a hostile probe fed the readers
// (10^5 levels of nesting, megabytes of white space, 1,001 sentences, NUL in a title) is
// refused at once as an InputError naming the file, the line and the field, in little time
// and memory. The inputs are generated here (synthetic), never stored.
#include "common/error.hpp"
#include "common/input_limits.hpp"
#include "stimuli/json_source.hpp"
#include "stimuli/story/story.hpp"
#include "stimuli/verbs/verbs.hpp"
#include "tests/stimuli/story_vocabulary.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <functional>
#include <string>

#include <sys/resource.h>

namespace signstim::stimuli {
namespace {

namespace fs = std::filesystem;

InputError errorOf(const std::function<void()>& run) {
    try {
        run();
    } catch (const InputError& e) {
        return e;
    }
    ADD_FAILURE() << "no InputError";
    return InputError("", 0, "", "");
}

long peakResidentKb() {
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    return usage.ru_maxrss;
}

fs::path scratch(const std::string& name) {
    const fs::path dir = fs::path(SIGNSTIM_BINARY_DIR) / "input_limits_test";
    fs::create_directories(dir);
    return dir / name;
}

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

TEST(JsonLimits, NestingOfAHundredThousandLevelsIsRefusedAtOnceInBoundedMemory) {
    const std::size_t depth = 100000;  // the probe's file: 200 KB that took ~20 GB and crashed
    const std::string text = "{\"a\":\n" + std::string(depth, '[') + std::string(depth, ']') + "\n}";
    const long before = peakResidentKb();
    const auto start = std::chrono::steady_clock::now();
    const InputError e = errorOf([&] { parseJsonText(text, "deep.json"); });
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    EXPECT_EQ(e.file(), "deep.json");
    EXPECT_EQ(e.line(), 2);
    EXPECT_EQ(e.field(), "/a" + [] {
        std::string pointer;
        for (std::size_t i = 1; i < limits::kJsonDepth; ++i) pointer += "/0";
        return pointer;
    }());
    EXPECT_TRUE(contains(e.detail(), "nested more than 64 deep")) << e.what();
    // Generous bounds (a loaded CI machine, sanitizers): the unbounded reader needed gigabytes.
    EXPECT_LT(seconds, 5.0);
    EXPECT_LT(peakResidentKb() - before, 64 * 1024) << "peak RSS grew by " << peakResidentKb() - before << " kB";
}

TEST(JsonLimits, NestingAtTheLimitIsRead) {
    const std::size_t depth = limits::kJsonDepth;
    const JsonSource source = parseJsonText(std::string(depth, '[') + "1" + std::string(depth, ']'), "ok.json");
    std::string pointer;
    for (std::size_t i = 0; i < depth; ++i) pointer += "/0";
    EXPECT_TRUE(source.has(pointer));
    EXPECT_EQ(source.lineAt(pointer), 1);
}

TEST(JsonLimits, AFileOverItsSizeIsRefusedBeforeItIsRead) {
    const fs::path path = scratch("huge_whitespace.json");
    {
        std::ofstream out(path, std::ios::binary);
        out << "{}";
        // A sparse file: limit + 1 bytes on disk cost nothing; reading them would.
        out.seekp(static_cast<std::streamoff>(limits::kJsonFileBytes));
        out << ' ';
    }
    ASSERT_GT(fs::file_size(path), limits::kJsonFileBytes);
    const long before = peakResidentKb();
    const InputError e = errorOf([&] { readJsonFile(path); });
    EXPECT_EQ(e.file(), path.string());
    EXPECT_TRUE(contains(e.detail(), "over the limit of 64 MiB")) << e.what();
    EXPECT_LT(peakResidentKb() - before, 16 * 1024);
    fs::remove(path);
}

TEST(JsonLimits, MegabytesOfWhiteSpaceAreRefusedNamingTheLineWhereTheyStart) {
    // The run starts with the line break that ends line 2.
    const std::string text = "{\n  \"a\": 1," + std::string(2 * limits::kJsonWhitespaceRun, '\n') + "x}";
    const InputError e = errorOf([&] { parseJsonText(text, "space.json"); });
    EXPECT_EQ(e.line(), 2);
    EXPECT_TRUE(contains(e.detail(), "bytes of white space in a row")) << e.what();
}

TEST(JsonLimits, ASyntaxErrorMessageStaysOneShortLine) {
    // White space under the run limit, then a bad token: nlohmann quotes all it read.
    const std::string text = std::string(limits::kJsonWhitespaceRun / 2, '\t') + "x";
    const InputError e = errorOf([&] { parseJsonText(text, "bad.json"); });
    EXPECT_EQ(e.line(), 1);
    EXPECT_LT(std::string(e.what()).size(), 400u) << e.what();
}

TEST(JsonLimits, LinesOfAFileOfManyBlocksAreCountedRight) {
    // Values past several 4 KiB blocks of the line index, on known lines.
    std::string text = "[\n";
    for (int i = 0; i < 3000; ++i) text += "  {\"n\": " + std::to_string(i) + "},\n";
    text += "  0\n]\n";
    const JsonSource source = parseJsonText(text, "many.json");
    EXPECT_EQ(source.lineAt("/0/n"), 2);
    EXPECT_EQ(source.lineAt("/1234/n"), 1236);
    EXPECT_EQ(source.lineAt("/2999"), 3001);
    EXPECT_EQ(source.lineAt("/3000"), 3002);
    EXPECT_FALSE(source.has("/3001"));
    EXPECT_EQ(source.lineAt("/3001"), 1);  // the nearest enclosing value: the root
}

TEST(JsonLimits, ObjectMembersAreFoundInKeyOrderWhateverTheirOrderInTheFile) {
    const JsonSource source = parseJsonText("{\n\"z\": 1,\n\"b\": {\"y\": 2,\n\"a\": 3},\n\"m\": 4\n}", "keys.json");
    EXPECT_EQ(source.lineAt("/z"), 2);
    EXPECT_EQ(source.lineAt("/b"), 3);
    EXPECT_EQ(source.lineAt("/b/y"), 3);
    EXPECT_EQ(source.lineAt("/b/a"), 4);
    EXPECT_EQ(source.lineAt("/m"), 5);
}

TEST(TextFields, ANulEscapedInATitleIsRefusedWithItsLineAndField) {
    const std::string text = "{\n  \"format\": \"signstim-story\",\n  \"title\": \"Tom\\u0000 and Ann\"\n}";
    const InputError e = errorOf([&] { parseJsonText(text, "story.json"); });
    EXPECT_EQ(e.line(), 3);
    EXPECT_EQ(e.field(), "/title");
    EXPECT_TRUE(contains(e.detail(), "U+0000 (NUL)")) << e.what();
    // The message is whole: no NUL cut it short.
    EXPECT_TRUE(contains(e.what(), "remove the invisible character")) << e.what();
}

TEST(TextFields, ControlCharactersInChoicesAndKeysAreRefusedButTabAndNewlineAreNot) {
    const InputError escape = errorOf([] { parseJsonText("{\"choices\": [\"a\", \"b\\u001b[31m\"]}", "q.json"); });
    EXPECT_EQ(escape.field(), "/choices/1");
    EXPECT_TRUE(contains(escape.detail(), "U+001B (ESC)")) << escape.what();
    const InputError key = errorOf([] { parseJsonText("{\"ti\\u0007tle\": 1}", "k.json"); });
    EXPECT_EQ(key.field(), "");
    EXPECT_TRUE(contains(key.detail(), "a key holds")) << key.what();
    const InputError del = errorOf([] { parseJsonText("[\"\x7f\"]", "d.json"); });
    EXPECT_EQ(del.field(), "/0");
    EXPECT_NO_THROW(parseJsonText("{\"notes\": \"one\\ttwo\\nthree\"}", "ok.json"));
}

// ---- stories -----------------------------------------------------------------------------

StoryVocabulary vocabulary() { return test::storyVocabulary({"BOOK"}); }

std::string storyWith(const std::string& sentences) {
    return "{\n  \"format\": \"signstim-story\",\n  \"version\": 1,\n  \"title\": \"Synthetic\",\n"
           "  \"characters\": [{\"gloss\": \"JOHN\", \"position\": 0.9}, {\"gloss\": \"MARY\", \"position\": -0.6}],\n"
           "  \"sentences\": [\n" +
           sentences + "\n  ]\n}\n";
}

TEST(StoryLimits, MoreSentencesThanTheLimitAreRefusedBeforeAnyIsChecked) {
    std::string sentences;
    for (std::size_t i = 0; i <= limits::kStorySentences; ++i)
        sentences += std::string(i ? ",\n" : "") + "    \"JOHN IX(0.9) ASK MARY IX(-0.6)\"";
    const auto start = std::chrono::steady_clock::now();
    const InputError e = errorOf([&] { parseStory(parseJsonText(storyWith(sentences), "long.json"), vocabulary()); });
    EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 2.0);
    EXPECT_EQ(e.line(), 6);
    EXPECT_EQ(e.field(), "/sentences");
    EXPECT_TRUE(contains(e.detail(), "1001 sentences; a story has at most 1000")) << e.what();
}

TEST(StoryLimits, ASentenceOfTooManySignsIsRefusedAtTheFirstSignTooMany) {
    std::string gloss = "JOHN IX(0.9)";
    for (std::size_t i = 3; i <= limits::kSentenceSigns; ++i) gloss += " BOOK";  // 64 signs
    const std::string first = "    \"" + gloss + "\"";
    EXPECT_NO_THROW(parseStory(parseJsonText(storyWith(first), "ok.json"), vocabulary()));
    const InputError e =
        errorOf([&] { parseStory(parseJsonText(storyWith("    \"" + gloss + " BOOK\""), "wide.json"), vocabulary()); });
    EXPECT_EQ(e.line(), 7);
    EXPECT_EQ(e.column(), static_cast<int>(gloss.size()) + 7);  // the 65th sign: after `    "` and the 64
    EXPECT_EQ(e.field(), "/sentences/0");
    EXPECT_TRUE(contains(e.detail(), "65 signs in one sentence")) << e.what();
}

TEST(StoryLimits, AFingerspelledWordOfTooManyLettersIsRefused) {
    const std::string letters(limits::kFingerspelledLetters + 1, 'A');
    const InputError e =
        errorOf([&] { parseStory(parseJsonText(storyWith("    \"JOHN IX(0.9) fs-" + letters + "\""), "fs.json"), vocabulary()); });
    EXPECT_EQ(e.line(), 7);
    EXPECT_EQ(e.field(), "/sentences/0");
    EXPECT_TRUE(contains(e.detail(), "41 letters to fingerspell; at most 40")) << e.what();
}

TEST(StoryLimits, AStoryFileOverItsSizeIsRefused) {
    const fs::path path = scratch("big_story.json");
    {
        std::ofstream out(path, std::ios::binary);
        out << storyWith("    \"JOHN IX(0.9) ASK MARY IX(-0.6)\"");
        out.seekp(static_cast<std::streamoff>(limits::kStoryFileBytes));
        out << ' ';
    }
    const InputError e = errorOf([&] { loadStory(path, vocabulary()); });
    EXPECT_TRUE(contains(e.detail(), "over the limit of 4 MiB")) << e.what();
    fs::remove(path);
}

}  // namespace
}  // namespace signstim::stimuli
