#include "stimuli/verbs/corpus.hpp"

#include "common/number_format.hpp"
#include "stimuli/verbs/signing_space.hpp"
#include "stimuli/verbs/sora.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <map>
#include <tuple>

namespace signstim::stimuli {
namespace {

constexpr std::array<const char*, 12> kColumns{"verb", "example", "subject", "object", "hand", "keyframe",
                                               "x",    "y",       "z",       "roll",   "pitch", "yaw"};

std::string trim(std::string_view text) {
    std::size_t begin = 0;
    std::size_t end = text.size();
    while (begin < end && (text[begin] == ' ' || text[begin] == '\t' || text[begin] == '"')) ++begin;
    while (end > begin && (text[end - 1] == ' ' || text[end - 1] == '\t' || text[end - 1] == '\r' || text[end - 1] == '"')) --end;
    return std::string(text.substr(begin, end - begin));
}

std::vector<std::string> splitCsv(std::string_view line) {
    std::vector<std::string> cells;
    std::size_t start = 0;
    for (;;) {
        const std::size_t comma = line.find(',', start);
        cells.push_back(trim(line.substr(start, comma == std::string_view::npos ? std::string_view::npos : comma - start)));
        if (comma == std::string_view::npos) break;
        start = comma + 1;
    }
    return cells;
}

std::string lowerCase(std::string text) {
    for (char& c : text) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return text;
}

bool parseDouble(const std::string& text, double& value) {
    if (text.empty()) return false;
    const char* begin = text.data();
    const char* end = text.data() + text.size();
    if (*begin == '+') ++begin;
    const auto result = std::from_chars(begin, end, value);
    return result.ec == std::errc() && result.ptr == end && std::isfinite(value);
}

bool parseLong(const std::string& text, long& value) {
    if (text.empty()) return false;
    const auto result = std::from_chars(text.data(), text.data() + text.size(), value);
    return result.ec == std::errc() && result.ptr == text.data() + text.size();
}

// Rounds to 1/scale and turns -0 into 0, so the text never shows "-0.00".
double rounded(double value, double scale) {
    const double r = std::round(value * scale) / scale;
    return r == 0.0 ? 0.0 : r;
}

struct PartialExample {
    CorpusExample example;
    std::vector<std::vector<int>> lines;  // line of each [hand][keyframe], 0 = missing
};

}  // namespace

std::vector<const CorpusExample*> Corpus::examplesOf(std::string_view verb) const {
    std::vector<const CorpusExample*> result;
    for (const CorpusExample& e : examples)
        if (e.verb == verb) result.push_back(&e);
    return result;
}

Corpus parseCorpus(std::string_view text, const std::string& fileName, const VerbLibrary& verbs) {
    text = withoutByteOrderMark(text);
    Corpus corpus;
    corpus.sourceFile = fileName;
    std::array<int, kColumns.size()> columnOf{};
    columnOf.fill(-1);
    bool haveHeader = false;
    std::size_t headerWidth = 0;
    std::map<std::pair<std::string, long>, PartialExample> partial;
    int lineNumber = 0;
    std::size_t position = 0;
    while (position <= text.size()) {
        std::size_t newline = text.find('\n', position);
        if (newline == std::string_view::npos) newline = text.size();
        std::string_view line = text.substr(position, newline - position);
        position = newline + 1;
        ++lineNumber;
        if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
        if (lineNumber == 1 && line.size() >= 3 && line.substr(0, 3) == "\xEF\xBB\xBF") line.remove_prefix(3);
        if (trim(line).empty()) {
            if (newline == text.size()) break;
            continue;
        }
        if (line.front() == '#') {
            corpus.comments.emplace_back(line.substr(1));
            continue;
        }
        const std::vector<std::string> cells = splitCsv(line);
        if (!haveHeader) {
            for (std::size_t c = 0; c < cells.size(); ++c) {
                const std::string name = lowerCase(cells[c]);
                for (std::size_t k = 0; k < kColumns.size(); ++k) {
                    if (name != kColumns[k]) continue;
                    if (columnOf[k] >= 0) throw InputError(fileName, lineNumber, name, "column '" + name + "' appears twice in the header");
                    columnOf[k] = static_cast<int>(c);
                }
            }
            for (std::size_t k = 0; k < kColumns.size(); ++k)
                if (columnOf[k] < 0)
                    throw InputError(fileName, lineNumber, kColumns[k],
                                     std::string("the header lacks column '") + kColumns[k] +
                                         "' (needed: verb,example,subject,object,hand,keyframe,x,y,z,roll,pitch,yaw)");
            haveHeader = true;
            headerWidth = cells.size();
            continue;
        }
        if (cells.size() != headerWidth)
            throw InputError(fileName, lineNumber, "",
                             "the row has " + std::to_string(cells.size()) + " fields, the header " +
                                 std::to_string(headerWidth) + (cells.size() > headerWidth ? " (a comma inside a value?)" : ""));
        const auto cell = [&](std::size_t k) -> const std::string& { return cells[static_cast<std::size_t>(columnOf[k])]; };
        const auto number = [&](std::size_t k) {
            double value = 0.0;
            if (cell(k).empty()) throw InputError(fileName, lineNumber, kColumns[k], "missing value");
            if (!parseDouble(cell(k), value))
                throw InputError(fileName, lineNumber, kColumns[k], "'" + cell(k) + "' is not a number");
            return value;
        };
        const std::string& verbName = cell(0);
        if (verbName.empty()) throw InputError(fileName, lineNumber, "verb", "missing value");
        const VerbDefinition& verb = verbs.get(verbName, fileName, lineNumber, "verb");
        long exampleNumber = 0;
        if (!parseLong(cell(1), exampleNumber) || exampleNumber < 1)
            throw InputError(fileName, lineNumber, "example",
                             cell(1).empty() ? "missing value" : "'" + cell(1) + "' is not a positive integer");
        double subject = 0.0;
        if (!(verb.objectOnly() && cell(2).empty())) {
            subject = number(2);
            checkArcPosition(subject, fileName, "subject");
        }
        const double object = number(3);
        try {
            checkArcPosition(object, fileName, "object");
            if (!verb.objectOnly()) checkArcPosition(subject, fileName, "subject");
        } catch (const InputError& e) {
            throw InputError(fileName, lineNumber, e.field(), e.detail());
        }
        const std::optional<HandSide> side = parseHandSide(lowerCase(cell(4)));
        if (!side) throw InputError(fileName, lineNumber, "hand", "'" + cell(4) + "' is not 'right' or 'left'");
        const int handIndex = verb.handIndex(*side);
        if (handIndex < 0)
            throw InputError(fileName, lineNumber, "hand", verb.name + " is one-handed: only the right hand is modelled");
        long keyframe = 0;
        if (!parseLong(cell(5), keyframe) || keyframe < 0)
            throw InputError(fileName, lineNumber, "keyframe",
                             cell(5).empty() ? "missing value" : "'" + cell(5) + "' is not an integer >= 0");
        if (keyframe >= static_cast<long>(verb.keyframeCount()))
            throw InputError(fileName, lineNumber, "keyframe",
                             verb.name + " has keyframes 0.." + std::to_string(verb.keyframeCount() - 1) +
                                 " (scenes/verbs.json); add keyframes there to train more");
        const auto inRange = [&](std::size_t k, const NumberRange& range) {
            const double value = number(k);
            checkInRange(value, range, fileName, lineNumber, kColumns[k]);
            return value;
        };
        const glm::dvec3 positionMm(inRange(6, kSigningSpacePositionRange), inRange(7, kSigningSpacePositionRange),
                                    inRange(8, kSigningSpacePositionRange));
        const glm::dquat orientation = rollPitchYawDegreesToQuaternion(
            inRange(9, kAngleDegreesRange), inRange(10, kAngleDegreesRange), inRange(11, kAngleDegreesRange));

        PartialExample& entry = partial[{verb.name, exampleNumber}];
        if (entry.lines.empty()) {
            entry.example.verb = verb.name;
            entry.example.example = exampleNumber;
            entry.example.subject = subject;
            entry.example.object = object;
            entry.example.firstLine = lineNumber;
            entry.example.poses.assign(verb.handCount(), std::vector<HandPose>(verb.keyframeCount()));
            entry.lines.assign(verb.handCount(), std::vector<int>(verb.keyframeCount(), 0));
        } else if (entry.example.subject != subject || entry.example.object != object) {
            throw InputError(fileName, lineNumber, entry.example.subject != subject ? "subject" : "object",
                             verb.name + " example " + std::to_string(exampleNumber) +
                                 " has other subject/object positions on line " + std::to_string(entry.example.firstLine));
        }
        int& seen = entry.lines[static_cast<std::size_t>(handIndex)][static_cast<std::size_t>(keyframe)];
        if (seen != 0)
            throw InputError(fileName, lineNumber, "keyframe",
                             "duplicate row: " + verb.name + " example " + std::to_string(exampleNumber) + " " +
                                 toString(*side) + " hand keyframe " + std::to_string(keyframe) +
                                 " is already on line " + std::to_string(seen));
        seen = lineNumber;
        entry.example.poses[static_cast<std::size_t>(handIndex)][static_cast<std::size_t>(keyframe)] =
            HandPose{positionMm, orientation};
        if (newline == text.size()) break;
    }
    if (!haveHeader) throw InputError(fileName, 0, "", "no header line (verb,example,subject,object,hand,keyframe,x,y,z,roll,pitch,yaw)");
    for (const VerbDefinition& verb : verbs.verbs) {
        for (auto& [key, entry] : partial) {
            if (key.first != verb.name) continue;
            for (std::size_t h = 0; h < entry.lines.size(); ++h)
                for (std::size_t k = 0; k < entry.lines[h].size(); ++k)
                    if (entry.lines[h][k] == 0)
                        throw InputError(fileName, entry.example.firstLine, "keyframe",
                                         verb.name + " example " + std::to_string(key.second) + " lacks the " +
                                             toString(verb.hands[h]) + " hand at keyframe " + std::to_string(k));
            corpus.examples.push_back(std::move(entry.example));
        }
    }
    if (corpus.examples.empty()) throw InputError(fileName, 0, "", "the corpus has no examples");
    const bool cutShort = !text.empty() && text.back() != '\n';
    corpus.warnings = designWarnings(corpus, verbs, cutShort);
    return corpus;
}

std::vector<std::string> designWarnings(const Corpus& corpus, const VerbLibrary& verbs, bool lastLineUnterminated) {
    std::vector<std::string> warnings;
    const auto text = [](double p) { return formatNumber(p); };
    for (const VerbDefinition& verb : verbs.verbs) {
        const std::vector<const CorpusExample*> examples = corpus.examplesOf(verb.name);
        if (examples.empty()) continue;
        const auto has = [&](double subject, double object) {
            for (const CorpusExample* e : examples)
                if (std::abs(e->object - object) < 1e-9 && (verb.objectOnly() || std::abs(e->subject - subject) < 1e-9)) return true;
            return false;
        };
        std::vector<std::string> missing;
        std::size_t cells = 0;
        for (double object : kDesignArcPositions) {
            if (verb.objectOnly()) {
                ++cells;
                if (!has(0.0, object)) missing.push_back(text(object));
                continue;
            }
            for (double subject : kDesignArcPositions) {
                if (subject == object) continue;
                ++cells;
                if (!has(subject, object)) missing.push_back("(" + text(subject) + ", " + text(object) + ")");
            }
        }
        if (missing.empty()) continue;
        std::string list;
        for (const std::string& item : missing) list += (list.empty() ? "" : " ") + item;
        warnings.push_back(corpus.sourceFile + ": " + verb.name + ": the examples cover " +
                           std::to_string(cells - missing.size()) + " of the " + std::to_string(cells) +
                           (verb.objectOnly() ? " objects" : " (subject, object) pairs") +
                           " of the SPEC §3.3 design; missing " + list +
                           (lastLineUnterminated ? " (the file's last line has no newline: was it cut short?)" : ""));
    }
    return warnings;
}

Corpus loadCorpus(const std::filesystem::path& path, const VerbLibrary& verbs) {
    const std::string text = readTextFile(path);
    return parseCorpus(text, path.string(), verbs);
}

std::string formatCorpus(const Corpus& corpus, const VerbLibrary& verbs) {
    std::string out;
    for (const std::string& comment : corpus.comments) out += "#" + comment + "\n";
    out += "verb,example,subject,object,hand,keyframe,x,y,z,roll,pitch,yaw\n";
    char buffer[256];
    for (const CorpusExample& example : corpus.examples) {
        const VerbDefinition& verb = verbs.get(example.verb);
        for (std::size_t h = 0; h < example.poses.size(); ++h) {
            for (std::size_t k = 0; k < example.poses[h].size(); ++k) {
                const HandPose& pose = example.poses[h][k];
                const glm::dvec3 rpy = quaternionToRollPitchYawDegrees(pose.orientation);
                std::snprintf(buffer, sizeof buffer, "%s,%ld,%.2f,%.2f,%s,%zu,%.2f,%.2f,%.2f,%.3f,%.3f,%.3f\n",
                              example.verb.c_str(), example.example, rounded(example.subject, 100),
                              rounded(example.object, 100), toString(verb.hands[h]).c_str(), k,
                              rounded(pose.positionMm.x, 100), rounded(pose.positionMm.y, 100),
                              rounded(pose.positionMm.z, 100), rounded(rpy.x, 1000), rounded(rpy.y, 1000),
                              rounded(rpy.z, 1000));
                out += buffer;
            }
        }
    }
    return out;
}

}  // namespace signstim::stimuli
