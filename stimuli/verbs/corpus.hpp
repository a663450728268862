#pragma once
// Training examples of the verbs (SPEC §3.3) and their CSV format (docs/verbs.md):
//
//   # comment lines start with '#'
//   verb,example,subject,object,hand,keyframe,x,y,z,roll,pitch,yaw
//   ASK,1,-0.9,-0.6,right,0,101.52,22.03,158.77,-12.104,3.550,1.027
//
// One row per verb example, hand and keyframe. x, y, z: millimetres in the torso-fixed
// signing-space frame (stimuli/verbs/signing_space.hpp); roll, pitch, yaw: degrees, the hand's
// palm frame rotated by R = Rz(yaw)·Ry(pitch)·Rx(roll) about the fixed frame axes
// (stimuli/verbs/sora.hpp). Subject/object: arc positions in [-1, 1] (subject may be empty for
// object-only verbs). Columns may come in any order; further columns are ignored, but every
// row has as many fields as the header. A leading UTF-8 BOM is skipped.
#include "stimuli/verbs/verbs.hpp"

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace signstim::stimuli {

struct CorpusExample {
    std::string verb;
    long example = 0;       // the CSV's example number (unique within the verb)
    double subject = 0.0;   // 0 when the verb is object-only and the column is empty
    double object = 0.0;
    std::vector<std::vector<HandPose>> poses;  // [hand of the verb][keyframe]
    int firstLine = 0;
};

struct Corpus {
    std::string sourceFile;
    std::vector<std::string> comments;      // the '#' lines, without the '#'
    std::vector<CorpusExample> examples;    // grouped by verb (verbs.json order), then example
    // Verbs whose examples do not cover the SPEC §3.3 design (designWarnings), for stderr.
    std::vector<std::string> warnings;

    std::vector<const CorpusExample*> examplesOf(std::string_view verb) const;
};

// SPEC §3.3: the arc positions of the recording design; a subject-object verb is recorded at
// every (subject, object) pair of them with s != o (42), an object-only verb at every object (7).
inline constexpr double kDesignArcPositions[] = {-0.9, -0.6, -0.3, 0.0, 0.3, 0.6, 0.9};

// One line per verb with examples whose examples miss positions or pairs of the design, naming
// them; `lastLineUnterminated` (the text did not end in a newline) adds a hint that the file
// may have been cut short. The models still train on fewer examples; this says so.
std::vector<std::string> designWarnings(const Corpus& corpus, const VerbLibrary& verbs, bool lastLineUnterminated);

// Throws InputError naming the file, line and column for missing, duplicate, non-numeric or
// out-of-range values, unknown verbs or hands, keyframes the verb does not have, and examples
// that lack a hand or keyframe.
Corpus parseCorpus(std::string_view text, const std::string& fileName, const VerbLibrary& verbs);
Corpus loadCorpus(const std::filesystem::path& path, const VerbLibrary& verbs);

// The CSV text (comments first, then the header, then rows in corpus order); positions with
// 2 decimals (0.01 mm), angles with 3.
std::string formatCorpus(const Corpus& corpus, const VerbLibrary& verbs);

}  // namespace signstim::stimuli
