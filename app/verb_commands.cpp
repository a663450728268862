// `signstim train`, `signstim verb`, `signstim evaluate`, `signstim reference-corpus`:
// the indicating verbs of SPEC §3 (Huenerfauth, Lu & Kacorri 2015).
#include "app/cli_values.hpp"
#include "app/clip_output.hpp"
#include "app/commands.hpp"
#include "signer/signer.hpp"
#include "signer/signer_reach.hpp"
#include "signer/timeline_clip.hpp"
#include "signer/verb_clip.hpp"
#include "stimuli/story/handshapes.hpp"
#include "stimuli/story/timeline_builder.hpp"
#include "common/atomic_file.hpp"
#include "common/error.hpp"
#include "common/standard_output.hpp"
#include "stimuli/verbs/corpus.hpp"
#include "stimuli/verbs/evaluation.hpp"
#include "stimuli/verbs/reference_performer.hpp"
#include "stimuli/scenes_path.hpp"
#include "stimuli/verbs/signing_space.hpp"
#include "stimuli/verbs/sora.hpp"
#include "stimuli/verbs/verb_models.hpp"
#include "stimuli/verbs/verb_synthesis.hpp"
#include "stimuli/verbs/verbs.hpp"
#include "stimuli/story/story_world.hpp"
#include "stimuli/study/study.hpp"

#include <cstdio>
#include <algorithm>
#include <filesystem>
#include <system_error>
#include <memory>
#include <sstream>
#include <string>

namespace signstim::app {

// The signer's room (avatar, rig, clips) is this command line's main collaborator.
using namespace signstim::signer;
namespace {

using namespace signstim::stimuli;

struct VerbOptions {
    std::string scenesDir;
    std::string verbsFile;   // default <scenes>/verbs.json
    std::string modelsFile;  // default <scenes>/models/verb_models.json
    std::string corpusFile;
    std::string outPath;
    std::string performerFile;
    std::string verb;
    std::string version = "point";
    double subject = 0.0;
    double object = 0.0;
    bool json = false;
    int degree = 3;
    // Rendering (verb --out).
    std::string size = "640x480";
    std::string fps = "30";
    std::uint32_t msaa = 4;
    std::string device;
    std::string avatarFile, boneMapFile;
    bool quiet = false;
};

std::filesystem::path scenes(const VerbOptions& o) { return resolveScenesDir(o.scenesDir); }

VerbLibrary verbLibrary(const VerbOptions& o) {
    return loadVerbLibrary(o.verbsFile.empty() ? scenes(o) / "verbs.json" : std::filesystem::path(o.verbsFile));
}

void addCommonOptions(CLI::App* command, const std::shared_ptr<VerbOptions>& o) {
    command->add_option("--scenes", o->scenesDir,
                        "Data directory (default: $SIGNSTIM_SCENES, else the scenes/ installed beside signstim)");
    command->add_option("--verbs", o->verbsFile, "Verb definitions (default: SCENES/verbs.json)");
}

void printSummary(const VerbPerformance& p) {
    std::printf("%s (%s), subject %.2f, object %.2f, %.2f s\n", p.verb.c_str(), toString(p.version).c_str(), p.subject,
                p.object, p.durationSeconds);
    for (const HandTrack& track : p.hands) {
        for (const PerformanceKeyframe& key : track.keyframes) {
            const glm::dvec3 f = fingersDirection(key.pose.orientation);
            const glm::dvec3 palm = palmDirection(key.pose.orientation);
            std::printf("  %-5s t=%.2f s  position (%7.1f, %7.1f, %7.1f) mm  fingers (%5.2f, %5.2f, %5.2f)  palm (%5.2f, "
                        "%5.2f, %5.2f)  %s\n",
                        toString(track.side).c_str(), key.timeSeconds, key.pose.positionMm.x, key.pose.positionMm.y,
                        key.pose.positionMm.z, f.x, f.y, f.z, palm.x, palm.y, palm.z, key.handshape.c_str());
        }
    }
    std::printf("(--json prints the keyframes as JSON, the animator file format)\n");
}

// verb --out: the signer performs the verb (lead-in from rest, the verb, a hold).
void renderVerb(const VerbOptions& o, const std::filesystem::path& scenesDir, const VerbPerformance& performance) {
    const ClipOutput output = checkClipOutput(o.outPath, o.size, o.fps, o.msaa, o.device, o.quiet);
    const Signer signer(scenesDir, o.avatarFile, o.boneMapFile.empty() ? BoneMapping{} : loadBoneMapping(o.boneMapFile));
    const stimuli::HandshapeLibrary shapes = stimuli::loadHandshapes(scenesDir / "handshapes.json", signer.rig().handModel());
    // SPEC §6.2: at human speed on the posed wrists' path, as a story's verb slot plays it (the
    // synthesis's own timing took SEND's wrist from -1 to 1 at 4.65 m/s).
    stimuli::TimelineSources pacing;
    pacing.shapes = &shapes;
    pacing.transitions = transitionPacer(signer.rig());
    pacing.reach = signerReach(signer.rig());  // issue 21: within the signer's comfortable reach
    const VerbClip clip(signer.rig(), shapes, stimuli::paceVerbPerformance(performance, pacing));
    const std::uint64_t frames = renderClipToOutput(output, signer, clip, clip.middleOfVerbSeconds());
    std::printf("%s: %s %s, %llu frame%s\n", output.out.string().c_str(), performance.verb.c_str(),
                toString(performance.version).c_str(), static_cast<unsigned long long>(frames), frames == 1 ? "" : "s");
}

}  // namespace

void registerVerbCommands(Commands& commands) {
    // ---- train ------------------------------------------------------------------------------
    {
        auto o = std::make_shared<VerbOptions>();
        CLI::App* train = commands.root.add_subcommand(
            "train",
            "Fit the verb models (PointModel, VectorModel, SORA orientation; SPEC 3.4-3.6) to a corpus CSV\n"
            "and write them as JSON. The CSV format (docs/verbs.md): one row per verb example, hand and\n"
            "keyframe: verb,example,subject,object,hand,keyframe,x,y,z,roll,pitch,yaw; x/y/z in mm in the\n"
            "torso frame (+x signer's right, +y up, +z forward), roll/pitch/yaw in degrees, R = Rz Ry Rx.\n"
            "Example: signstim train scenes/corpus/reference_corpus.csv --out scenes/models/verb_models.json");
        train->add_option("corpus", o->corpusFile, "Corpus CSV (motion capture export or the reference corpus)")->required();
        train->add_option("--out", o->outPath, "Where to write the trained models (JSON)")->required();
        train->add_option("--degree", o->degree, "Polynomial degree (SPEC 3.4: 3)")->check(CLI::Range(1, 3));
        addCommonOptions(train, o);
        train->callback([o] {
            const VerbLibrary verbs = verbLibrary(*o);
            const Corpus corpus = loadCorpus(o->corpusFile, verbs);
            ModelOptions options;
            options.degree = o->degree;
            for (const std::string& warning : corpus.warnings) std::fprintf(stderr, "signstim: warning: %s\n", warning.c_str());
            const TrainedVerbModels models = trainVerbModels(corpus, verbs, options);
            writeFileAtomic(o->outPath, formatCheckedVerbModels(models, verbs, o->outPath));
            std::printf("trained %zu verbs on %zu examples -> %s\n", models.verbs.size(), corpus.examples.size(),
                        o->outPath.c_str());
        });
    }
    // ---- verb -------------------------------------------------------------------------------
    {
        auto o = std::make_shared<VerbOptions>();
        CLI::App* verb = commands.root.add_subcommand(
            "verb",
            "Synthesize one indicating verb for a subject and object on the signing arc (SPEC 3.7).\n"
            "Arc positions are in [-1, 1]: -1 the signer's far left, 0 straight ahead, 1 far right\n"
            "(the paper's example: subject 0.9, object -0.6). Versions: point and vector (the trained\n"
            "models), animator (hand-authored keyframes in SCENES/animator/), uninflected (the citation\n"
            "form, the same for every subject and object).\n"
            "Example: signstim verb ASK --subject 0.9 --object -0.6 --version point --json");
        verb->add_option("verb", o->verb, "Verb gloss: ASK, GIVE, MEET, SCOLD, TELL, COPY, EMAIL, SEND")->required();
        verb->add_option("--subject", o->subject, "Subject's arc position (ignored by object-only verbs SCOLD, TELL)");
        verb->add_option("--object", o->object, "Object's arc position")->required();
        verb->add_option("--version", o->version, "point | vector | animator | uninflected")->required();
        auto* jsonFlag = verb->add_flag("--json", o->json, "Print the keyframes (per hand: time, position, orientation, handshape) as JSON");
        verb->add_option("--out", o->outPath,
                         "Render the signer: FILE.mp4 (video), FILE.png/.exr/.tif (the middle frame) or DIR (frame_00001.png ...;\n"
                         "a new folder, or one holding only an earlier render's frames, which it replaces whole)")
            ->excludes(jsonFlag);
        verb->add_option("--size", o->size, "Rendered image size WxH (even for .mp4)")->capture_default_str();
        verb->add_option("--fps", o->fps, "Frame rate: 30, 25, 30000/1001 ...")->capture_default_str();
        verb->add_option("--msaa", o->msaa, "Multisampling: 1 or 4")->capture_default_str();
        verb->add_option("--device", o->device, "Vulkan device: name substring or index (see `signstim devices`)");
        verb->add_option("--avatar", o->avatarFile,
                         "Your own avatar (.glb/.gltf, +Y up) with VRM humanoid bone names; any rest pose and facing");
        verb->add_option("--bone-map", o->boneMapFile,
                         "JSON {\"vrmBoneName\": \"yourNodeName\", ...} for an avatar without VRM names");
        verb->add_flag("--quiet", o->quiet, "No progress on stderr");
        verb->add_option("--models", o->modelsFile, "Trained models (default: SCENES/models/verb_models.json)");
        addCommonOptions(verb, o);
        verb->callback([o, verb] {
            const std::optional<VerbVersion> version = parseVerbVersion(o->version);
            if (!version)
                throw InputError("<command line>", 0, "--version",
                                 "'" + o->version + "' is not a version (point, vector, animator, uninflected)");
            const VerbLibrary verbs = verbLibrary(*o);
            const VerbDefinition& definition = verbs.get(o->verb, "<command line>", 0, "VERB");
            checkArcPosition(o->object, "<command line>", "--object");
            if (!definition.objectOnly()) {
                if (verb->count("--subject") == 0)
                    throw InputError("<command line>", 0, "--subject",
                                     definition.name + " inflects for its subject too: give --subject S in [-1, 1]");
                checkArcPosition(o->subject, "<command line>", "--subject");
            }
            const std::filesystem::path scenesDir = scenes(*o);
            TrainedVerbModels models;
            if (*version == VerbVersion::Point || *version == VerbVersion::Vector)
                models = loadVerbModels(o->modelsFile.empty() ? scenesDir / "models" / "verb_models.json"
                                                              : std::filesystem::path(o->modelsFile),
                                        verbs);
            // Every handshape the verb names is checked here, against the file the signer uses,
            // so an unknown one is blamed on the verbs or animator file that names it.
            const HandshapeLibrary handshapes = loadHandshapes(scenesDir / "handshapes.json", hand::buildHandModel());
            const VerbSources sources{&verbs, &models, scenesDir / "animator", &handshapes};
            const VerbPerformance performance = synthesizeVerb(sources, definition.name, *version, o->subject, o->object);
            if (!o->outPath.empty()) renderVerb(*o, scenesDir, performance);
            else if (o->json) writeStandardOutput(formatPerformanceJson(performance));
            else printSummary(performance);
        });
    }
    // ---- evaluate ---------------------------------------------------------------------------
    {
        auto o = std::make_shared<VerbOptions>();
        CLI::App* evaluate = commands.root.add_subcommand(
            "evaluate",
            "Cross-validate the verb models on a corpus (SPEC 3.8): leave-one-out (LOO) and\n"
            "leave-one-arc-position-out (LOPO) errors per verb and model - position (mm, per hand and\n"
            "keyframe), direction of the right hand's movement (degrees) and orientation (degrees) -\n"
            "beside the uninflected citation form and lower-order PointModels. Prints a Markdown table.\n"
            "Example: signstim evaluate scenes/corpus/reference_corpus.csv");
        evaluate->add_option("corpus", o->corpusFile, "Corpus CSV")->required();
        addCommonOptions(evaluate, o);
        evaluate->callback([o] {
            const VerbLibrary verbs = verbLibrary(*o);
            const Corpus corpus = loadCorpus(o->corpusFile, verbs);
            for (const std::string& warning : corpus.warnings) std::fprintf(stderr, "signstim: warning: %s\n", warning.c_str());
            writeStandardOutput(formatEvaluationTable(evaluateVerbModels(corpus, verbs)));
        });
    }
    // ---- reference-corpus -------------------------------------------------------------------
    {
        auto o = std::make_shared<VerbOptions>();
        CLI::App* reference = commands.root.add_subcommand(
            "reference-corpus",
            "Generate the synthetic reference corpus (SPEC 3.3): the parametric performer of\n"
            "SCENES/corpus/reference_performer.json signs every verb for 7 arc positions x 6 others.\n"
            "The output is labelled synthetic; it stands in for motion capture, which no public corpus\n"
            "provides. Example: signstim reference-corpus --out scenes/corpus/reference_corpus.csv");
        reference->add_option("--out", o->outPath, "Where to write the corpus CSV")->required();
        reference->add_option("--performer", o->performerFile,
                              "Performer parameters (default: SCENES/corpus/reference_performer.json)");
        addCommonOptions(reference, o);
        reference->callback([o] {
            const VerbLibrary verbs = verbLibrary(*o);
            const ReferencePerformer performer = loadReferencePerformer(
                o->performerFile.empty() ? scenes(*o) / "corpus" / "reference_performer.json"
                                         : std::filesystem::path(o->performerFile),
                verbs);
            const Corpus corpus = generateReferenceCorpus(performer, verbs);
            writeFileAtomic(o->outPath, formatCorpus(corpus, verbs));
            std::printf("wrote %zu synthetic examples -> %s\n", corpus.examples.size(), o->outPath.c_str());
        });
    }
    // ---- animator draft ---------------------------------------------------------------------
    {
        struct DraftOptions {
            std::string file, outDir, scenesDir, lexicon;
        };
        auto o = std::make_shared<DraftOptions>();
        CLI::App* animator = commands.root.add_subcommand("animator", "Animator keyframe files (docs/verbs.md)");
        animator->require_subcommand(1);
        CLI::App* draft = animator->add_subcommand(
            "draft",
            "Write a starting animator file for every verb instance of a story or study that has none in\n"
            "SCENES/animator/: the point model's keyframes, marked \"draft\": true. An animator edits them and\n"
            "deletes the mark; a study refuses drafts unless --allow-draft-animator. Existing files are\n"
            "never overwritten. Example: signstim animator draft my-story.json");
        draft->add_option("FILE", o->file, "A story or a study file (JSON)")->required();
        draft->add_option("--out", o->outDir, "Where to write them (default: SCENES/animator/)");
        draft->add_option("--scenes", o->scenesDir,
                          "Data directory (default: $SIGNSTIM_SCENES, else the scenes/ installed beside signstim)");
        draft->add_option("--lexicon", o->lexicon, "A lab's own lexicon on top of SCENES/lexicon/ (as for `story`)");
        draft->callback([o] {
            const StoryWorld world(o->scenesDir, o->lexicon);
            std::vector<std::filesystem::path> storyFiles;
            const JsonSource source = readJsonFile(o->file);
            if (source.root.is_object() && source.root.value("format", "") == "signstim-study") {
                const StudyFile study = loadStudyFile(o->file);
                for (const StudyFile::StoryEntry& entry : study.stories) storyFiles.push_back(entry.path);
                if (!study.phase2Story.path.empty()) storyFiles.push_back(study.phase2Story.path);
            } else {
                storyFiles.push_back(o->file);
            }
            const std::filesystem::path existing = world.scenes / "animator";
            const std::filesystem::path out = o->outDir.empty() ? existing : std::filesystem::path(o->outDir);
            const VerbSources sources{&world.verbs, &world.models, existing, &world.shapes};
            std::vector<std::string> done;
            std::size_t written = 0, present = 0;
            for (const std::filesystem::path& file : storyFiles) {
                const Story story = world.loadStory(file);
                for (const StorySentence& sentence : story.sentences)
                    for (const StoryItem& item : sentence.items) {
                        if (item.kind != StoryItemKind::Verb) continue;
                        const VerbDefinition& verb = world.verbs.get(item.gloss);
                        const double subject =
                            item.subject >= 0 ? story.characters[static_cast<std::size_t>(item.subject)].position : 0.0;
                        const double object = story.characters[static_cast<std::size_t>(item.object)].position;
                        const std::string name = animatorFileName(verb, subject, object);
                        if (std::find(done.begin(), done.end(), name) != done.end()) continue;
                        done.push_back(name);
                        if (std::filesystem::exists(existing / name) || std::filesystem::exists(out / name)) {
                            ++present;
                            continue;
                        }
                        std::error_code ec;
                        std::filesystem::create_directories(out, ec);
                        if (ec) throw IoError(out.string(), "cannot create the folder", ec.value());
                        writeFileAtomic(out / name, formatAnimatorDraft(sources, item.gloss, subject, object));
                        std::printf("%s\n", (out / name).string().c_str());
                        ++written;
                    }
            }
            std::printf("%zu draft%s written, %zu verb instance%s already had a file\n", written, written == 1 ? "" : "s",
                        present, present == 1 ? "" : "s");
        });
    }
}

}  // namespace signstim::app
