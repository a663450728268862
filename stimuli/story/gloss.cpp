#include "stimuli/story/gloss.hpp"

#include "common/input_limits.hpp"
#include "stimuli/story/gloss_markers.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <variant>

namespace signstim::stimuli {
namespace {

bool isUpper(char c) { return c >= 'A' && c <= 'Z'; }
bool isLower(char c) { return c >= 'a' && c <= 'z'; }
bool isDigit(char c) { return c >= '0' && c <= '9'; }
bool isSpace(char c) { return c == ' ' || c == '\t'; }

// Hold durations a story may ask for [D]: a beat is ~0.1 s; a hold longer than a few seconds
// reads as the signer freezing, and 10 s is far past any pause a storyteller makes.
constexpr double kMinimumHoldSeconds = 0.05;
constexpr double kMaximumHoldSeconds = 10.0;

struct Cursor {
    std::string_view text;
    std::size_t at = 0;
    int column() const { return static_cast<int>(at) + 1; }
};

std::optional<GlossError> error(std::size_t offset, std::string message) {
    return GlossError{static_cast<int>(offset) + 1, std::move(message)};
}

std::string trimmed(std::string_view s) {
    while (!s.empty() && isSpace(s.front())) s.remove_prefix(1);
    while (!s.empty() && isSpace(s.back())) s.remove_suffix(1);
    return std::string(s);
}

std::optional<double> parseNumber(std::string_view s) {
    if (s.empty()) return std::nullopt;
    const char* begin = s.data();
    if (*begin == '+') ++begin;  // from_chars takes no '+'
    double value = 0.0;
    const auto [end, ec] = std::from_chars(begin, s.data() + s.size(), value);
    if (ec != std::errc() || end != s.data() + s.size() || !std::isfinite(value)) return std::nullopt;
    return value;
}

bool looksNumeric(std::string_view s) {
    return !s.empty() && (isDigit(s.front()) || s.front() == '-' || s.front() == '+' || s.front() == '.');
}

// A gloss word: capitals, digits and hyphens, starting with a capital or digit (STUDENT,
// BENT-B, NAME-SIGN, 3-OF-US).
std::optional<GlossError> checkWord(std::string_view word, std::size_t offset) {
    if (word.empty()) return error(offset, "expected a gloss word");
    for (std::size_t i = 0; i < word.size(); ++i) {
        const char c = word[i];
        if (isLower(c))
            return error(offset + i, "'" + std::string(word) +
                                         "': glosses are written in capitals (fingerspelling: fs-" +
                                         [&] {
                                             std::string upper(word);
                                             for (char& u : upper) u = static_cast<char>(std::toupper(static_cast<unsigned char>(u)));
                                             return upper;
                                         }() +
                                         ")");
        if (!(isUpper(c) || isDigit(c) || (c == '-' && i > 0 && i + 1 < word.size())))
            return error(offset + i, "unexpected character '" + std::string(1, c) + "' in '" + std::string(word) +
                                         "' (a gloss is capitals, digits and inner hyphens)");
    }
    return std::nullopt;
}

// "(a, b, ...)" starting at `open` (the '(' itself); fills arguments; returns the error, if any.
std::optional<GlossError> parseArguments(std::string_view token, std::size_t tokenOffset, std::size_t open,
                                         GlossItem& item) {
    if (token.back() != ')')
        return error(tokenOffset + token.size(), "'" + std::string(token) + "': missing ')'");
    item.hasArgumentList = true;
    const std::string_view inside = token.substr(open + 1, token.size() - open - 2);
    if (trimmed(inside).empty()) return error(tokenOffset + open + 1, "'" + std::string(token) + "': empty parentheses");
    std::size_t start = 0;
    while (start <= inside.size()) {
        std::size_t comma = inside.find(',', start);
        if (comma == std::string_view::npos) comma = inside.size();
        const std::string_view raw = inside.substr(start, comma - start);
        std::size_t lead = 0;
        while (lead < raw.size() && isSpace(raw[lead])) ++lead;
        const std::string argument = trimmed(raw);
        const std::size_t offset = tokenOffset + open + 1 + start + lead;
        GlossArgument parsed;
        parsed.column = static_cast<int>(offset) + 1;
        if (argument.empty()) return error(offset, "'" + std::string(token) + "': empty argument");
        if (looksNumeric(argument)) {
            parsed.position = parseNumber(argument);
            if (!parsed.position)
                return error(offset, "'" + argument + "' is not a number (arc positions are written like 0.9 or -0.6)");
        } else {
            if (auto bad = checkWord(argument, offset)) return bad;
            parsed.name = argument;
        }
        item.arguments.push_back(parsed);
        if (comma == inside.size()) break;
        start = comma + 1;
    }
    return std::nullopt;
}

std::optional<GlossError> parseToken(std::string_view token, std::size_t offset, GlossItem& item) {
    item.text = std::string(token);
    item.column = static_cast<int>(offset) + 1;
    const std::size_t open = token.find('(');
    const std::string_view head = token.substr(0, open);
    if (open == std::string_view::npos && token.find(')') != std::string_view::npos)
        return error(offset + token.find(')'), "')' without '('");

    if (head.size() >= 3 && (head.substr(0, 3) == "fs-" || head.substr(0, 3) == "FS-")) {
        item.kind = GlossItemKind::Fingerspelling;
        if (open != std::string_view::npos) return error(offset + open, "fingerspelling takes no parentheses");
        item.word = std::string(head.substr(3));
        if (item.word.empty()) return error(offset, "'fs-' needs letters: fs-JOHN");
        if (item.word.size() > limits::kFingerspelledLetters)
            return error(offset + 3 + limits::kFingerspelledLetters,
                         std::to_string(item.word.size()) + " letters to fingerspell; at most " +
                             std::to_string(limits::kFingerspelledLetters) + " (docs/errors.md, Limits)");
        for (std::size_t i = 0; i < item.word.size(); ++i) {
            const char c = item.word[i];
            if (isLower(c)) return error(offset + 3 + i, "fingerspelled letters are written in capitals: fs-" +
                                                             [&] {
                                                                 std::string upper = item.word;
                                                                 for (char& u : upper) u = static_cast<char>(std::toupper(static_cast<unsigned char>(u)));
                                                                 return upper;
                                                             }());
            if (!isUpper(c))
                return error(offset + 3 + i, "'" + std::string(1, c) + "' cannot be fingerspelled (letters A to Z only)");
        }
        return std::nullopt;
    }
    if (auto bad = checkWord(head, offset)) return bad;
    item.word = std::string(head);
    if (open != std::string_view::npos)
        if (auto bad = parseArguments(token, offset, open, item)) return bad;

    if (item.word == "IX") {
        item.kind = GlossItemKind::Pointing;
        if (!item.hasArgumentList)
            return error(offset, "IX needs a place: IX(0.9) points at arc position 0.9, IX(JOHN) at JOHN");
        if (item.arguments.size() != 1)
            return error(offset + open, "IX points at one place: IX(0.9) or IX(JOHN)");
        const GlossArgument& place = item.arguments.front();
        if (place.position && !(*place.position >= -1.0 && *place.position <= 1.0))
            return GlossError{place.column, "arc position " + trimmed(token.substr(open + 1, token.size() - open - 2)) +
                                                " is outside [-1, 1] (-1 the signer's far left, 1 far right)"};
        return std::nullopt;
    }
    if (item.word == "HOLD") {
        item.kind = GlossItemKind::Hold;
        if (!item.hasArgumentList) return std::nullopt;
        if (item.arguments.size() != 1 || !item.arguments.front().position)
            return error(offset + open, "HOLD takes one duration in seconds: HOLD(0.5)");
        const double seconds = *item.arguments.front().position;
        if (!(seconds >= kMinimumHoldSeconds && seconds <= kMaximumHoldSeconds))
            return GlossError{item.arguments.front().column,
                              "hold of " + trimmed(token.substr(open + 1, token.size() - open - 2)) +
                                  " s: expected 0.05 to 10 s"};
        item.holdSeconds = seconds;
        return std::nullopt;
    }
    item.kind = GlossItemKind::Word;
    return std::nullopt;
}

}  // namespace

GlossParse parseGloss(std::string_view sentence) {
    GlossParse result;
    auto fail = [&](GlossError e) {
        result.error = std::move(e);
        return result;
    };
    std::vector<GlossMarker> open;  // markers opened and not yet closed, innermost last
    std::size_t at = 0;
    while (at < sentence.size()) {
        if (isSpace(sentence[at])) {
            ++at;
            continue;
        }
        if (sentence[at] == '\n' || sentence[at] == '\r') return fail(GlossError{static_cast<int>(at) + 1, "a sentence is one line"});
        if (sentence[at] == '[') {
            // A marker's head runs to the first space or ']' outside parentheses: "[rs(JOE, 0.5)".
            const std::size_t start = at++;
            int depth = 0;
            while (at < sentence.size() && (depth > 0 || (!isSpace(sentence[at]) && sentence[at] != ']' && sentence[at] != '['))) {
                if (sentence[at] == '(') ++depth;
                if (sentence[at] == ')') --depth;
                if (sentence[at] == '\n' || sentence[at] == '\r') break;
                ++at;
            }
            auto parsed = parseMarkerHead(sentence.substr(start + 1, at - start - 1), start);
            if (auto* bad = std::get_if<GlossError>(&parsed)) return fail(*bad);
            GlossMarker marker = std::get<GlossMarker>(std::move(parsed));
            marker.firstItem = static_cast<int>(result.items.size());
            const MarkerDefinition& definition = *findMarkerByName(marker.name);
            if (definition.markerClass == MarkerClass::Event) {
                // An event stands between signs: [blink], [nod].
                if (at >= sentence.size() || sentence[at] != ']')
                    return fail(GlossError{marker.column, "[" + std::string(definition.written) +
                                                              "] is a single event and covers no signs: write [" +
                                                              std::string(definition.written) + "] between signs"});
                ++at;
                marker.lastItem = marker.firstItem - 1;
                result.markers.push_back(std::move(marker));
                continue;
            }
            for (const GlossMarker& outer : open)
                if (findMarkerByName(outer.name)->markerClass == definition.markerClass)
                    return fail(GlossError{marker.column, "[" + marker.written + "] overlaps [" + outer.written +
                                                              "], still open: one " +
                                                              std::string(toString(definition.markerClass)) +
                                                              " at a time; close it with ']' first"});
            open.push_back(std::move(marker));
            continue;
        }
        if (sentence[at] == ']') {
            if (open.empty())
                return fail(GlossError{static_cast<int>(at) + 1, "']' without '[': a marker is written [neg NOT KNOW]"});
            GlossMarker marker = std::move(open.back());
            open.pop_back();
            marker.lastItem = static_cast<int>(result.items.size()) - 1;
            if (marker.lastItem < marker.firstItem)
                return fail(GlossError{marker.column, "[" + marker.written + "] marks no signs: [" + marker.written + " SIGN ...]"});
            result.markers.push_back(std::move(marker));
            ++at;
            continue;
        }
        // A token runs to the next space, '[' or ']' outside parentheses: "ASK(JOHN, MARY)" is one item.
        const std::size_t start = at;
        int depth = 0;
        while (at < sentence.size() && (depth > 0 || (!isSpace(sentence[at]) && sentence[at] != ']' && sentence[at] != '['))) {
            if (sentence[at] == '(') ++depth;
            if (sentence[at] == ')') --depth;
            if (depth < 0) return fail(GlossError{static_cast<int>(at) + 1, "')' without '('"});
            ++at;
        }
        GlossItem item;
        if (auto bad = parseToken(sentence.substr(start, at - start), start, item)) return fail(*bad);
        result.items.push_back(std::move(item));
    }
    if (!open.empty())
        return fail(GlossError{open.back().column, "[" + open.back().written +
                                                       " is not closed: a marker ends with ']' in its sentence"});
    if (result.items.empty()) return fail(GlossError{1, "empty sentence"});
    std::stable_sort(result.markers.begin(), result.markers.end(), [](const GlossMarker& a, const GlossMarker& b) {
        return a.firstItem != b.firstItem ? a.firstItem < b.firstItem : a.column < b.column;
    });
    return result;
}

std::vector<std::string> closestNames(std::string_view name, const std::vector<std::string>& candidates,
                                      std::size_t count) {
    auto distance = [](std::string_view a, std::string_view b) {
        std::vector<std::size_t> row(b.size() + 1);
        for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
        for (std::size_t i = 1; i <= a.size(); ++i) {
            std::size_t diagonal = row[0];
            row[0] = i;
            for (std::size_t j = 1; j <= b.size(); ++j) {
                const std::size_t above = row[j];
                row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
                diagonal = above;
            }
        }
        return row[b.size()];
    };
    const std::size_t limit = std::max<std::size_t>(1, (name.size() + 2) / 3);
    std::vector<std::pair<std::size_t, std::string>> scored;
    for (const std::string& candidate : candidates) {
        const std::size_t d = distance(name, candidate);
        if (d <= limit) scored.emplace_back(d, candidate);
    }
    std::sort(scored.begin(), scored.end());
    std::vector<std::string> names;
    for (std::size_t i = 0; i < scored.size() && i < count; ++i) names.push_back(scored[i].second);
    return names;
}

}  // namespace signstim::stimuli
