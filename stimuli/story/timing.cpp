#include "stimuli/story/timing.hpp"

#include "common/number_format.hpp"
#include "stimuli/story/timeline_builder.hpp"

#include <functional>
#include <vector>

namespace signstim::stimuli {
namespace {

using json = nlohmann::json;

// The fields a `timing` object may give: JSON name, range, and the option it sets.
struct TimingField {
    const char* name;
    double low, high;
    bool flag;  // true/false
    std::function<void(TimelineOptions&, double)> set;
};

const std::vector<TimingField>& timingFields() {
    static const std::vector<TimingField> fields{
        {"boundaryLengthening", 1.0, 2.0, false, [](TimelineOptions& o, double v) { o.boundaryLengthening = v; }},
        {"repetitionShortening", 0.5, 1.0, false, [](TimelineOptions& o, double v) { o.repetitionShortening = v; }},
        {"pauseShare", 0.0, 0.5, false, [](TimelineOptions& o, double v) { o.pauseShare = v; }},
        {"boundaryHoldSeconds", 0.0, 2.0, false, [](TimelineOptions& o, double v) { o.boundaryHoldSeconds = v; }},
        {"boundaryHoldMinimumSeconds", 0.0, 2.0, false, [](TimelineOptions& o, double v) { o.boundaryHoldMinimumSeconds = v; }},
        {"boundaryHoldMaximumSeconds", 0.0, 2.0, false, [](TimelineOptions& o, double v) { o.boundaryHoldMaximumSeconds = v; }},
        {"restBetweenSentences", 0.0, 1.0, true, [](TimelineOptions& o, double v) { o.restBetweenSentences = v != 0.0; }},
        {"sentencePauseSeconds", 0.0, 5.0, false, [](TimelineOptions& o, double v) { o.sentencePauseSeconds = v; }},
        {"restSeconds", 0.0, 5.0, false, [](TimelineOptions& o, double v) { o.restSeconds = v; }},
        {"holdSeconds", 0.0, 5.0, false, [](TimelineOptions& o, double v) { o.holdSeconds = v; }},
        {"signScale", 0.3, 3.0, false, [](TimelineOptions& o, double v) { o.signScale = v; }},
        {"pointingSeconds", 0.05, 2.0, false, [](TimelineOptions& o, double v) { o.pointingSeconds = v; }},
        {"letterSeconds", 0.03, 1.0, false, [](TimelineOptions& o, double v) { o.letterSeconds = v; }},
        {"letterTransitionSeconds", 0.02, 1.0, false, [](TimelineOptions& o, double v) { o.letterTransitionSeconds = v; }},
        {"coarticulation", 0.0, 1.0, true, [](TimelineOptions& o, double v) { o.coarticulation = v != 0.0; }},
        {"fittsTransitions", 0.0, 1.0, true, [](TimelineOptions& o, double v) { o.fittsTransitions = v != 0.0; }},
        {"fittsInterceptSeconds", 0.0, 1.0, false, [](TimelineOptions& o, double v) { o.fittsInterceptSeconds = v; }},
        {"fittsSecondsPerBit", 0.0, 1.0, false, [](TimelineOptions& o, double v) { o.fittsSecondsPerBit = v; }},
        {"fittsWidthMm", 1.0, 500.0, false, [](TimelineOptions& o, double v) { o.fittsWidthMm = v; }},
        {"fittsContactWidthMm", 1.0, 500.0, false, [](TimelineOptions& o, double v) { o.fittsContactWidthMm = v; }},
        {"verbTransitionSeconds", 0.0, 2.0, false, [](TimelineOptions& o, double v) { o.verbTransitionSeconds = v; }},
        // 0: no limit (legacy); else at least a slow hand's speed.
        {"peakWristSpeed", 0.0, 5.0, false, [](TimelineOptions& o, double v) { o.peakSpeedMmPerSecond = v * 1000.0; }},
    };
    return fields;
}

const TimingField* findField(const std::string& name) {
    for (const TimingField& f : timingFields())
        if (name == f.name) return &f;
    return nullptr;
}

}  // namespace

StoryTiming parseStoryTiming(const JsonSource& source, const json& object, const std::string& pointer) {
    if (!object.is_object())
        source.failAt(pointer, "expected an object: {\"preset\": \"natural\"} or {\"preset\": \"legacy\"}, and named fields");
    StoryTiming timing;
    timing.line = std::max(1, source.lineAt(pointer));
    for (auto it = object.begin(); it != object.end(); ++it) {
        const std::string at = pointer + "/" + jsonPointerToken(it.key());
        if (it.key() == "preset") {
            if (!it.value().is_string() || (it.value() != "natural" && it.value() != "legacy"))
                source.failAt(at, "expected \"natural\" (SPEC §6.3) or \"legacy\" (the timing before issue 21)");
            timing.preset = it.value().get<std::string>();
            continue;
        }
        const TimingField* field = findField(it.key());
        if (!field) {
            std::string known = "preset";
            for (const TimingField& f : timingFields()) known += std::string(", ") + f.name;
            source.failAt(at, "unknown timing field '" + it.key() + "' (known: " + known + ")");
        }
        if (field->flag) {
            if (!it.value().is_boolean()) source.failAt(at, "expected true or false");
            timing.fields[field->name] = it.value().get<bool>() ? 1.0 : 0.0;
        } else {
            timing.fields[field->name] = source.number(it.value(), at, NumberRange{field->low, field->high, ""});
        }
    }
    const auto value = [&](const char* name, double otherwise) {
        const auto it = timing.fields.find(name);
        return it == timing.fields.end() ? otherwise : it->second;
    };
    const TimelineOptions base = timing.preset == "legacy" ? legacyTimelineOptions() : TimelineOptions{};
    if (value("boundaryHoldMinimumSeconds", base.boundaryHoldMinimumSeconds) >
        value("boundaryHoldMaximumSeconds", base.boundaryHoldMaximumSeconds))
        source.failAt(pointer + (timing.fields.count("boundaryHoldMinimumSeconds") ? "/boundaryHoldMinimumSeconds"
                                                                                    : "/boundaryHoldMaximumSeconds"),
                      "the boundary hold's minimum is above its maximum");
    const double peak = value("peakWristSpeed", base.peakSpeedMmPerSecond / 1000.0);
    if (peak > 0.0 && peak < 0.5)
        source.failAt(pointer + "/peakWristSpeed", "expected 0 (no limit) or 0.5 to 5 m/s (SPEC §6.2 gives 2.5)");
    return timing;
}

std::string describeTiming(const StoryTiming& timing) {
    std::string text = timing.preset;
    for (const auto& [name, value] : timing.fields) {
        const TimingField* field = findField(name);
        text += ", " + name + " " + (field && field->flag ? std::string(value != 0.0 ? "true" : "false") : formatNumber(value));
    }
    return text;
}

TimelineOptions timelineOptionsFor(const StoryTiming& timing, double rate) {
    TimelineOptions options = timing.preset == "legacy" ? legacyTimelineOptions() : TimelineOptions{};
    for (const auto& [name, value] : timing.fields)
        if (const TimingField* field = findField(name)) field->set(options, value);
    options.rate = rate;
    return options;
}

}  // namespace signstim::stimuli
