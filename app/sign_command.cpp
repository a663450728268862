// `signstim sign GLOSS`: one lexicon sign alone (issue 22 §4): what it is, the ASL-LEX code it
// claims and the results of its checks (stimuli/story/sign_notation_check.hpp), on the hands as
// the signer's arm solution poses them too (contacts reached, orientation kept); with --out, the
// signer signing it in citation form, as a clip or as a contact sheet of its frames.
#include "app/cli_values.hpp"
#include "app/clip_output.hpp"
#include "app/commands.hpp"
#include "app/sign_alone.hpp"
#include "common/atomic_file.hpp"
#include "common/error.hpp"
#include "renderer/contact_sheet.hpp"
#include "renderer/image_io.hpp"
#include "renderer/renderer.hpp"
#include "signer/avatar_render.hpp"
#include "signer/clip_render.hpp"
#include "signer/signer.hpp"
#include "signer/signer_reach.hpp"
#include "signer/timeline_clip.hpp"
#include "stimuli/story/sign_notation_check.hpp"
#include "stimuli/story/story_world.hpp"

#include <cstdio>

namespace signstim::app {
namespace {

using namespace signstim::stimuli;

struct SignOptions {
    std::string gloss, outPath, scenesDir, lexicon, device;
    std::string size = "640x480", fps = "30";
    std::uint32_t msaa = 4;
    int columns = 8;
    bool quiet = false;
};

// What the sign is and whether it realizes what it claims, on the posed hands too; true when
// every check passes.
bool report(const StoryWorld& world, const LexiconSign& sign, const PosedHands& posed) {
    std::printf("%s (%s:%d): %s\n", sign.gloss.c_str(), sign.file.c_str(), sign.line, sign.meaning.c_str());
    std::printf("  %zu hand%s, %.3f s in citation form\n", sign.hands.size(), sign.hands.size() == 1 ? "" : "s",
                sign.durationSeconds() * sign.passes);
    if (!sign.notation) {
        std::printf("  written as keyframes (no notation): it claims no ASL-LEX code and has no checks\n");
        return true;
    }
    const SignNotation& n = *sign.notation;
    const std::vector<AslLexCode> derived = deriveAslLexCode(n, world.shapes);
    for (std::size_t i = 0; i < derived.size(); ++i)
        std::printf("  claims, part %zu: %s\n", i + 1, describeAslLexCode(derived[i]).c_str());
    const NotationProvenance& p = n.provenance;
    if (p.entry.empty()) std::printf("  follows no ASL-LEX 2.0 entry\n");
    else
        std::printf("  follows ASL-LEX 2.0 entry '%s'%s%s%s (SignDuration %.0f ms)\n", p.entry.c_str(),
                    p.variant.empty() ? "" : ", variant: ", p.variant.c_str(), p.source.empty() ? "" : (", source: " + p.source).c_str(),
                    p.durationMs);
    bool ok = true;
    for (const NotationCheck& c : checkSignNotation(sign, world.lexicon, world.shapes, world.handModel, posed)) {
        std::printf("  %s %s: %s\n", c.ok ? "ok  " : "FAIL", c.name.c_str(), c.detail.c_str());
        ok = ok && c.ok;
    }
    return ok;
}

void renderSign(const SignOptions& o, const signer::Signer& signer, const signer::TimelineClip& clip, const LexiconSign& sign) {
    const ClipOutput output = checkClipOutput(o.outPath, o.size, o.fps, o.msaa, o.device, o.quiet);
    if (output.kind == render::OutputKind::Folder) throw commandLineError("--out", "give FILE.png (a contact sheet) or FILE.mp4");
    double start = 0.0, from = 0.0, to = clip.durationSeconds();
    for (const TimelineSpan& span : clip.timeline().spans)
        if (span.kind == SpanKind::Sign) start = span.keysStartSeconds, from = span.startSeconds, to = span.keysEndSeconds + 0.1;
    if (output.kind == render::OutputKind::Video) {
        const std::uint64_t frames = renderClipToOutput(output, signer, clip, start);
        std::printf("%s: %s, %llu frames, %.2f s\n", output.out.string().c_str(), sign.gloss.c_str(),
                    static_cast<unsigned long long>(frames), clip.durationSeconds());
        return;
    }
    // The contact sheet: every frame of the sign's own keys (and the moves in and out).
    render::Renderer renderer(signer::signerRendererOptions(output.size.width, output.size.height, output.msaa, output.device));
    checkOutputWritable(output.out);
    const int handle = renderer.addScene(signer.avatar());
    signer::ClipRenderOptions options;
    options.framesPerSecond = output.frameRate.value();
    std::vector<double> contacts;  // clip time
    for (const ContactEvent& e : sign.contactEvents) contacts.push_back(clipSeconds(clip, sign, e.timeSeconds));
    render::ContactSheetSink sink(options.framesPerSecond, from, to, contacts);
    signer::renderClips(renderer, handle, signer.avatar(), signer.rig(), {&clip}, {}, options, sink);
    const std::size_t frames = sink.kept();
    failOnValidationMessages(renderer);
    render::writeImage(sink.sheet(o.columns), output.out);
    std::printf("%s: %s, contact sheet of %zu frames at %.0f fps from the move in to the end, %d a row (red: a contact event)\n",
                output.out.string().c_str(), sign.gloss.c_str(), frames,
                options.framesPerSecond, o.columns);
}

}  // namespace

void registerSignCommand(Commands& commands) {
    auto o = std::make_shared<SignOptions>();
    CLI::App* sign = commands.root.add_subcommand(
        "sign",
        "One sign of the lexicon alone (docs/lexicon.md): its place, the ASL-LEX 2.0 code it claims and\n"
        "the results of its checks, on the hands as the signer's arms pose them too (exit 2 when one\n"
        "fails); with --out, the signer signing it in citation form as a clip or a contact sheet of\n"
        "its frames.\n"
        "Examples:\n"
        "  signstim sign MOTHER\n"
        "  signstim sign LIBRARY --out library.png\n"
        "  signstim sign HOMEWORK --out homework.mp4");
    sign->add_option("GLOSS", o->gloss, "The sign's gloss (MOTHER, THANK-YOU)")->required();
    sign->add_option("--out", o->outPath, "FILE.png (a contact sheet of its frames) or FILE.mp4");
    sign->add_option("--size", o->size, "Frame size WxH (each frame of the sheet is half of it)")->capture_default_str();
    sign->add_option("--fps", o->fps, "Frame rate")->capture_default_str();
    sign->add_option("--columns", o->columns, "Frames a row of the contact sheet")->capture_default_str()->check(CLI::Range(1, 64));
    sign->add_option("--msaa", o->msaa, "Multisampling: 1 or 4")->capture_default_str();
    sign->add_option("--device", o->device, "Vulkan device: name substring or index (see `signstim devices`)");
    sign->add_option("--scenes", o->scenesDir, "Data directory (default: $SIGNSTIM_SCENES, else the scenes/ installed beside signstim)");
    sign->add_option("--lexicon", o->lexicon, "A lab's own lexicon on top of SCENES/lexicon/ (as for `story`)");
    sign->add_flag("--quiet", o->quiet, "No progress on stderr");
    sign->callback([o] {
        StoryWorld pacedWorld(o->scenesDir, o->lexicon);
        const auto signer = std::make_shared<const signer::Signer>(pacedWorld.scenes);
        // Issue 21: transitions paced by the path the signer's hands take, as in a story.
        pacedWorld.transitionPacer = signer::transitionPacer(signer);
        pacedWorld.reach = signer::signerReach(signer->rig());  // issue 21: verbs within the comfortable reach
        const StoryWorld& world = pacedWorld;
        const LexiconSign* found = world.lexicon.find(o->gloss);
        if (!found) {
            std::string known;
            for (const std::string& g : world.lexicon.glosses()) known += (known.empty() ? "" : " ") + g;
            throw InputError(world.lexicon.file, 0, "GLOSS", "no sign " + o->gloss + " in the lexicon (signs: " + known + ")");
        }
        const signer::TimelineClip clip = signAlone(world, *signer, *found);
        const bool ok = report(world, *found, posedHands(*signer, clip, *found));
        std::fflush(stdout);
        if (!o->outPath.empty()) renderSign(*o, *signer, clip, *found);
        if (!ok) throw InputError(found->file, found->line, "notation", found->gloss + " does not realize the code it claims (FAIL above)");
    });
}

}  // namespace signstim::app
