#include "stimuli/story/gloss_markers.hpp"

#include <charconv>
#include <cmath>

namespace signstim::stimuli {
namespace {

GlossError errorAt(std::size_t offset, std::string message) { return GlossError{static_cast<int>(offset) + 1, std::move(message)}; }

char lower(char c) { return c >= 'A' && c <= 'Z' ? static_cast<char>(c - 'A' + 'a') : c; }

bool equalNoCase(std::string_view a, std::string_view b) {
    if (a.size() != b.size()) return false;
    for (std::size_t i = 0; i < a.size(); ++i)
        if (lower(a[i]) != lower(b[i])) return false;
    return true;
}

std::string markerList() {
    std::string list;
    for (const MarkerDefinition& d : markerDefinitions()) list += (list.empty() ? "" : " ") + std::string(d.written);
    return list;
}

bool isNumberStart(char c) { return (c >= '0' && c <= '9') || c == '-' || c == '+' || c == '.'; }

}  // namespace

const std::vector<MarkerDefinition>& markerDefinitions() {
    static const std::vector<MarkerDefinition> definitions{
        {"y/n", "yn-question", MarkerClass::Clause, MarkerArgument::None, "yes/no question"},
        {"wh", "wh-question", MarkerClass::Clause, MarkerArgument::None, "wh-question"},
        {"rhq", "rhetorical-question", MarkerClass::Clause, MarkerArgument::None, "rhetorical question"},
        {"t", "topic", MarkerClass::Clause, MarkerArgument::None, "topic"},
        {"cond", "conditional", MarkerClass::Clause, MarkerArgument::None, "conditional clause"},
        {"neg", "negation", MarkerClass::Head, MarkerArgument::None, "negation (head shake)"},
        {"aff", "affirmation", MarkerClass::Head, MarkerArgument::None, "affirmation (nods)"},
        {"rs", "role-shift", MarkerClass::RoleShift, MarkerArgument::Character, "role shift toward a character"},
        {"mm", "mouth:MM", MarkerClass::Mouth, MarkerArgument::None, "mouth morpheme MM (normally, as expected)"},
        {"oo", "mouth:OO", MarkerClass::Mouth, MarkerArgument::None, "mouth morpheme OO (small, thin)"},
        {"cha", "mouth:CHA", MarkerClass::Mouth, MarkerArgument::None, "mouth morpheme CHA (large)"},
        {"th", "mouth:TH", MarkerClass::Mouth, MarkerArgument::None, "mouth morpheme TH (carelessly)"},
        {"pah", "mouth:PAH", MarkerClass::Mouth, MarkerArgument::None, "mouth morpheme PAH (finally)"},
        {"cs", "mouth:CS", MarkerClass::Mouth, MarkerArgument::None, "mouth morpheme CS (close, recent)"},
        {"puff", "mouth:PUFF", MarkerClass::Mouth, MarkerArgument::None, "puffed cheeks (a lot, large)"},
        {"mouth", "mouthing", MarkerClass::Mouth, MarkerArgument::Word, "mouthing of an English word"},
        {"blink", "blink", MarkerClass::Event, MarkerArgument::None, "a blink"},
        {"nod", "nod", MarkerClass::Event, MarkerArgument::None, "a single nod"},
    };
    return definitions;
}

const MarkerDefinition* findMarker(std::string_view written) {
    if (equalNoCase(written, "yn")) written = "y/n";
    for (const MarkerDefinition& d : markerDefinitions())
        if (equalNoCase(d.written, written)) return &d;
    return nullptr;
}

const MarkerDefinition* findMarkerByName(std::string_view name) {
    for (const MarkerDefinition& d : markerDefinitions())
        if (d.name == name) return &d;
    return nullptr;
}

std::string_view toString(MarkerClass markerClass) {
    switch (markerClass) {
        case MarkerClass::Clause: return "clause marker (y/n, wh, rhq, t, cond)";
        case MarkerClass::Head: return "head marker (neg, aff)";
        case MarkerClass::Mouth: return "mouth marker";
        case MarkerClass::RoleShift: return "role shift";
        case MarkerClass::Event: return "event";
    }
    return "?";
}

std::variant<GlossMarker, GlossError> parseMarkerHead(std::string_view head, std::size_t offset) {
    GlossMarker marker;
    marker.column = static_cast<int>(offset) + 1;
    marker.written = std::string(head);
    const std::size_t open = head.find('(');
    const std::string_view name = head.substr(0, open);
    if (name.empty())
        return errorAt(offset, "'[' starts a non-manual marker: [y/n ...], [wh ...], [neg ...], [t ...] (known: " +
                                   markerList() + ")");
    const MarkerDefinition* definition = findMarker(name);
    if (!definition)
        return errorAt(offset + 1, "unknown non-manual marker '" + std::string(name) + "' (known: " + markerList() +
                                       "; docs/nonmanuals.md)");
    marker.name = std::string(definition->name);
    if (open == std::string_view::npos) {
        if (head.find(')') != std::string_view::npos) return errorAt(offset + 1 + head.find(')'), "')' without '('");
    } else {
        if (head.back() != ')') return errorAt(offset + 1 + head.size(), "'[" + std::string(head) + "': missing ')'");
        const std::string_view inside = head.substr(open + 1, head.size() - open - 2);
        std::size_t start = 0;
        for (;;) {
            std::size_t comma = inside.find(',', start);
            if (comma == std::string_view::npos) comma = inside.size();
            std::string_view part = inside.substr(start, comma - start);
            std::size_t at = offset + 1 + open + 1 + start;  // 0-based offset of `part`
            while (!part.empty() && (part.front() == ' ' || part.front() == '\t')) {
                part.remove_prefix(1);
                ++at;
            }
            while (!part.empty() && (part.back() == ' ' || part.back() == '\t')) part.remove_suffix(1);
            if (part.empty()) return errorAt(at, "'[" + std::string(head) + "': empty argument");
            if (isNumberStart(part.front())) {
                if (marker.intensity) return errorAt(at, "one intensity per marker");
                double value = 0.0;
                const char* first = part.data() + (part.front() == '+' ? 1 : 0);
                const auto [end, ec] = std::from_chars(first, part.data() + part.size(), value);
                if (ec != std::errc() || end != part.data() + part.size() || !std::isfinite(value))
                    return errorAt(at, "'" + std::string(part) + "' is not a number (an intensity is written like 0.5)");
                if (!(value >= kMinimumMarkerIntensity && value <= kMaximumMarkerIntensity))
                    return errorAt(at, "intensity " + std::string(part) + " is outside 0.1 to 1.5 (1: the marker as documented)");
                marker.intensity = value;
            } else if (!marker.argument.empty() || definition->argument == MarkerArgument::None) {
                return errorAt(at, definition->argument == MarkerArgument::None
                                       ? "[" + std::string(definition->written) + "] takes only an intensity: [" +
                                             std::string(definition->written) + "(0.5) ...]"
                                       : "one " + std::string(definition->argument == MarkerArgument::Character ? "character" : "word") +
                                             " per marker");
            } else {
                for (std::size_t i = 0; i < part.size(); ++i) {
                    const char c = part[i];
                    const bool letter = (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z');
                    const bool ok = definition->argument == MarkerArgument::Character
                                        ? (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || (c == '-' && i > 0)
                                        : letter || ((c == '\'' || c == '-') && i > 0);
                    if (!ok)
                        return errorAt(at + i, definition->argument == MarkerArgument::Character
                                                   ? "'" + std::string(part) + "': a character is named by its gloss, in capitals: rs(JOHN)"
                                                   : "'" + std::string(part) + "': a mouthed word is English letters: mouth(pizza)");
                }
                if (definition->argument == MarkerArgument::Word && part.size() > kMaximumMouthedLetters)
                    return errorAt(at, "a mouthed word of " + std::to_string(part.size()) + " letters; at most " +
                                           std::to_string(kMaximumMouthedLetters));
                marker.argument = std::string(part);
                marker.argumentColumn = static_cast<int>(at) + 1;
            }
            if (comma == inside.size()) break;
            start = comma + 1;
        }
    }
    if (definition->argument != MarkerArgument::None && marker.argument.empty())
        return errorAt(offset + 1, definition->argument == MarkerArgument::Character
                                       ? "[rs] needs the character it turns toward: [rs(JOHN) ...]"
                                       : "[mouth] needs the English word mouthed: [mouth(pizza) PIZZA]");
    return marker;
}

}  // namespace signstim::stimuli
