// The listing as JSON (study.json's "listing"), written and read back with every field checked
// (study.hpp: listingToJson, listingFromJson).
#include "stimuli/study/study.hpp"

#include "common/error.hpp"

namespace signstim::stimuli {

using nlohmann::json;

namespace {

json clipToJson(const ListedClip& c) {
    return {{"video", c.video},     {"poster", c.poster},         {"frames", c.frames},
            {"regions", c.regions}, {"annotation", c.annotation}, {"durationSeconds", c.durationSeconds},
            {"frameCount", c.frameCount}};
}

// Reads the fields back with their types checked; a mistake names the file and the field.
class ListingReader {
public:
    explicit ListingReader(std::string file) : file_(std::move(file)) {}

    const json& at(const json& object, const char* key, const std::string& where) const {
        if (!object.is_object() || !object.contains(key)) fail(where + "/" + key, "missing");
        return object[key];
    }
    std::string text(const json& object, const char* key, const std::string& where) const {
        const json& v = at(object, key, where);
        if (!v.is_string()) fail(where + "/" + key, "expected text");
        return v.get<std::string>();
    }
    std::uint64_t count(const json& object, const char* key, const std::string& where) const {
        const json& v = at(object, key, where);
        if (!v.is_number_integer() || v.get<long long>() < 0) fail(where + "/" + key, "expected a whole number");
        return v.get<std::uint64_t>();
    }
    double number(const json& object, const char* key, const std::string& where) const {
        const json& v = at(object, key, where);
        if (!v.is_number()) fail(where + "/" + key, "expected a number");
        return v.get<double>();
    }
    const json& list(const json& object, const char* key, const std::string& where) const {
        const json& v = at(object, key, where);
        if (!v.is_array()) fail(where + "/" + key, "expected a list");
        return v;
    }
    std::vector<std::string> texts(const json& object, const char* key, const std::string& where) const {
        std::vector<std::string> out;
        const json& l = list(object, key, where);
        for (std::size_t i = 0; i < l.size(); ++i) {
            if (!l[i].is_string()) fail(where + "/" + key + "/" + std::to_string(i), "expected text");
            out.push_back(l[i].get<std::string>());
        }
        return out;
    }
    std::vector<std::size_t> indices(const json& object, const char* key, const std::string& where, std::size_t bound) const {
        std::vector<std::size_t> out;
        const json& l = list(object, key, where);
        for (std::size_t i = 0; i < l.size(); ++i) {
            if (!l[i].is_number_integer() || l[i].get<long long>() < 0 || l[i].get<std::uint64_t>() >= bound)
                fail(where + "/" + key + "/" + std::to_string(i), "expected an index below " + std::to_string(bound));
            out.push_back(l[i].get<std::size_t>());
        }
        return out;
    }
    std::size_t index(const json& object, const char* key, const std::string& where, std::size_t bound) const {
        const std::uint64_t v = count(object, key, where);
        if (v >= bound) fail(where + "/" + key, "expected an index below " + std::to_string(bound));
        return static_cast<std::size_t>(v);
    }
    ListedClip clip(const json& object, const std::string& where) const {
        ListedClip c;
        c.video = text(object, "video", where);
        c.poster = text(object, "poster", where);
        c.frames = text(object, "frames", where);
        // Absent from folders written before issue 24: none written.
        if (object.contains("regions")) c.regions = text(object, "regions", where);
        if (object.contains("annotation")) c.annotation = text(object, "annotation", where);
        c.durationSeconds = number(object, "durationSeconds", where);
        c.frameCount = count(object, "frameCount", where);
        return c;
    }
    [[noreturn]] void fail(const std::string& field, const std::string& message) const {
        throw InputError(file_, 0, field, message + " (a study folder written by another signstim version?)");
    }

private:
    std::string file_;
};

}  // namespace

json listingToJson(const StudyListing& listing) {
    json j;
    j["title"] = listing.title;
    j["studyFile"] = listing.studyFile;
    j["toolVersion"] = listing.toolVersion;
    j["seed"] = listing.seed;
    j["designHash"] = listing.designHash;
    j["versions"] = listing.versions;
    j["versionLetters"] = listing.versionLetters;
    j["likertMinimum"] = listing.likertMinimum;
    j["likertMaximum"] = listing.likertMaximum;
    j["size"] = listing.size;
    j["fps"] = listing.fps;
    j["msaa"] = listing.msaa;
    j["ratingPrompt"] = listing.ratingPrompt;
    j["background"] = listing.background;
    json stories = json::array();
    for (const ListedStory& s : listing.stories) {
        json questions = json::array();
        for (const ListedQuestion& q : s.questions) {
            json question = {{"text", q.text}, {"choices", q.choices}, {"answer", q.answer},
                             {"probeVerb", q.probeVerb}, {"probeSentence", q.probeSentence}};
            // Issue 24: only when there is one, so listings without ASL questions read as before.
            if (!q.gloss.empty()) question["gloss"] = q.gloss;
            if (!q.clip.video.empty()) question["clip"] = clipToJson(q.clip);
            questions.push_back(std::move(question));
        }
        json clips = json::array();
        for (const ListedClip& c : s.clips) clips.push_back(clipToJson(c));
        stories.push_back({{"id", s.id}, {"title", s.title}, {"file", s.file}, {"sentences", s.sentences},
                           {"questions", questions}, {"clips", clips}});
    }
    j["stories"] = stories;
    j["groupVersion"] = listing.groupVersion;
    json sentences = json::array();
    for (const ListedSentence& s : listing.sentences)
        sentences.push_back({{"id", s.id}, {"gloss", s.gloss}, {"verb", s.verb}, {"panelVersion", s.panelVersion},
                             {"panelCode", s.panelCode}, {"clip", clipToJson(s.clip)}});
    j["sentences"] = sentences;
    json participants = json::array();
    for (const ListedParticipant& p : listing.participants) {
        json phase1 = json::array(), phase2 = json::array();
        for (const ListedPhase1Trial& t : p.phase1)
            phase1.push_back({{"trial", t.trial}, {"story", t.story}, {"version", t.version}});
        for (const ListedPhase2Trial& t : p.phase2) phase2.push_back({{"trial", t.trial}, {"sentence", t.sentence}});
        participants.push_back({{"id", p.id}, {"group", p.group}, {"phase1", phase1}, {"phase2", phase2}});
    }
    j["participants"] = participants;
    if (!listing.draftAnimator.empty()) j["draftAnimator"] = listing.draftAnimator;  // issue 22: only when there are some
    // Issue 24: questions and instructions in ASL.
    j["questionsShown"] = listing.questionsShown;
    j["instructionsShown"] = listing.instructionsShown;
    json instructions = json::array();
    for (const ListedInstruction& page : listing.instructions) {
        json entry = {{"page", page.page}, {"text", page.text}, {"gloss", page.gloss}};
        if (!page.clip.video.empty()) entry["clip"] = clipToJson(page.clip);
        instructions.push_back(std::move(entry));
    }
    j["instructions"] = instructions;
    return j;
}

StudyListing listingFromJson(const json& j, const std::string& file) {
    const ListingReader r(file);
    StudyListing listing;
    listing.title = r.text(j, "title", "");
    listing.studyFile = r.text(j, "studyFile", "");
    listing.toolVersion = r.text(j, "toolVersion", "");
    listing.seed = r.count(j, "seed", "");
    listing.designHash = r.text(j, "designHash", "");
    listing.versions = r.texts(j, "versions", "");
    listing.versionLetters = r.texts(j, "versionLetters", "");
    if (listing.versionLetters.size() != listing.versions.size()) r.fail("/versionLetters", "one letter per version");
    listing.likertMinimum = static_cast<int>(r.count(j, "likertMinimum", ""));
    listing.likertMaximum = static_cast<int>(r.count(j, "likertMaximum", ""));
    listing.size = r.text(j, "size", "");
    listing.fps = r.text(j, "fps", "");
    listing.msaa = static_cast<std::uint32_t>(r.count(j, "msaa", ""));
    // Plans written before the session settings existed lack them: the defaults then.
    listing.ratingPrompt = j.contains("ratingPrompt") ? r.text(j, "ratingPrompt", "") : std::string(kDefaultRatingPrompt);
    if (j.contains("background")) listing.background = r.texts(j, "background", "");
    else listing.background.assign(kBackgroundQuestions.begin(), kBackgroundQuestions.end());
    const std::size_t versions = listing.versions.size();
    const json& stories = r.list(j, "stories", "");
    for (std::size_t i = 0; i < stories.size(); ++i) {
        const std::string w = "/stories/" + std::to_string(i);
        ListedStory s;
        s.id = r.text(stories[i], "id", w);
        s.title = r.text(stories[i], "title", w);
        s.file = r.text(stories[i], "file", w);
        s.sentences = r.texts(stories[i], "sentences", w);
        const json& questions = r.list(stories[i], "questions", w);
        for (std::size_t q = 0; q < questions.size(); ++q) {
            const std::string wq = w + "/questions/" + std::to_string(q);
            ListedQuestion question;
            question.text = r.text(questions[q], "text", wq);
            question.choices = r.texts(questions[q], "choices", wq);
            question.answer = static_cast<int>(r.index(questions[q], "answer", wq, question.choices.size()));
            question.probeVerb = r.text(questions[q], "probeVerb", wq);
            question.probeSentence = static_cast<int>(r.index(questions[q], "probeSentence", wq, s.sentences.size()));
            if (questions[q].contains("gloss")) question.gloss = r.text(questions[q], "gloss", wq);
            if (questions[q].contains("clip")) question.clip = r.clip(questions[q]["clip"], wq + "/clip");
            s.questions.push_back(std::move(question));
        }
        const json& clips = r.list(stories[i], "clips", w);
        // One per phase-1 version: a version in phase 2 only (a human version) has none.
        if (clips.empty() || clips.size() > versions) r.fail(w + "/clips", "one clip per phase-1 version");
        for (std::size_t c = 0; c < clips.size(); ++c) s.clips.push_back(r.clip(clips[c], w + "/clips/" + std::to_string(c)));
        listing.stories.push_back(std::move(s));
    }
    const json& groupVersion = r.list(j, "groupVersion", "");
    if (groupVersion.size() != listing.stories.size()) r.fail("/groupVersion", "one row per story");
    // Phase 1's versions (and groups): all, or the first ones when a version is in phase 2 only.
    const std::size_t phase1Versions = listing.stories.empty() ? versions : listing.stories.front().clips.size();
    for (std::size_t s = 0; s < groupVersion.size(); ++s) {
        const std::string w = "/groupVersion/" + std::to_string(s);
        if (!groupVersion[s].is_array() || groupVersion[s].size() != phase1Versions) r.fail(w, "one version per group");
        std::vector<std::size_t> row;
        for (const json& v : groupVersion[s]) {
            if (!v.is_number_integer() || v.get<long long>() < 0 || v.get<std::uint64_t>() >= phase1Versions)
                r.fail(w, "expected version indices below " + std::to_string(phase1Versions));
            row.push_back(v.get<std::size_t>());
        }
        listing.groupVersion.push_back(std::move(row));
    }
    const json& sentences = r.list(j, "sentences", "");
    for (std::size_t i = 0; i < sentences.size(); ++i) {
        const std::string w = "/sentences/" + std::to_string(i);
        ListedSentence s;
        s.id = r.text(sentences[i], "id", w);
        s.gloss = r.text(sentences[i], "gloss", w);
        s.verb = r.text(sentences[i], "verb", w);
        s.panelVersion = r.indices(sentences[i], "panelVersion", w, versions);
        s.panelCode = r.text(sentences[i], "panelCode", w);
        s.clip = r.clip(r.at(sentences[i], "clip", w), w + "/clip");
        listing.sentences.push_back(std::move(s));
    }
    const json& participants = r.list(j, "participants", "");
    for (std::size_t i = 0; i < participants.size(); ++i) {
        const std::string w = "/participants/" + std::to_string(i);
        ListedParticipant p;
        p.id = r.text(participants[i], "id", w);
        p.group = r.index(participants[i], "group", w, phase1Versions);
        const json& phase1 = r.list(participants[i], "phase1", w);
        for (std::size_t t = 0; t < phase1.size(); ++t) {
            const std::string wt = w + "/phase1/" + std::to_string(t);
            p.phase1.push_back({static_cast<std::size_t>(r.count(phase1[t], "trial", wt)),
                                r.index(phase1[t], "story", wt, listing.stories.size()),
                                r.index(phase1[t], "version", wt, phase1Versions)});
        }
        const json& phase2 = r.list(participants[i], "phase2", w);
        for (std::size_t t = 0; t < phase2.size(); ++t) {
            const std::string wt = w + "/phase2/" + std::to_string(t);
            p.phase2.push_back({static_cast<std::size_t>(r.count(phase2[t], "trial", wt)),
                                r.index(phase2[t], "sentence", wt, listing.sentences.size())});
        }
        listing.participants.push_back(std::move(p));
    }
    if (j.contains("draftAnimator")) listing.draftAnimator = r.texts(j, "draftAnimator", "");  // issue 22
    // Issue 24; a listing written before it: English only, no instruction pages.
    if (j.contains("questionsShown")) listing.questionsShown = r.text(j, "questionsShown", "");
    if (j.contains("instructionsShown")) listing.instructionsShown = r.text(j, "instructionsShown", "");
    if (j.contains("instructions")) {
        const json& pages = r.list(j, "instructions", "");
        for (std::size_t i = 0; i < pages.size(); ++i) {
            const std::string w = "/instructions/" + std::to_string(i);
            ListedInstruction page;
            page.page = r.text(pages[i], "page", w);
            page.text = r.text(pages[i], "text", w);
            page.gloss = r.texts(pages[i], "gloss", w);
            if (pages[i].contains("clip")) page.clip = r.clip(pages[i]["clip"], w + "/clip");
            listing.instructions.push_back(std::move(page));
        }
    }
    return listing;
}

}  // namespace signstim::stimuli
