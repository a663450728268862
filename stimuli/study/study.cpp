#include "stimuli/study/study.hpp"

#include "common/error.hpp"
#include "common/number_format.hpp"
#include "common/sha256.hpp"
#include "stimuli/json_source.hpp"
#include "stimuli/story/story.hpp"

#include <algorithm>
#include <cstdio>
#include <set>

namespace signstim::stimuli {
namespace {

using nlohmann::json;

class StudyReader {
public:
    explicit StudyReader(const JsonSource& source) : source_(source) {}

    StudyFile read() {
        const json& root = source_.root;
        study_.file = source_.file;
        if (!root.is_object()) source_.failAt("", "a study file is a JSON object {\"format\": \"signstim-study\", ...}");
        knownKeys(root, "", {"format", "version", "title", "seed", "participants", "versions", "stories", "phase2",
                             "likertScale", "render", "quick", "outputs", "notes", "order", "session",
                             "humanVersions"});
        if (!root.contains("format")) source_.failAt("", "missing \"format\": \"signstim-study\"");
        source_.checkFormat("signstim-study", kStudyFormatVersion);
        if (!root.contains("version")) source_.failAt("", "missing \"version\": " + std::to_string(kStudyFormatVersion));
        study_.title = string(root, "", "title");
        study_.seed = static_cast<std::uint64_t>(integer(root, "", "seed", 0, 9007199254740991LL));  // 2^53 - 1: exact in JSON
        study_.participants = static_cast<std::size_t>(integer(root, "", "participants", 1, 10000));
        study_.participantsLine = source_.lineAt("/participants");
        readVersions(member(root, "", "versions"));
        readStories(member(root, "", "stories"));
        if (root.contains("humanVersions")) {
            std::vector<std::string> names;
            for (VerbVersion v : study_.versions) names.push_back(toString(v));
            study_.humanVersions = parseHumanVersions(source_, root["humanVersions"], names);
        }
        if (root.contains("phase2")) readPhase2(root["phase2"]);
        if (root.contains("likertScale")) readScale(root["likertScale"]);
        study_.render = readRender(member(root, "", "render"), "/render", StudyRenderSettings{});
        study_.quick.timing = study_.render.timing;
        study_.quick.nonManuals = study_.render.nonManuals;
        if (root.contains("quick")) study_.quick = readRender(root["quick"], "/quick", study_.quick);
        if (root.contains("outputs")) {
            const json& outputs = root["outputs"];
            if (!outputs.is_object())
                source_.failAt("/outputs", "expected {\"pngFrames\": false, \"experiment\": \"jspsych\"}");
            knownKeys(outputs, "/outputs", {"pngFrames", "experiment", "regions", "elan"});
            for (const char* key : {"regions", "elan"}) {
                if (!outputs.contains(key)) continue;
                if (!outputs[key].is_boolean()) source_.failAt(std::string("/outputs/") + key, "expected true or false");
                (std::string(key) == "regions" ? study_.regions : study_.elan) = outputs[key].get<bool>();
            }
            if (outputs.contains("pngFrames")) {
                if (!outputs["pngFrames"].is_boolean()) source_.failAt("/outputs/pngFrames", "expected true or false");
                study_.pngFrames = outputs["pngFrames"].get<bool>();
            }
            if (outputs.contains("experiment")) {
                const json& experiment = outputs["experiment"];
                const std::string name = experiment.is_string() ? experiment.get<std::string>() : "";
                if (name != "jspsych" && name != "none")
                    source_.failAt("/outputs/experiment",
                                   "expected \"jspsych\" (a ready-to-run jsPsych experiment, docs/experiment.md) or \"none\"");
                study_.experiment = name;
            }
        }
        if (root.contains("order")) {
            const json& order = root["order"];
            const std::string name = order.is_string() ? order.get<std::string>() : "";
            if (name == "balanced") study_.order = StoryOrder::Balanced;
            else if (name != "random")
                source_.failAt("/order", "expected \"random\" (each participant's own shuffle, the default) or "
                                         "\"balanced\" (every version equally often at every trial position, "
                                         "a Williams-type design; docs/study.md)");
        }
        if (root.contains("session")) readSession(root["session"]);
        if (root.contains("notes") && !root["notes"].is_string()) source_.failAt("/notes", "expected text");
        checkDesign();
        return study_;
    }

private:
    void knownKeys(const json& object, const std::string& pointer, std::initializer_list<const char*> known) {
        for (const auto& item : object.items()) {
            const std::string& key = item.key();
            if (std::find_if(known.begin(), known.end(), [&](const char* k) { return key == k; }) != known.end()) continue;
            std::string list;
            for (const char* k : known) list += (list.empty() ? "" : ", ") + std::string(k);
            source_.failAt(pointer + "/" + jsonPointerToken(key), "unknown field '" + key + "' (known: " + list + ")");
        }
    }

    const json& member(const json& object, const std::string& pointer, const std::string& key) {
        if (!object.contains(key)) source_.failAt(pointer, "missing field \"" + key + "\"");
        return object[key];
    }

    std::string string(const json& object, const std::string& pointer, const std::string& key) {
        const json& value = member(object, pointer, key);
        if (!value.is_string() || value.get<std::string>().empty())
            source_.failAt(pointer + "/" + key, "expected non-empty text");
        return value.get<std::string>();
    }

    long long integer(const json& object, const std::string& pointer, const std::string& key, long long low,
                      long long high) {
        const json& value = member(object, pointer, key);
        const std::string at = pointer + "/" + key;
        if (!value.is_number_integer())
            source_.failAt(at, "expected a whole number from " + std::to_string(low) + " to " + std::to_string(high));
        // Unsigned values above the signed range are out of range too.
        if (value.is_number_unsigned() && value.get<unsigned long long>() > static_cast<unsigned long long>(high))
            source_.failAt(at, value.dump() + " is out of range (" + std::to_string(low) + " to " + std::to_string(high) + ")");
        const long long n = value.get<long long>();
        if (n < low || n > high)
            source_.failAt(at, std::to_string(n) + " is out of range (" + std::to_string(low) + " to " + std::to_string(high) + ")");
        return n;
    }

    StudyFile::StoryEntry storyEntry(const json& value, const std::string& pointer) {
        if (!value.is_string() || value.get<std::string>().empty())
            source_.failAt(pointer, "expected the path of a story file (relative to this study file)");
        StudyFile::StoryEntry entry;
        entry.written = value.get<std::string>();
        const std::filesystem::path written(entry.written);
        entry.path = written.is_absolute() ? written : std::filesystem::path(source_.file).parent_path() / written;
        entry.line = source_.lineAt(pointer);
        return entry;
    }

    void readVersions(const json& list) {
        study_.versionsLine = source_.lineAt("/versions");
        if (!list.is_array() || list.empty())
            source_.failAt("/versions", "expected a list of versions, e.g. [\"point\", \"vector\", \"animator\", \"uninflected\"]");
        for (std::size_t i = 0; i < list.size(); ++i) {
            const std::string at = "/versions/" + std::to_string(i);
            const std::optional<VerbVersion> version =
                list[i].is_string() ? parseVerbVersion(list[i].get<std::string>()) : std::nullopt;
            if (!version) source_.failAt(at, "expected one of \"point\", \"vector\", \"animator\", \"uninflected\"");
            if (std::find(study_.versions.begin(), study_.versions.end(), *version) != study_.versions.end())
                source_.failAt(at, "\"" + toString(*version) + "\" is listed twice");
            study_.versions.push_back(*version);
        }
    }

    void readStories(const json& list) {
        study_.storiesLine = source_.lineAt("/stories");
        if (!list.is_array() || list.empty()) source_.failAt("/stories", "expected a list of story files");
        std::set<std::string> seen;
        for (std::size_t i = 0; i < list.size(); ++i) {
            const std::string at = "/stories/" + std::to_string(i);
            StudyFile::StoryEntry entry = storyEntry(list[i], at);
            if (!seen.insert(entry.path.lexically_normal().string()).second)
                source_.failAt(at, "\"" + entry.written + "\" is listed twice (a participant sees each story once)");
            study_.stories.push_back(std::move(entry));
        }
    }

    void readPhase2(const json& phase2) {
        study_.phase2Line = source_.lineAt("/phase2");
        if (!phase2.is_object())
            source_.failAt("/phase2", "expected {\"story\": \"sentences.json\", \"sentences\": [1, 2, ...]}");
        knownKeys(phase2, "/phase2", {"story", "sentences"});
        study_.phase2Story = storyEntry(member(phase2, "/phase2", "story"), "/phase2/story");
        if (!phase2.contains("sentences")) return;
        const json& list = phase2["sentences"];
        if (!list.is_array() || list.empty())
            source_.failAt("/phase2/sentences", "expected a list of sentence numbers (1-based) of the phase-2 story");
        for (std::size_t i = 0; i < list.size(); ++i) {
            const std::string at = "/phase2/sentences/" + std::to_string(i);
            if (!list[i].is_number_integer() || list[i].get<long long>() < 1 || list[i].get<long long>() > 1000)
                source_.failAt(at, "expected a sentence number (1-based)");
            const int index = static_cast<int>(list[i].get<long long>()) - 1;
            if (std::find(study_.phase2Sentences.begin(), study_.phase2Sentences.end(), index) != study_.phase2Sentences.end())
                source_.failAt(at, "sentence " + std::to_string(index + 1) + " is listed twice");
            study_.phase2Sentences.push_back(index);
        }
    }

    void readSession(const json& session) {
        if (!session.is_object())
            source_.failAt("/session", "expected {\"ratingPrompt\": \"...\", \"background\": [\"hearing\", ...]}");
        knownKeys(session, "/session", {"ratingPrompt", "background", "questions", "instructions"});
        study_.sessionLine = source_.lineAt("/session");
        if (session.contains("ratingPrompt")) study_.ratingPrompt = string(session, "/session", "ratingPrompt");
        // Issue 24: questions and instructions in ASL (question_clips.hpp).
        const auto show = [&](const json& value, const std::string& at) {
            const std::string text = value.is_string() ? value.get<std::string>() : "";
            if (!isShowChoice(text))
                source_.failAt(at, "expected \"asl\" (the signed clip), \"english\" (the text) or \"both\" (the default)");
            return text;
        };
        if (session.contains("questions")) study_.questionsShown = show(session["questions"], "/session/questions");
        if (session.contains("instructions")) {
            const json& instructions = session["instructions"];
            if (!instructions.is_object())
                source_.failAt("/session/instructions",
                               "expected {\"show\": \"both\", \"welcome\": {\"text\": ..., \"gloss\": [...]}, \"part2\": {...}}");
            if (instructions.contains("show"))
                study_.instructionsShown = show(instructions["show"], "/session/instructions/show");
            study_.instructions = readInstructionPages(source_, "/session/instructions", {"show"});
        }
        if (!session.contains("background")) return;
        const json& list = session["background"];
        std::string known;
        for (std::string_view id : kBackgroundQuestions) known += (known.empty() ? "\"" : ", \"") + std::string(id) + "\"";
        if (!list.is_array())
            source_.failAt("/session/background", "expected a list of background questions (" + known + "), or [] for none");
        study_.background.clear();
        for (std::size_t i = 0; i < list.size(); ++i) {
            const std::string at = "/session/background/" + std::to_string(i);
            const std::string id = list[i].is_string() ? list[i].get<std::string>() : "";
            if (std::find(kBackgroundQuestions.begin(), kBackgroundQuestions.end(), id) == kBackgroundQuestions.end())
                source_.failAt(at, "expected one of " + known);
            if (std::find(study_.background.begin(), study_.background.end(), id) != study_.background.end())
                source_.failAt(at, "\"" + id + "\" is listed twice");
            study_.background.push_back(id);
        }
    }

    void readScale(const json& scale) {
        if (!scale.is_array() || scale.size() != 2 || !scale[0].is_number_integer() || !scale[1].is_number_integer())
            source_.failAt("/likertScale", "expected [lowest, highest], e.g. [1, 10]");
        const long long low = scale[0].get<long long>(), high = scale[1].get<long long>();
        if (low < 0 || high > 100 || high - low < 1)
            source_.failAt("/likertScale", "expected 0 <= lowest < highest <= 100, e.g. [1, 10]");
        study_.likertMinimum = static_cast<int>(low);
        study_.likertMaximum = static_cast<int>(high);
    }

    StudyRenderSettings readRender(const json& object, const std::string& pointer, StudyRenderSettings settings) {
        if (!object.is_object())
            source_.failAt(pointer, "expected {\"size\": \"1280x720\", \"fps\": \"30\", \"msaa\": 4, \"rate\": 1}");
        knownKeys(object, pointer, {"size", "fps", "msaa", "rate", "timing", "nonManuals"});
        if (object.contains("size")) {
            const std::string at = pointer + "/size";
            const json& size = object["size"];
            unsigned width = 0, height = 0;
            char extra = 0;
            if (!size.is_string() || std::sscanf(size.get<std::string>().c_str(), "%ux%u%c", &width, &height, &extra) != 2)
                source_.failAt(at, "expected \"WIDTHxHEIGHT\", e.g. \"1280x720\"");
            if (width < 64 || height < 64 || width > 7680 || height > 4320)
                source_.failAt(at, "size " + size.get<std::string>() + " is out of range (64x64 to 7680x4320)");
            if (width % 2 != 0 || height % 2 != 0)
                source_.failAt(at, "size " + size.get<std::string>() +
                                       " has an odd side: H.264 (yuv420p) needs even width and height, e.g. " +
                                       std::to_string(width + width % 2) + "x" + std::to_string(height + height % 2));
            settings.width = width;
            settings.height = height;
        }
        if (object.contains("fps")) {
            const json& fps = object["fps"];
            if (fps.is_number_integer() && fps.get<long long>() > 0 && fps.get<long long>() <= 240)
                settings.fps = std::to_string(fps.get<long long>());
            else if (fps.is_string() && !fps.get<std::string>().empty())
                settings.fps = fps.get<std::string>();
            else
                source_.failAt(pointer + "/fps", "expected a frame rate: 30, \"25\", \"30000/1001\"");
            settings.fpsLine = source_.lineAt(pointer + "/fps");
        }
        if (object.contains("msaa")) {
            const json& msaa = object["msaa"];
            if (!msaa.is_number_integer() || (msaa.get<long long>() != 1 && msaa.get<long long>() != 4))
                source_.failAt(pointer + "/msaa", "expected 1 or 4 (the sample counts every Vulkan device supports)");
            settings.msaa = static_cast<std::uint32_t>(msaa.get<long long>());
        }
        if (object.contains("rate"))
            settings.rate = source_.number(object["rate"], pointer + "/rate", NumberRange{0.1, 4.0, ""});
        if (object.contains("timing")) settings.timing = parseStoryTiming(source_, object["timing"], pointer + "/timing");
        if (object.contains("nonManuals")) {
            if (!object["nonManuals"].is_boolean())
                source_.failAt(pointer + "/nonManuals", "expected true or false (false: no non-manuals; docs/study.md)");
            settings.nonManuals = object["nonManuals"].get<bool>();
        }
        return settings;
    }

    void checkDesign() {
        StudyDesignSpec spec = study_.designSpec();
        // Phase 2's sentence count is known only once its story is read; the design check
        // of stories, versions and participants happens here, phase 2's in checkPhase2Count.
        spec.likertTrials = 0;
        const std::string problem = designProblem(spec);
        if (problem.empty()) return;
        const bool aboutStories = problem.find("stories") != std::string::npos;
        source_.failAt(aboutStories ? "/stories" : "/versions",
                       "this design cannot be built: " + problem +
                           (study_.humanVersions.empty() ? std::string()
                                                         : " (the human versions in phase 1 count as versions)"));
    }

    const JsonSource& source_;
    StudyFile study_;
};

std::string twoDigits(std::size_t number, std::size_t width = 2) {
    std::string text = std::to_string(number);
    if (text.size() < width) text.insert(0, width - text.size(), '0');
    return text;
}

}  // namespace

std::string StudyRenderSettings::text() const {
    return std::to_string(width) + "x" + std::to_string(height) + ", " + fps + " fps, MSAA " + std::to_string(msaa) +
           ", rate " + formatNumber(rate) + (timing.given() ? ", timing " + describeTiming(timing) : std::string()) +
           (nonManuals ? std::string() : ", no non-manuals");
}

StudyDesignSpec StudyFile::designSpec() const {
    StudyDesignSpec spec;
    spec.stories = stories.size();
    spec.versions = phase1VersionCount(*this);  // the animated versions and the human ones in phase 1
    if (const std::size_t panels = phase2VersionIndices(*this).size(); panels != spec.versions) spec.likertVersions = panels;
    spec.participants = participants;
    spec.likertTrials = phase2Sentences.size();
    spec.seed = seed;
    spec.order = order;
    return spec;
}

StudyFile parseStudyFile(const JsonSource& source) {
    return withJsonErrors(source, [&] { return StudyReader(source).read(); });
}

StudyFile loadStudyFile(const std::filesystem::path& file) { return parseStudyFile(readJsonFile(file)); }

std::filesystem::path defaultStudyFile(const std::filesystem::path& scenesDir) {
    return scenesDir / "studies" / "default.json";
}

std::string storyId(std::size_t storyIndex) { return "story-" + twoDigits(storyIndex + 1); }
std::string likertId(std::size_t sentenceIndex) { return "likert-" + twoDigits(sentenceIndex + 1); }

std::string participantId(std::size_t participant, std::size_t participantCount) {
    return "P" + twoDigits(participant + 1, std::max<std::size_t>(2, std::to_string(participantCount).size()));
}

std::string versionLetter(VerbVersion version) {
    switch (version) {
    case VerbVersion::Point: return "P";
    case VerbVersion::Vector: return "V";
    case VerbVersion::Animator: return "A";
    case VerbVersion::Uninflected: return "U";
    }
    return "?";
}

std::string storyClipName(std::size_t storyIndex, VerbVersion version) {
    return storyId(storyIndex) + "_version-" + toString(version);
}

std::string likertClipName(std::size_t sentenceIndex, const std::string& panelCode) {
    return likertId(sentenceIndex) + "_panels-" + panelCode;
}

StudyListing planStudy(const StudyFile& study, const std::vector<Story>& stories, const Story* phase2,
                       const std::string& toolVersion, bool pngFrames) {
    StudyListing listing;
    listing.title = study.title;
    listing.studyFile = study.file;
    listing.toolVersion = toolVersion;
    listing.seed = study.seed;
    listing.likertMinimum = study.likertMinimum;
    listing.likertMaximum = study.likertMaximum;
    listing.ratingPrompt = study.ratingPrompt;
    listing.background = study.background;
    listing.questionsShown = study.questionsShown;
    listing.instructionsShown = study.instructionsShown;
    for (VerbVersion v : study.versions) {
        listing.versions.push_back(toString(v));
        listing.versionLetters.push_back(versionLetter(v));
    }
    const std::vector<const HumanVersion*> humans = orderedHumanVersions(study);
    for (const HumanVersion* h : humans) {
        listing.versions.push_back(h->name);
        listing.versionLetters.push_back(h->letter);
    }
    const auto clip = [&](const std::string& name) {
        ListedClip c;
        c.video = "clips/" + name + ".mp4";
        c.poster = "posters/" + name + ".png";
        if (pngFrames) c.frames = "frames/" + name;
        if (study.regions) c.regions = "regions/" + name + ".csv";
        if (study.elan) c.annotation = "elan/" + name + ".eaf";
        return c;
    };
    for (std::size_t s = 0; s < stories.size(); ++s) {
        const Story& story = stories[s];
        ListedStory listed;
        listed.id = storyId(s);
        listed.title = story.title;
        listed.file = study.stories.at(s).written;
        for (const StorySentence& sentence : story.sentences) listed.sentences.push_back(sentence.gloss);
        for (std::size_t q = 0; q < story.questions.size(); ++q) {
            const StoryQuestion& question = story.questions[q];
            ListedQuestion item{question.text, question.choices, question.answer, question.probeVerb, question.probeSentence, {}, {}};
            // Issue 24: a question with gloss has its clip when the study shows questions signed.
            if (showsSigned(study.questionsShown) && !question.gloss.empty()) {
                item.gloss = question.gloss;
                item.clip = clip(questionClipName(s, q));
            }
            listed.questions.push_back(std::move(item));
        }
        for (VerbVersion v : study.versions) listed.clips.push_back(clip(storyClipName(s, v)));
        for (const HumanVersion* h : humans)
            if (!h->phase1Clips.empty()) {
                // A lab's recording: no eye-tracking regions or ELAN file (nothing is known of where
                // its signer's face and hands are, or when each sign starts).
                ListedClip recording = clip(storyId(s) + "_version-" + h->name);
                recording.regions.clear();
                recording.annotation.clear();
                listed.clips.push_back(std::move(recording));
            }
        listing.stories.push_back(std::move(listed));
    }
    for (const StudyInstruction& page : study.instructions) {
        ListedInstruction listed{page.page, page.text, page.gloss, {}};
        if (showsSigned(study.instructionsShown)) listed.clip = clip(instructionClipName(page.page));
        listing.instructions.push_back(std::move(listed));
    }
    StudyDesignSpec spec = study.designSpec();
    if (phase2) {
        for (std::size_t i = 0; i < study.phase2Sentences.size(); ++i) {
            const StorySentence& sentence = phase2->sentences.at(static_cast<std::size_t>(study.phase2Sentences[i]));
            ListedSentence listed;
            listed.id = likertId(i);
            listed.gloss = sentence.gloss;
            for (const StoryItem& item : sentence.items)
                if (item.kind == StoryItemKind::Verb) listed.verb = item.gloss;
            // Phase 2's own versions (the animated ones and the human ones in phase 2) in study order.
            const std::vector<std::size_t> phase2Versions = phase2VersionIndices(study);
            for (std::size_t k : likertPanels(spec, i)) listed.panelVersion.push_back(phase2Versions.at(k));
            for (std::size_t v : listed.panelVersion) listed.panelCode += listing.versionLetters[v];
            listed.clip = clip(likertClipName(i, listed.panelCode));
            listing.sentences.push_back(std::move(listed));
        }
    } else {
        spec.likertTrials = 0;
    }
    listing.groupVersion.assign(stories.size(), {});
    for (std::size_t s = 0; s < stories.size(); ++s)
        for (std::size_t g = 0; g < spec.versions; ++g) listing.groupVersion[s].push_back(phase1Version(spec, s, g));
    for (std::size_t p = 0; p < study.participants; ++p) {
        const ParticipantSchedule schedule = participantSchedule(spec, p);
        ListedParticipant participant;
        participant.id = participantId(p, study.participants);
        participant.group = schedule.group;
        for (std::size_t t = 0; t < schedule.phase1.size(); ++t)
            participant.phase1.push_back({t + 1, schedule.phase1[t].story, schedule.phase1[t].version});
        for (std::size_t t = 0; t < schedule.phase2.size(); ++t) participant.phase2.push_back({t + 1, schedule.phase2[t].sentence});
        listing.participants.push_back(std::move(participant));
    }
    listing.size = std::to_string(study.render.width) + "x" + std::to_string(study.render.height);
    listing.fps = study.render.fps;
    listing.msaa = study.render.msaa;
    listing.designHash = sha256Hex(designText(listing));
    return listing;
}

std::string designText(const StudyListing& listing) {
    std::string text = "signstim study design 1\nseed " + std::to_string(listing.seed) + "\nversions";
    for (const std::string& v : listing.versions) text += " " + v;
    text += "\n";
    // What each story says (title, glosses, questions), not where its file lives: moving or
    // renaming the stories' folder leaves the design, and a finished study, as it was.
    for (const ListedStory& story : listing.stories) {
        text += story.id + " " + story.title + "\n";
        for (const std::string& gloss : story.sentences) text += "  " + gloss + "\n";
        for (const ListedQuestion& q : story.questions) {
            text += "  ? " + q.text + " |";
            for (const std::string& choice : q.choices) text += " " + choice + " |";
            text += " answer " + std::to_string(q.answer) + " probe " + q.probeVerb + " " + std::to_string(q.probeSentence) + "\n";
            // Issue 24: the question as signed, when it is (a study in English keeps its design).
            if (!q.clip.video.empty()) text += "  ?asl " + q.gloss + "\n";
        }
    }
    for (const ListedSentence& sentence : listing.sentences)
        text += sentence.id + " " + sentence.panelCode + " " + sentence.gloss + "\n";
    for (const ListedInstruction& page : listing.instructions)
        if (!page.clip.video.empty()) {
            text += "instructions " + page.page + ":";
            for (const std::string& gloss : page.gloss) text += " " + gloss + " |";
            text += "\n";
        }
    for (const ListedParticipant& p : listing.participants) {
        text += p.id + " group " + std::to_string(p.group) + ":";
        for (const ListedPhase1Trial& t : p.phase1)
            text += " " + listing.stories[t.story].id + "/" + listing.versions[t.version];
        text += " |";
        for (const ListedPhase2Trial& t : p.phase2) text += " " + listing.sentences[t.sentence].id;
        text += "\n";
    }
    return text;
}

}  // namespace signstim::stimuli
