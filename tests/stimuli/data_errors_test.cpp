// Every bad number and every misplaced message in the data-file readers (issue 15): each kind
// of mistake is refused as an InputError naming the file, the line and the field, with the
// range or the expected value in the message; nothing non-finite gets through.
#include "common/error.hpp"
#include "hand/hand_model.hpp"
#include "stimuli/verbs/corpus.hpp"
#include "stimuli/story/handshapes.hpp"
#include "stimuli/json_source.hpp"
#include "stimuli/verbs/reference_performer.hpp"
#include "stimuli/verbs/sensor_io.hpp"
#include "stimuli/verbs/verb_models.hpp"
#include "stimuli/verbs/verb_synthesis.hpp"
#include "stimuli/verbs/verbs.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <limits>
#include <sstream>
#include <string>

#include <sys/stat.h>
#include <unistd.h>

namespace signstim::stimuli {
namespace {

namespace fs = std::filesystem;

const fs::path kScenes = fs::path(SIGNSTIM_SOURCE_DIR) / "scenes";

std::string readFile(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

fs::path scratch(const std::string& name) {
    const fs::path dir = fs::path(SIGNSTIM_BINARY_DIR) / "data_errors_test";
    fs::create_directories(dir);
    return dir / name;
}

fs::path writeFile(const std::string& name, const std::string& text) {
    const fs::path path = scratch(name);
    std::ofstream(path, std::ios::binary) << text;
    return path;
}

// `text` with the first `from` replaced by `to` (which must be there).
std::string replaced(std::string text, const std::string& from, const std::string& to) {
    const std::size_t at = text.find(from);
    EXPECT_NE(at, std::string::npos) << "no '" << from << "'";
    if (at != std::string::npos) text.replace(at, from.size(), to);
    return text;
}

// Line (1-based) of the first occurrence of `needle` in `text`.
int lineOfText(const std::string& text, const std::string& needle) {
    const std::size_t at = text.find(needle);
    EXPECT_NE(at, std::string::npos) << needle;
    return 1 + static_cast<int>(std::count(text.begin(), text.begin() + static_cast<std::ptrdiff_t>(at), '\n'));
}

InputError errorOf(const std::function<void()>& read) {
    try {
        read();
    } catch (const InputError& e) {
        return e;
    }
    ADD_FAILURE() << "no InputError";
    return InputError("none");
}

const hand::HandModel& handModel() {
    static const hand::HandModel model = hand::buildHandModel();
    return model;
}
const VerbLibrary& verbs() {
    static const VerbLibrary library = loadVerbLibrary(kScenes / "verbs.json");
    return library;
}
const HandshapeLibrary& shapes() {
    static const HandshapeLibrary library = loadHandshapes(kScenes / "handshapes.json", handModel());
    return library;
}
const std::string& verbsText() {
    static const std::string text = readFile(kScenes / "verbs.json");
    return text;
}
const std::string& modelsText() {
    static const std::string text = readFile(kScenes / "models" / "verb_models.json");
    return text;
}
const std::string& shapesText() {
    static const std::string text = readFile(kScenes / "handshapes.json");
    return text;
}
const std::string& askAnimatorText() {
    static const std::string text = readFile(kScenes / "animator" / "ASK_s0.9_o-0.6.json");
    return text;
}

VerbPerformance askAnimator(const std::string& text) {
    return parseAnimatorPerformance(parseJsonText(text, "ASK_s0.9_o-0.6.json"), *verbs().find("ASK"), 0.9, -0.6);
}

// ---- 1. JSON parse exceptions ----------------------------------------------------------------

TEST(JsonErrors, NumberOverflowIsAnInputErrorWithItsLineAndField) {
    const InputError e = errorOf([] { parseJsonText("{\n  \"a\": 1,\n  \"b\": [0, 1e400]\n}\n", "f.json"); });
    EXPECT_EQ(e.file(), "f.json");
    EXPECT_EQ(e.line(), 3);
    EXPECT_EQ(e.field(), "/b");
    EXPECT_NE(e.detail().find("number overflow parsing '1e400'"), std::string::npos) << e.what();
    EXPECT_EQ(e.detail().find("[json.exception"), std::string::npos) << e.what();
}

TEST(JsonErrors, SyntaxErrorsNameTheirLine) {
    EXPECT_EQ(errorOf([] { parseJsonText("{\n  \"a\": 1,\n  \"b\": tru\n}\n", "f.json"); }).line(), 3);
    EXPECT_EQ(errorOf([] { parseJsonText("{\n  \"a\": 1\n  \"b\": 2\n}\n", "f.json"); }).line(), 3);  // missing comma
    EXPECT_EQ(errorOf([] { parseJsonText("{\n  \"a\": [1, 2,\n", "f.json"); }).line(), 2);          // cut short
}

TEST(JsonErrors, HandshapeFileWithAnOverflowingBendNamesTheLine) {
    const std::string text = replaced(shapesText(), "\"bend\": 0,", "\"bend\": 1e400,");
    const InputError e = errorOf([&] { parseHandshapes(text, "shapes.json", handModel()); });
    EXPECT_EQ(e.line(), lineOfText(text, "1e400"));
    EXPECT_NE(std::string(e.what()).find("1e400"), std::string::npos) << e.what();
}

TEST(JsonErrors, AValueOfAnUnexpectedTypeIsAnInputError) {
    // verbs.json's "meaning" is read with .value(): a number there was a json::type_error (exit 4).
    const std::string text = replaced(verbsText(), "\"meaning\": \"ask a question\"", "\"meaning\": 5");
    const InputError e = errorOf([&] { parseVerbLibrary(parseJsonText(text, "verbs.json")); });
    EXPECT_EQ(e.file(), "verbs.json");
}

// ---- 2. Duplicate keys -----------------------------------------------------------------------

TEST(JsonErrors, DuplicateKeysAreRefusedNamingBothLines) {
    const InputError e =
        errorOf([] { parseJsonText("{\n  \"a\": {\n    \"x\": 1,\n    \"y\": 2,\n    \"x\": 3\n  }\n}\n", "f.json"); });
    EXPECT_EQ(e.line(), 5);
    EXPECT_EQ(e.field(), "/a/x");
    EXPECT_NE(e.detail().find("first on line 3"), std::string::npos) << e.what();
    // The same key in two objects is fine.
    EXPECT_NO_THROW(parseJsonText("[{\"x\": 1}, {\"x\": 2}]", "f.json"));
}

TEST(JsonErrors, LinesAreRecordedByJsonPointer) {
    const JsonSource source = parseJsonText("{\n  \"a\": [\n    1,\n    {\"b\":\n      2}\n  ],\n  \"c/d\": 1e5\n}\n", "f.json");
    EXPECT_EQ(source.lineAt("/a"), 2);
    EXPECT_EQ(source.lineAt("/a/0"), 3);
    EXPECT_EQ(source.lineAt("/a/1"), 4);
    EXPECT_EQ(source.lineAt("/a/1/b"), 4);
    EXPECT_EQ(source.lineAt("/c~1d"), 7);
    EXPECT_EQ(source.lineAt("/a/1/missing"), 4);  // the nearest enclosing value
}

// ---- 3, 4. Magnitudes and times --------------------------------------------------------------

TEST(DataRanges, AHugePositionInTheVerbsFileIsRefusedWithTheRange) {
    const std::string text = replaced(verbsText(), "\"position\": [100, 0, 370]", "\"position\": [100, 1e308, 370]");
    const InputError e = errorOf([&] { parseVerbLibrary(parseJsonText(text, "verbs.json")); });
    EXPECT_EQ(e.line(), lineOfText(text, "1e308"));
    EXPECT_EQ(e.field(), "/verbs/0/citation/right/1/position/1");
    EXPECT_NE(e.detail().find("expected -2000 to 2000 mm, got 1e+308"), std::string::npos) << e.what();
}

TEST(DataRanges, AHugePositionInAnAnimatorFileIsRefused) {
    const std::string text = replaced(askAnimatorText(), "[-190, 0, 330]", "[-190, 0, 1e308]");
    const InputError e = errorOf([&] { askAnimator(text); });
    EXPECT_EQ(e.line(), 12);
    EXPECT_EQ(e.field(), "/hands/right/1/position/2");
    EXPECT_NE(e.detail().find("got 1e+308"), std::string::npos) << e.what();
}

TEST(DataRanges, KeyframeTimesBeyondAMinuteAreRefused) {
    const std::string text = replaced(askAnimatorText(), "\"time\": 0.45", "\"time\": 1e9");
    const InputError e = errorOf([&] { askAnimator(text); });
    EXPECT_EQ(e.line(), 12);
    EXPECT_NE(e.detail().find("expected 0 to 60 s, got 1000000000"), std::string::npos) << e.what();
    const std::string verbsWithLongTime = replaced(verbsText(), "\"time\": 0.45", "\"time\": 61");
    EXPECT_NE(errorOf([&] { parseVerbLibrary(parseJsonText(verbsWithLongTime, "verbs.json")); }).detail().find("0 to 60 s"),
              std::string::npos);
}

TEST(DataRanges, HugeModelCoefficientsAreRefusedWithTheirLine) {
    // The first coefficient of ASK's point model, x.
    const std::size_t point = modelsText().find("\"point\"");
    const std::size_t x = modelsText().find("\"x\": [", point);
    const std::size_t first = modelsText().find_first_of("-0123456789", x + 6);
    const std::size_t end = modelsText().find_first_of(",\n", first);
    std::string text = modelsText();
    text.replace(first, end - first, "1e300");
    const InputError e = errorOf([&] { parseVerbModels(parseJsonText(text, "models.json"), verbs()); });
    EXPECT_EQ(e.line(), lineOfText(text, "1e300"));
    EXPECT_EQ(e.field(), "/verbs/0/point/0/0/x/0");
    EXPECT_NE(e.detail().find("expected -100000 to 100000, got 1e+300"), std::string::npos) << e.what();
}

TEST(DataRanges, AModelThatPredictsAPoseOutsideTheSigningSpaceIsRefusedNamingTheFile) {
    TrainedVerbModels models = loadVerbModels(kScenes / "models" / "verb_models.json", verbs());
    // Coefficients within range that add up, at s = o = 0.9, to 9e4 mm.
    for (VerbModel& model : models.verbs)
        if (model.verb == "ASK") model.point.position[0][0].x.coefficients.assign(10, 1.0e4);
    const VerbSources sources{&verbs(), &models, {}, nullptr};
    const InputError e = errorOf([&] { synthesizeVerb(sources, "ASK", VerbVersion::Point, 0.9, 0.9); });
    EXPECT_EQ(e.file(), (kScenes / "models" / "verb_models.json").string());
    EXPECT_GT(e.line(), 0);
    EXPECT_NE(e.detail().find("retrain"), std::string::npos) << e.what();
}

TEST(DataRanges, HugeSensorSamplesAreRefusedWithTheRange) {
    std::string text = "time,sensor,x,y,z,azimuth,elevation,roll\n";
    const char* sensors[] = {"hand", "thumb", "index", "middle", "ring", "little"};
    for (const char* sensor : sensors) text += std::string("0,") + sensor + ",1,2,3,4,5,6\n";
    const std::string bad = replaced(text, "0,ring,1,2,3", "0,ring,1,1e300,3");
    const InputError e = errorOf([&] { parseSensorSamples(bad, "s.csv"); });
    EXPECT_EQ(e.line(), 6);
    EXPECT_EQ(e.field(), "y");
    EXPECT_NE(e.detail().find("expected -10000 to 10000 mm, got 1e+300"), std::string::npos) << e.what();
    const std::string badAngle = replaced(text, "0,thumb,1,2,3,4", "0,thumb,1,2,3,400");
    EXPECT_EQ(errorOf([&] { parseSensorSamples(badAngle, "s.csv"); }).field(), "azimuth");
}

TEST(DataRanges, ANonFiniteSensorHandIsNeverWritten) {
    std::vector<SensorSample> samples(2);
    samples[1].line = 9;
    samples[1].timeS = 0.5;
    std::vector<hand::SensorHandFrame> frames(2);
    EXPECT_NO_THROW(checkSensorHandFinite(samples, frames, "s.csv"));
    frames[1].joints[2].proximalJoint.y = std::numeric_limits<float>::quiet_NaN();
    const InputError e = errorOf([&] { checkSensorHandFinite(samples, frames, "s.csv"); });
    EXPECT_EQ(e.file(), "s.csv");
    EXPECT_EQ(e.line(), 9);
}

TEST(DataRanges, HugeCorpusValuesAreRefused) {
    const std::string text = "verb,example,subject,object,hand,keyframe,x,y,z,roll,pitch,yaw\n"
                             "ASK,1,0.3,-0.6,right,0,1,2,1e300,0,0,0\n";
    const InputError e = errorOf([&] { parseCorpus(text, "c.csv", verbs()); });
    EXPECT_EQ(e.line(), 2);
    EXPECT_EQ(e.field(), "z");
    EXPECT_NE(e.detail().find("expected -2000 to 2000 mm"), std::string::npos) << e.what();
}

TEST(DataRanges, AVerbWhosePassesLastMoreThanAMinuteIsRefused) {
    const std::string text = replaced(verbsText(), "\"passes\": 3", "\"passes\": 20");
    std::string longer = text;
    // SCOLD's last keyframe at 0.18 s: 20 passes are 3.6 s, fine; at 3.5 s they are 70 s.
    const VerbLibrary fine = parseVerbLibrary(parseJsonText(text, "verbs.json"));
    EXPECT_EQ(fine.find("SCOLD")->passes, 20);
    const double last = fine.find("SCOLD")->citation[0].back().timeSeconds;
    char from[32];
    std::snprintf(from, sizeof from, "\"time\": %g", last);
    const std::size_t scold = longer.find("\"SCOLD\"");
    const std::size_t at = longer.find(from, scold);
    ASSERT_NE(at, std::string::npos) << from;
    longer.replace(at, std::strlen(from), "\"time\": 3.5");
    const InputError e = errorOf([&] { parseVerbLibrary(parseJsonText(longer, "verbs.json")); });
    EXPECT_EQ(e.line(), lineOfText(longer, "\"passes\": 20"));
    EXPECT_NE(e.detail().find("lasts 70 s in all"), std::string::npos) << e.what();
}

// ---- 5. train validates before writing -------------------------------------------------------

TEST(TrainValidation, ModelsThatWouldNotLoadBackAreRefusedBeforeWriting) {
    TrainedVerbModels models = loadVerbModels(kScenes / "models" / "verb_models.json", verbs());
    EXPECT_EQ(formatCheckedVerbModels(models, verbs(), "out.json"), modelsText());
    models.sourceFile = "corpus.csv";
    models.verbs.front().point.position[0][0].y.coefficients[3] = 1e200;
    const InputError e = errorOf([&] { formatCheckedVerbModels(models, verbs(), "out.json"); });
    EXPECT_EQ(e.file(), "corpus.csv");
    EXPECT_NE(e.detail().find("out.json is not written"), std::string::npos) << e.what();
    EXPECT_NE(e.detail().find("got 1e+200"), std::string::npos) << e.what();
    // A coefficient that is not finite is refused, not written as 0 or null.
    models.verbs.front().point.position[0][0].y.coefficients[3] = std::numeric_limits<double>::quiet_NaN();
    EXPECT_THROW(formatCheckedVerbModels(models, verbs(), "out.json"), InputError);
}

// ---- 6. Enough digits ------------------------------------------------------------------------

TEST(DataRanges, AValueJustPastALimitIsPrintedWithEnoughDigits) {
    const std::string text = replaced(shapesText(), "\"bend\": 0,", "\"bend\": 1.0000001,");
    const InputError e = errorOf([&] { parseHandshapes(text, "shapes.json", handModel()); });
    EXPECT_NE(e.detail().find("got 1.0000001"), std::string::npos) << e.what();
    EXPECT_EQ(e.line(), lineOfText(text, "1.0000001"));
}

// ---- 7. Messages that point to the right place -----------------------------------------------

TEST(Blame, AnUnknownHandshapeInAnAnimatorFileNamesTheFileLineAndField) {
    const fs::path dir = scratch("animator");
    fs::create_directories(dir);
    const std::string text = replaced(askAnimatorText(), "\"handshape\": \"X\"", "\"handshape\": \"bogus\"");
    std::ofstream(dir / "ASK_s0.9_o-0.6.json") << text;
    const VerbSources sources{&verbs(), nullptr, dir, &shapes()};
    const InputError e = errorOf([&] { synthesizeVerb(sources, "ASK", VerbVersion::Animator, 0.9, -0.6); });
    EXPECT_EQ(e.file(), (dir / "ASK_s0.9_o-0.6.json").string());
    EXPECT_EQ(e.line(), 12);
    EXPECT_EQ(e.field(), "/hands/right/1/handshape");
    EXPECT_NE(e.detail().find("unknown handshape 'bogus'"), std::string::npos) << e.what();
}

TEST(Blame, AnUnknownHandshapeInTheVerbsFileNamesItsLine) {
    const std::string text = replaced(verbsText(), "\"handshape\": \"X\"", "\"handshape\": \"bogus\"");
    const VerbLibrary library = parseVerbLibrary(parseJsonText(text, "verbs.json"));
    const VerbSources sources{&library, nullptr, {}, &shapes()};
    const InputError e = errorOf([&] { synthesizeVerb(sources, "ASK", VerbVersion::Uninflected, 0.9, -0.6); });
    EXPECT_EQ(e.file(), "verbs.json");
    EXPECT_EQ(e.line(), lineOfText(text, "bogus"));
    EXPECT_EQ(e.field(), "/verbs/0/citation/right/1/handshape");
    const InputError check = errorOf([&] { checkHandshapeNames(library, [](const std::string& n) { return n != "bogus"; }); });
    EXPECT_EQ(check.line(), lineOfText(text, "bogus"));
}

TEST(Blame, AMissingVerbModelNamesTheModelsFile) {
    TrainedVerbModels models;
    models.sourceFile = "my_models.json";
    const VerbSources sources{&verbs(), &models, {}, nullptr};
    EXPECT_EQ(errorOf([&] { synthesizeVerb(sources, "ASK", VerbVersion::Point, 0.9, -0.6); }).file(), "my_models.json");
}

TEST(Blame, TooFewExamplesNameTheCorpusFile) {
    std::string text = "verb,example,subject,object,hand,keyframe,x,y,z,roll,pitch,yaw\n";
    for (int e = 1; e <= 3; ++e)
        for (int k = 0; k < 2; ++k)
            text += "ASK," + std::to_string(e) + ",0.3,-0." + std::to_string(e) + ",right," + std::to_string(k) + ",1,2,3,0,0,0\n";
    const Corpus corpus = parseCorpus(text, "few.csv", verbs());
    const InputError e = errorOf([&] { trainVerbModels(corpus, verbs()); });
    EXPECT_EQ(e.file(), "few.csv");
    EXPECT_EQ(e.line(), 2);
}

// Every reader reports the line an error is on.
TEST(LineNumbers, EveryReaderNamesTheLineOfTheError) {
    // handshapes (text anchors)
    {
        const std::string text = replaced(shapesText(), "\"hook\": 0", "\"hook\": 7");
        EXPECT_EQ(errorOf([&] { parseHandshapes(text, "h.json", handModel()); }).line(), lineOfText(text, "\"hook\": 7"));
    }
    // handshapes written compactly, one shape per line: the line is still that of the shape
    {
        nlohmann::json shapes = nlohmann::json::parse(shapesText());
        shapes["handshapes"][3]["fingers"]["ring"] = "no-such-preset";
        std::string text = "{\n";
        for (const auto& [key, value] : shapes.items())
            if (key != "handshapes") text += "\"" + key + "\":" + value.dump() + ",\n";
        text += "\"handshapes\":[\n";
        for (std::size_t i = 0; i < shapes["handshapes"].size(); ++i)
            text += shapes["handshapes"][i].dump() + (i + 1 < shapes["handshapes"].size() ? ",\n" : "\n");
        text += "]}\n";
        const InputError e = errorOf([&] { parseHandshapes(text, "h.json", handModel()); });
        EXPECT_EQ(e.line(), lineOfText(text, "no-such-preset")) << e.what();
    }
    // verbs: the second keyframe's fingers of GIVE
    {
        const std::size_t give = verbsText().find("\"GIVE\"");
        std::string text = verbsText();
        const std::size_t fingers = text.find("\"fingers\": [", text.find("\"time\": 0.", text.find("\"time\": 0.0", give) + 5));
        text.replace(fingers, 12, "\"fingers\": [\"a\", ");
        const InputError e = errorOf([&] { parseVerbLibrary(parseJsonText(text, "verbs.json")); });
        EXPECT_EQ(e.line(), lineOfText(text, "[\"a\", "));
    }
    // models: the weight of a mixture component
    {
        const std::string text = replaced(modelsText(), "\"weight\": ", "\"weight\": -");
        const InputError e = errorOf([&] { parseVerbModels(parseJsonText(text, "m.json"), verbs()); });
        EXPECT_EQ(e.line(), lineOfText(text, "\"weight\": -"));
    }
    // animator: a keyframe time out of order
    {
        const std::string text = replaced(askAnimatorText(), "\"time\": 0.45", "\"time\": 0.0");
        EXPECT_EQ(errorOf([&] { askAnimator(text); }).line(), 12);
    }
    // reference performer: a gain out of range on a known line
    {
        const std::string performer = readFile(kScenes / "corpus" / "reference_performer.json");
        const std::string text = replaced(performer, "\"reachGain\": 1.04", "\"reachGain\": 100");
        const InputError e = errorOf([&] { parseReferencePerformer(parseJsonText(text, "p.json"), verbs()); });
        EXPECT_EQ(e.line(), lineOfText(text, "\"reachGain\": 100"));
        EXPECT_EQ(e.field(), "/bias/reachGain");
    }
    // corpus: comment lines count
    {
        const std::string text = "# one\n# two\nverb,example,subject,object,hand,keyframe,x,y,z,roll,pitch,yaw\n\n"
                                 "ASK,1,0.3,-0.6,right,0,1,2,3,0,0,0\nASK,1,0.3,-0.6,right,1,1,2,3,0,0,x\n";
        const InputError e = errorOf([&] { parseCorpus(text, "c.csv", verbs()); });
        EXPECT_EQ(e.line(), 6);
        EXPECT_EQ(e.field(), "yaw");
    }
    // sensor calibration (text anchors)
    {
        const hand::SensorCalibration calibration = hand::calibrationForModel(handModel(), hand::Side::Right);
        const std::string good = formatSensorCalibration(calibration);
        std::string text = good;
        const std::size_t ring = text.find("\"ring\"");
        const std::size_t tip = text.find("\"tipThicknessMm\": ", ring);
        text.insert(tip + 18, "9");  // 9xx mm: out of range
        const InputError e = errorOf([&] { parseSensorCalibration(text, "cal.json"); });
        EXPECT_EQ(e.line(), 1 + static_cast<int>(std::count(text.begin(), text.begin() + static_cast<std::ptrdiff_t>(tip), '\n')));
    }
}

// ---- 8. Inputs that are not regular files ----------------------------------------------------

TEST(FileKinds, WhatIsNotARegularFileIsRefusedSayingWhatItIs) {
    const fs::path dir = scratch("a_directory");
    fs::create_directories(dir);
    EXPECT_NE(errorOf([&] { readTextFile(dir); }).detail().find("is a directory"), std::string::npos);
    EXPECT_NE(errorOf([] { readTextFile("/dev/zero"); }).detail().find("is a character device"), std::string::npos);
    const fs::path fifo = scratch("a_fifo");
    fs::remove(fifo);
    ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
    // No writer: opening it for reading would block for ever.
    EXPECT_NE(errorOf([&] { readTextFile(fifo); }).detail().find("is a FIFO"), std::string::npos);
    fs::remove(fifo);
    const InputError missing = errorOf([] { readTextFile(scratch("does_not_exist.json")); });
    EXPECT_NE(missing.detail().find("no such file"), std::string::npos);
    EXPECT_THROW(loadVerbLibrary(dir), InputError);
    EXPECT_THROW(loadSensorSamples("/dev/zero"), InputError);
}

TEST(FileKinds, AReadThatFailsWithAnIoErrorIsAnIoError) {
    // /proc/self/mem is a regular file whose first page is unmapped: read() fails with EIO,
    // whoever runs the test (root included).
    try {
        readTextFile("/proc/self/mem");
        ADD_FAILURE() << "no error";
    } catch (const IoError& e) {
        EXPECT_NE(std::string(e.what()).find("/proc/self/mem: cannot read: Input/output error"), std::string::npos) << e.what();
    }
}

TEST(FileKinds, AFileTheSystemRefusesToReadIsAnIoError) {
    if (::geteuid() == 0) GTEST_SKIP() << "root reads files whatever their permissions";
    const fs::path locked = writeFile("locked.json", "{}");
    fs::permissions(locked, fs::perms::none);
    EXPECT_THROW(readTextFile(locked), IoError);
    fs::permissions(locked, fs::perms::owner_all);
}

// ---- 9. Byte-order marks ---------------------------------------------------------------------

TEST(ByteOrderMark, IsAcceptedInEveryCsvAndJsonReader) {
    const std::string bom = "\xEF\xBB\xBF";
    std::string samples = "time,sensor,x,y,z,azimuth,elevation,roll\n";
    for (const char* sensor : {"hand", "thumb", "index", "middle", "ring", "little"})
        samples += std::string("0,") + sensor + ",1,2,3,4,5,6\n";
    EXPECT_EQ(parseSensorSamples(bom + samples, "s.csv").size(), 1u);
    const std::string corpus = readFile(kScenes / "corpus" / "reference_corpus.csv");
    EXPECT_EQ(parseCorpus(bom + corpus, "c.csv", verbs()).examples.size(), parseCorpus(corpus, "c.csv", verbs()).examples.size());
    EXPECT_EQ(parseVerbLibrary(parseJsonText(bom + verbsText(), "v.json")).verbs.size(), verbs().verbs.size());
    EXPECT_EQ(parseHandshapes(bom + shapesText(), "h.json", handModel()).shapes.size(), shapes().shapes.size());
    const hand::SensorCalibration calibration = hand::calibrationForModel(handModel(), hand::Side::Left);
    EXPECT_EQ(parseSensorCalibration(bom + formatSensorCalibration(calibration), "c.json").side, hand::Side::Left);
    // Lines still count from the first.
    const std::string badVerbs = replaced(verbsText(), "\"time\": 0.45", "\"time\": -1");
    EXPECT_EQ(errorOf([&] { parseVerbLibrary(parseJsonText(bom + badVerbs, "v.json")); }).line(), lineOfText(badVerbs, "\"time\": -1"));
}

// ---- 10. format, version, extra fields -------------------------------------------------------

TEST(Formats, AWrongFormatOrVersionIsRefusedSayingWhatWasExpected) {
    const InputError format = errorOf([] {
        parseVerbLibrary(parseJsonText(replaced(verbsText(), "\"signstim-verbs\"", "\"signstim-verb-models\""), "v.json"));
    });
    EXPECT_EQ(format.line(), 2);
    EXPECT_NE(format.detail().find("expected \"signstim-verbs\""), std::string::npos) << format.what();
    const InputError version = errorOf([] { parseVerbLibrary(parseJsonText(replaced(verbsText(), "\"version\": 1", "\"version\": 2"), "v.json")); });
    EXPECT_EQ(version.line(), 3);
    EXPECT_NE(version.detail().find("expected 1, got 2"), std::string::npos) << version.what();
    EXPECT_THROW(parseVerbModels(parseJsonText(replaced(modelsText(), "\"version\": 1", "\"version\": 3"), "m.json"), verbs()),
                 InputError);
    EXPECT_THROW(parseHandshapes(replaced(shapesText(), "\"signstim-handshapes\"", "\"x\""), "h.json", handModel()), InputError);
    EXPECT_THROW(askAnimator(replaced(askAnimatorText(), "\"signstim-verb-keyframes\"", "\"signstim-verbs\"")), InputError);
    EXPECT_THROW(askAnimator(replaced(askAnimatorText(), "\"version\": \"animator\"", "\"version\": 2")), InputError);
    const std::string performer = readFile(kScenes / "corpus" / "reference_performer.json");
    EXPECT_THROW(parseReferencePerformer(parseJsonText(replaced(performer, "\"version\": 1", "\"version\": 7"), "p.json"), verbs()),
                 InputError);
}

TEST(Formats, CsvRowsWithExtraFieldsAreRefused) {
    const std::string text = "verb,example,subject,object,hand,keyframe,x,y,z,roll,pitch,yaw\n"
                             "ASK,1,0.3,-0.6,right,0,1,2,3,0,0,0,5\n";
    const InputError e = errorOf([&] { parseCorpus(text, "c.csv", verbs()); });
    EXPECT_EQ(e.line(), 2);
    EXPECT_NE(e.detail().find("13 fields, the header 12"), std::string::npos) << e.what();
}

// ---- 11. A corpus cut short ------------------------------------------------------------------

TEST(CorpusDesign, ACorpusCutShortWarnsWhichPairsAreMissing) {
    const std::string full = readFile(kScenes / "corpus" / "reference_corpus.csv");
    EXPECT_TRUE(parseCorpus(full, "c.csv", verbs()).warnings.empty());
    // The first 5000 bytes, as `head -c 5000` gives: the last row's yaw is cut from -6x.x to -6
    // and ASK keeps 30 of its 42 examples.
    const Corpus corpus = parseCorpus(full.substr(0, 5000), "cut.csv", verbs());
    EXPECT_EQ(corpus.examples.size(), 30u);
    ASSERT_EQ(corpus.warnings.size(), 1u);
    const std::string& warning = corpus.warnings.front();
    EXPECT_NE(warning.find("ASK"), std::string::npos) << warning;
    EXPECT_NE(warning.find("cover 30 of the 42 (subject, object) pairs"), std::string::npos) << warning;
    EXPECT_NE(warning.find("(0.9, 0.3)"), std::string::npos) << warning;
    EXPECT_NE(warning.find("last line has no newline"), std::string::npos) << warning;
    // Object-only verbs are checked against the 7 objects.
    std::string scold = "verb,example,subject,object,hand,keyframe,x,y,z,roll,pitch,yaw\n";
    int example = 0;
    for (const char* object : {"-0.9", "-0.6", "0", "0.3", "0.6", "0.9"}) {
        ++example;
        for (const char* keyframe : {"0", "1"})
            scold += "SCOLD," + std::to_string(example) + ",," + object + ",right," + keyframe + ",1,2,3,0,0,0\n";
    }
    const Corpus objects = parseCorpus(scold, "scold.csv", verbs());
    ASSERT_EQ(objects.warnings.size(), 1u);
    EXPECT_NE(objects.warnings.front().find("6 of the 7 objects"), std::string::npos) << objects.warnings.front();
    EXPECT_NE(objects.warnings.front().find("missing -0.3"), std::string::npos) << objects.warnings.front();
    EXPECT_EQ(objects.warnings.front().find("no newline"), std::string::npos);
}

}  // namespace
}  // namespace signstim::stimuli
