// A story's versions rendered together (signer/clip_render.hpp, renderClipsSharingFrames): the
// frames outside the verbs are drawn once for all versions, and every version still gets
// exactly the images it would get rendered alone (validation layer on).
#include "signer/avatar_builder.hpp"
#include "signer/avatar_render.hpp"
#include "signer/signer_pose.hpp"
#include "signer/timeline_clip.hpp"
#include "signer/clip_render.hpp"
#include "stimuli/story/handshapes.hpp"
#include "stimuli/story/lexicon.hpp"
#include "stimuli/story/story.hpp"
#include "stimuli/story/timeline_builder.hpp"
#include "stimuli/verbs/verb_models.hpp"
#include "stimuli/verbs/verbs.hpp"

#include <gtest/gtest.h>

#include <memory>

using namespace signstim;

namespace {

const std::filesystem::path kScenes = std::filesystem::path(SIGNSTIM_SOURCE_DIR) / "scenes";

class CollectingSink : public render::FrameSink {
public:
    void push(render::Image&& frame) override { frames.push_back(std::move(frame)); }
    void finish() override {}
    std::uint64_t framesPushed() const override { return frames.size(); }
    std::vector<render::Image> frames;
};

}  // namespace

TEST(StudyRender, SharedFramesGiveEveryVersionTheImagesItGetsAlone) {
    const render::Scene avatar = signer::buildDefaultAvatar();
    const signer::SignerRig rig(avatar);
    const stimuli::HandshapeLibrary shapes = stimuli::loadHandshapes(kScenes / "handshapes.json", rig.handModel());
    const stimuli::VerbLibrary verbs = stimuli::loadVerbLibrary(kScenes / "verbs.json");
    const stimuli::TrainedVerbModels models = stimuli::loadVerbModels(kScenes / "models" / "verb_models.json", verbs);
    const stimuli::Lexicon lexicon = stimuli::loadLexicon(kScenes / "lexicon", shapes, rig.handModel());
    stimuli::StoryVocabulary vocabulary;
    vocabulary.verbs = &verbs;
    vocabulary.signs = lexicon.glosses();
    const stimuli::Story story = stimuli::loadStory(kScenes / "stories" / "examples" / "the-question.json", vocabulary);
    stimuli::TimelineSources sources;
    sources.lexicon = &lexicon;
    sources.shapes = &shapes;
    sources.verbs = [&](const std::string& verb, stimuli::VerbVersion version, double subject, double object, int, int) {
        return stimuli::synthesizeVerb(stimuli::VerbSources{&verbs, &models, kScenes / "animator", &shapes}, verb, version,
                                       subject, object);
    };
    std::vector<std::unique_ptr<signer::TimelineClip>> clips;
    std::vector<const signer::Clip*> pointers;
    for (auto version : {stimuli::VerbVersion::Point, stimuli::VerbVersion::Vector, stimuli::VerbVersion::Animator,
                         stimuli::VerbVersion::Uninflected}) {
        clips.push_back(std::make_unique<signer::TimelineClip>(rig, stimuli::buildTimeline(story, version, sources)));
        pointers.push_back(clips.back().get());
    }

    render::RendererOptions options = signer::signerRendererOptions(96, 72, 1, "");
    options.validation = true;
    render::Renderer renderer(options);
    const int handle = renderer.addScene(avatar);
    const double fps = 6.0;
    std::vector<CollectingSink> together(4);
    std::vector<render::FrameSink*> sinks;
    for (CollectingSink& s : together) sinks.push_back(&s);
    const signer::SharedRenderStats stats =
        signer::renderClipsSharingFrames(renderer, handle, avatar, rig, pointers, fps, sinks);

    // Most of a story is outside its verbs: most frames are drawn once, but not all (the verbs differ).
    EXPECT_GT(stats.sharedFrames, stats.frames / 2);
    EXPECT_LT(stats.sharedFrames, stats.frames);
    EXPECT_EQ(stats.renderedImages, stats.sharedFrames + 4 * (stats.frames - stats.sharedFrames));

    signer::ClipRenderOptions alone;
    alone.framesPerSecond = fps;
    for (std::size_t v = 0; v < 4; ++v) {
        CollectingSink single;
        const std::uint64_t frames = signer::renderClips(renderer, handle, avatar, rig, {pointers[v]}, {}, alone, single);
        ASSERT_EQ(frames, stats.frames);
        ASSERT_EQ(together[v].frames.size(), frames) << "version " << v;
        for (std::uint64_t f = 0; f < frames; ++f)
            ASSERT_EQ(together[v].frames[f].bytes, single.frames[f].bytes) << "version " << v << ", frame " << f;
    }
    EXPECT_TRUE(renderer.validationMessages().empty()) << renderer.validationMessages().front();
}
