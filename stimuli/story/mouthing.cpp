// Mouthing (issue 23 §4; docs/mouthing.md): espeak-ng's phonemes → visemes → ARKit-52 mouth
// tracks, timed to the span. espeak-ng itself: mouthing_espeak.cpp.
#include "stimuli/story/mouthing.hpp"

#include "common/error.hpp"
#include "stimuli/story/mouthing_espeak.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <iterator>
#include <stdexcept>
#include <string_view>

namespace signstim::stimuli {
namespace {

// The mouth channels mouthing writes, ARKit-52 names (Apple, ARFaceAnchor.BlendShapeLocation).
// The sided ones are written alike on both sides.
enum Channel { Jaw, Close, Funnel, Pucker, Press, Stretch, Smile, RollLower, UpperUp, Tongue, kChannels };
struct ChannelNames {
    const char* names[2];  // one or both sides
};
constexpr ChannelNames kChannelNames[kChannels] = {
    {{"jawOpen", nullptr}},
    {{"mouthClose", nullptr}},
    {{"mouthFunnel", nullptr}},
    {{"mouthPucker", nullptr}},
    {{"mouthPressLeft", "mouthPressRight"}},
    {{"mouthStretchLeft", "mouthStretchRight"}},
    {{"mouthSmileLeft", "mouthSmileRight"}},
    {{"mouthRollLower", nullptr}},
    {{"mouthUpperUpLeft", "mouthUpperUpRight"}},
    {{"tongueOut", nullptr}},
};

// The articulators blend separately (Cohen & Massaro 1993: a dominance per segment and
// articulator): the jaw, the lips, the tongue tip.
enum Group { JawGroup, LipGroup, TongueGroup, kGroups };
constexpr Group groupOf(int channel) {
    return channel == Jaw ? JawGroup : channel == Tongue ? TongueGroup : LipGroup;
}

// The 15 visemes of MPEG-4 (ISO/IEC 14496-2, Annex C: 14 visemes and neutral), by the names of
// the Oculus (Meta) LipSync viseme reference, which uses the same set.
struct VisemeShape {
    const char* name;
    std::array<double, kChannels> weights;  // at intensity 1
    std::array<double, kGroups> dominance;  // how strongly it holds its shape against its neighbours
};
// Weights: ours, set by looking at the default signer's face (docs/mouthing.md, "The table");
// the ARKit shapes each viseme is made of follow the viseme's description (MPEG-4 Annex C, the
// Oculus reference images). Dominance: Cohen & Massaro (1993): the lips of lingual consonants
// (t, d, n, l, k, g) give way to the neighbouring vowels (low lip dominance), the lips of
// bilabials, labiodentals and rounded vowels do not; s and z need the jaw nearly closed.
//                               jaw   close funnel pucker press stretch smile roll  upUp  tongue   jaw   lips  tongue
constexpr VisemeShape kVisemes[] = {
    {"sil", {0.00, 0.00, 0.00, 0.00, 0.00, 0.00, 0.00, 0.00, 0.00, 0.00}, {0.6, 0.6, 0.6}},  // rest
    {"PP", {0.05, 0.00, 0.00, 0.00, 0.45, 0.00, 0.00, 0.00, 0.00, 0.00}, {0.6, 1.0, 0.3}},   // p b m
    {"FF", {0.08, 0.00, 0.00, 0.00, 0.00, 0.00, 0.00, 0.65, 0.20, 0.00}, {0.7, 1.0, 0.3}},   // f v
    {"TH", {0.18, 0.00, 0.00, 0.00, 0.00, 0.10, 0.00, 0.00, 0.00, 0.45}, {0.7, 0.3, 1.0}},   // θ ð
    {"DD", {0.15, 0.00, 0.00, 0.00, 0.00, 0.10, 0.00, 0.00, 0.00, 0.00}, {0.7, 0.2, 0.3}},   // t d
    {"kk", {0.22, 0.00, 0.00, 0.00, 0.00, 0.00, 0.00, 0.00, 0.00, 0.00}, {0.4, 0.2, 0.3}},   // k g ŋ
    {"CH", {0.10, 0.00, 0.55, 0.25, 0.00, 0.00, 0.00, 0.00, 0.15, 0.00}, {0.7, 0.9, 0.3}},   // tʃ dʒ ʃ ʒ
    {"SS", {0.06, 0.00, 0.00, 0.00, 0.00, 0.30, 0.10, 0.00, 0.00, 0.00}, {0.9, 0.3, 0.3}},   // s z
    {"nn", {0.18, 0.00, 0.00, 0.00, 0.00, 0.00, 0.00, 0.00, 0.00, 0.00}, {0.5, 0.2, 0.3}},   // n l
    {"RR", {0.12, 0.00, 0.25, 0.35, 0.00, 0.00, 0.00, 0.00, 0.00, 0.00}, {0.5, 0.7, 0.3}},   // r ɝ
    {"aa", {0.60, 0.00, 0.00, 0.00, 0.00, 0.10, 0.00, 0.00, 0.00, 0.00}, {1.0, 0.8, 0.3}},   // ɑ æ ʌ
    {"E", {0.35, 0.00, 0.00, 0.00, 0.00, 0.25, 0.10, 0.00, 0.00, 0.00}, {1.0, 0.8, 0.3}},    // ɛ e ə
    {"ih", {0.15, 0.00, 0.00, 0.00, 0.00, 0.35, 0.20, 0.00, 0.00, 0.00}, {1.0, 0.8, 0.3}},   // ɪ i j
    {"oh", {0.42, 0.00, 0.50, 0.15, 0.00, 0.00, 0.00, 0.00, 0.00, 0.00}, {1.0, 1.0, 0.3}},   // ɔ ɒ o
    {"ou", {0.12, 0.00, 0.35, 0.65, 0.00, 0.00, 0.00, 0.00, 0.00, 0.00}, {1.0, 1.0, 0.3}},   // ʊ u w
};
constexpr int kBilabial = 1, kLabiodental = 2;  // indices in kVisemes

int visemeIndex(std::string_view name) {
    for (int i = 0; i < static_cast<int>(std::size(kVisemes)); ++i)
        if (name == kVisemes[i].name) return i;
    throw std::logic_error("mouthing: no viseme " + std::string(name));
}

// espeak-ng's English phoneme names (espeak-ng's phsource/ph_english, its docs/phonemes.md) →
// visemes; a diphthong has two. "h" and the glottal stop have no lip shape of their own: they
// take their neighbours' (an empty list).
struct PhonemeVisemes {
    std::string_view phoneme;
    std::array<std::string_view, 2> visemes;
};
constexpr PhonemeVisemes kPhonemes[] = {
    {"p", {"PP"}}, {"b", {"PP"}}, {"m", {"PP"}},                                 // bilabials
    {"f", {"FF"}}, {"v", {"FF"}},                                                // labiodentals
    {"T", {"TH"}}, {"D", {"TH"}},                                                // dentals
    {"t", {"DD"}}, {"d", {"DD"}},                                                // alveolar stops
    {"k", {"kk"}}, {"g", {"kk"}}, {"N", {"kk"}}, {"x", {"kk"}},                  // velars
    {"tS", {"CH"}}, {"dZ", {"CH"}}, {"S", {"CH"}}, {"Z", {"CH"}},                // postalveolars
    {"s", {"SS"}}, {"z", {"SS"}},                                                // sibilants
    {"n", {"nn"}}, {"l", {"nn"}},                                                // n l
    {"r", {"RR"}}, {"3", {"RR"}}, {"3:", {"RR"}},                                // r, r-coloured vowels
    {"w", {"ou"}}, {"j", {"ih"}},                                                // glides
    {"h", {}}, {"?", {}},                                                        // no lip shape
    {"a", {"aa"}}, {"A", {"aa"}}, {"A:", {"aa"}}, {"aa", {"aa"}}, {"V", {"aa"}},  // open vowels
    {"E", {"E"}}, {"e", {"E"}}, {"@", {"E"}},                                    // mid, schwa
    {"i", {"ih"}}, {"i:", {"ih"}}, {"I", {"ih"}},                                // close front
    {"0", {"oh"}}, {"O", {"oh"}}, {"O:", {"oh"}}, {"o", {"oh"}},                 // back rounded
    {"U", {"ou"}}, {"u:", {"ou"}}, {"u", {"ou"}},                                // close rounded
    {"aI", {"aa", "ih"}}, {"aU", {"aa", "ou"}}, {"eI", {"E", "ih"}},              // diphthongs
    {"oU", {"oh", "ou"}}, {"OI", {"oh", "ih"}},
    {"A@", {"aa", "RR"}}, {"O@", {"oh", "RR"}}, {"o@", {"oh", "RR"}}, {"e@", {"E", "RR"}},
    {"i@", {"ih", "RR"}}, {"U@", {"ou", "RR"}}, {"aI@", {"aa", "ih"}}, {"aU@", {"aa", "ou"}},
    {"@L", {"E", "nn"}},
};

const PhonemeVisemes* findPhoneme(std::string_view name) {
    for (const PhonemeVisemes& entry : kPhonemes)
        if (entry.phoneme == name) return &entry;
    return nullptr;
}

// espeak-ng marks variants of a phoneme with a trailing digit or sign ("t2", "a#", "@2", "n-",
// "l/"): the lips are those of the plain phoneme. Unknown names fall back to their first
// character, and failing that to no shape of their own.
const PhonemeVisemes* lookUpPhoneme(std::string name) {
    while (!name.empty()) {
        if (const PhonemeVisemes* entry = findPhoneme(name)) return entry;
        if (name.size() == 1) break;
        const char last = name.back();
        if (std::isdigit(static_cast<unsigned char>(last)) || std::string_view("#-/;!~^").find(last) != std::string_view::npos)
            name.pop_back();
        else
            name.resize(1);
    }
    return nullptr;
}

// The letters said: ASCII letters lowercased (espeak-ng spells some all-capital words letter by
// letter, and gloss is written in capitals), apostrophes kept, anything else a word break.
std::string sayable(const std::string& word) {
    std::string text;
    std::size_t letters = 0;
    bool gap = false;
    for (const char c : word) {
        const auto u = static_cast<unsigned char>(c);
        if (std::isalpha(u) && u < 0x80) {
            if (gap && !text.empty()) text += ' ';
            gap = false;
            text += static_cast<char>(std::tolower(u));
            ++letters;
        } else if (c == '\'' && !text.empty() && !gap) {
            text += c;
        } else {
            gap = true;
        }
    }
    if (letters == 0) return {};
    if (letters > kMouthedLetters)
        throw InputError("a mouthed word has at most " + std::to_string(kMouthedLetters) + " letters; '" +
                         word.substr(0, 60) + "' has " + std::to_string(letters));
    return text;
}

// Visemes with their index in kVisemes (-1: the phoneme's own shape is its neighbours').
struct TimedViseme {
    MouthingViseme shown;
    int index = -1;
};

// How long each phoneme is said, relative to the others (the span sets the total): nominal ms
// of the magnitudes espeak-ng 1.51 gives at its default rate of 175 words a minute (its phoneme
// events for about 30 common words, looked at while writing this; docs/mouthing.md, "Timing"),
// by class and stress. The events' own times are not used: they move by 1 ms to tens of ms with
// what was said before (espeak-ng's wave generator keeps state), and the same word must give the
// same tracks in every run.
bool isVowel(const std::string& name) {
    return std::string_view("aAeEiIoOuU03V@").find(name[0]) != std::string_view::npos;
}
double nominalMs(const mouthing_detail::SpokenPhoneme& phoneme, const PhonemeVisemes* entry) {
    const std::string& name = phoneme.name;
    if (isVowel(name)) {
        const bool reduced = name[0] == '@' || name == "a#" || (name == "3" && phoneme.stress == 0);
        double ms = phoneme.stress == 2 ? 170.0 : phoneme.stress == 1 ? 130.0 : reduced ? 60.0 : 90.0;
        if (entry != nullptr && !entry->visemes[1].empty()) ms *= 1.25;  // diphthongs
        else if (name.find(':') != std::string::npos) ms *= 1.15;         // long vowels
        return ms;
    }
    switch (name[0]) {
        case 'p': case 'b': case 't': case 'd': case 'k': case 'g': case '?': return 70.0;   // stops
        case 'm': case 'n': case 'N': return 75.0;                                           // nasals
        case 'l': case 'r': case 'w': case 'j': return 65.0;                                 // approximants
        default: return 90.0;                                                                // fricatives, affricates, h
    }
}

std::vector<TimedViseme> timedVisemes(const std::string& word) {
    const std::string text = sayable(word);
    if (text.empty()) return {};
    std::vector<TimedViseme> visemes;
    double ms = 0.0;
    for (const mouthing_detail::SpokenPhoneme& phoneme : mouthing_detail::sayWord(text)) {
        if (phoneme.name.empty() || phoneme.name[0] == '_') continue;  // pauses: none inside a mouthed word
        const PhonemeVisemes* entry = lookUpPhoneme(phoneme.name);
        const double startMs = ms, endMs = ms + nominalMs(phoneme, entry);
        ms = endMs;
        const std::string_view first = entry != nullptr ? entry->visemes[0] : std::string_view();
        const std::string_view second = entry != nullptr ? entry->visemes[1] : std::string_view();
        const double middleMs = second.empty() ? endMs : 0.5 * (startMs + endMs);
        visemes.push_back({{phoneme.name, std::string(first.empty() ? "-" : first), startMs, middleMs},
                           first.empty() ? -1 : visemeIndex(first)});
        if (!second.empty())
            visemes.push_back({{phoneme.name, std::string(second), middleMs, endMs}, visemeIndex(second)});
    }
    return visemes;
}

// Cohen & Massaro (1993), "Modeling coarticulation in synthetic visual speech": a segment's
// dominance falls off exponentially with the time from its centre, D(t) = α·exp(−θ·|t − c|),
// and an articulator's value is the dominance-weighted mean of the segments' targets. θ: ours,
// per second of the word as spoken, by group (jaw, lips, tongue): the lips' falls off slowest, so
// anticipatory lip rounding reaches a consonant or two before a rounded vowel (a neighbour
// 100 ms away weighs e^−1.5 of its α); the jaw and the tongue tip blend with their next
// neighbours only (e^−2.5 at 100 ms).
constexpr std::array<double, kGroups> kDominanceFalloffPerSecond = {25.0, 15.0, 25.0};

double roundedWeight(double value, double intensity) {
    // 4 decimals: a weight finer than 1e-4 is invisible, and the JSON stays short.
    return std::clamp(std::round(value * 1e4) / 1e4, 0.0, intensity);
}

}  // namespace

std::vector<MouthingViseme> mouthingVisemes(const std::string& word) {
    std::vector<MouthingViseme> shown;
    for (TimedViseme& viseme : timedVisemes(word)) shown.push_back(std::move(viseme.shown));
    return shown;
}

void loadMouthingSynthesizer(const std::string& espeakDataPath) { mouthing_detail::loadSynthesizer(espeakDataPath); }

std::vector<NonManualTrack> mouthingTracks(const std::string& word, double startSeconds, double endSeconds,
                                           double intensity) {
    if (!std::isfinite(startSeconds) || !std::isfinite(endSeconds) || !(endSeconds > startSeconds))
        throw std::invalid_argument("mouthingTracks: the span must be finite and increasing");
    if (!(intensity >= 0.0 && intensity <= 1.0))
        throw std::invalid_argument("mouthingTracks: the intensity must be within [0, 1]");
    const std::vector<TimedViseme> visemes = timedVisemes(word);
    if (visemes.empty() || intensity == 0.0) return {};

    // The spoken word fills the span.
    const double spokenMs = visemes.back().shown.endMs;
    const double scale = (endSeconds - startSeconds) / spokenMs;
    auto at = [&](double ms) { return startSeconds + ms * scale; };

    // Each viseme's centre (where the blend is computed) and its keys: one at the centre, or,
    // for a closure of the lips (p b m f v), two at 30 % and 70 % of it so the closure holds.
    // Coarticulation is computed in the word's nominal time, as it is spoken: stretching the
    // mouthing to a long sign slows it down without changing how the shapes blend.
    struct KeyAt {
        std::size_t viseme;
        double ms;
    };
    std::vector<double> centresMs;
    std::vector<KeyAt> keyTimes;
    for (std::size_t i = 0; i < visemes.size(); ++i) {
        const double a = visemes[i].shown.startMs, b = visemes[i].shown.endMs;
        centresMs.push_back(0.5 * (a + b));
        if (visemes[i].index == kBilabial || visemes[i].index == kLabiodental) {
            keyTimes.push_back({i, a + 0.3 * (b - a)});
            keyTimes.push_back({i, a + 0.7 * (b - a)});
        } else {
            keyTimes.push_back({i, centresMs.back()});
        }
    }

    std::array<std::vector<double>, kChannels> values;
    for (const KeyAt& key : keyTimes) {
        std::array<double, kChannels> blended{};
        for (int channel = 0; channel < kChannels; ++channel) {
            if (channel == Close) continue;  // set below, at the lip closures only
            const Group group = groupOf(channel);
            double weighted = 0.0, total = 0.0;
            for (std::size_t j = 0; j < visemes.size(); ++j) {
                if (visemes[j].index < 0) continue;  // h, glottal stop: no shape of their own
                const VisemeShape& shape = kVisemes[visemes[j].index];
                const double dominance =
                    shape.dominance[group] * std::exp(-kDominanceFalloffPerSecond[group] * 1e-3 * std::abs(key.ms - centresMs[j]));
                weighted += dominance * shape.weights[channel];
                total += dominance;
            }
            blended[channel] = total > 0.0 ? weighted / total : 0.0;
        }
        // The lips close fully at p, b, m whatever the neighbours (the one thing a viewer
        // lip-reads without fail): the jaw stays where the blend puts it, at most a third open,
        // mouthClose brings the lower lip up by as much (ARKit: used with jawOpen), and nothing
        // that parts the lips remains. At f, v the lower lip rolls under the upper teeth.
        const int index = visemes[key.viseme].index;
        if (index == kBilabial) {
            const VisemeShape& shape = kVisemes[kBilabial];
            blended[Jaw] = std::min(blended[Jaw], 0.3);
            blended[Close] = blended[Jaw];
            blended[Press] = std::max(blended[Press], shape.weights[Press]);
            blended[Funnel] = blended[UpperUp] = blended[Tongue] = blended[RollLower] = 0.0;
        } else if (index == kLabiodental) {
            const VisemeShape& shape = kVisemes[kLabiodental];
            blended[RollLower] = std::max(blended[RollLower], shape.weights[RollLower]);
            blended[Funnel] = blended[Tongue] = 0.0;
        }
        for (int channel = 0; channel < kChannels; ++channel)
            values[channel].push_back(roundedWeight(intensity * blended[channel], intensity));
    }

    std::vector<NonManualTrack> tracks;
    for (int channel = 0; channel < kChannels; ++channel) {
        if (std::none_of(values[channel].begin(), values[channel].end(), [](double v) { return v > 0.0; })) continue;
        NonManualTrack track;
        track.keys.push_back({startSeconds, 0.0});
        for (std::size_t k = 0; k < keyTimes.size(); ++k) track.keys.push_back({at(keyTimes[k].ms), values[channel][k]});
        track.keys.push_back({endSeconds, 0.0});
        for (const char* name : kChannelNames[channel].names) {
            if (name == nullptr) continue;
            track.channel = name;
            tracks.push_back(track);
        }
    }
    return tracks;
}

}  // namespace signstim::stimuli
