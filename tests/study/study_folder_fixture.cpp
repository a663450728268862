#include "tests/study/study_folder_fixture.hpp"

#include "common/atomic_file.hpp"
#include "common/file_manifest.hpp"
#include "tests/stimuli/review_page_fixture.hpp"

#include <unistd.h>

#include <fstream>
#include <sstream>

namespace signstim::stimuli::testing {

namespace fs = std::filesystem;
using nlohmann::json;

FolderFixture folderFixture(const std::string& salt, bool signedQuestions) {
    FolderFixture f;
    f.salt = salt;
    ReviewFixtureShape shape{.stories = 4, .participants = 4, .likertSentences = 4};
    shape.signedQuestions = signedQuestions;
    f.listing = reviewFixtureListing(shape);
    // The review fixture leaves the design's table out; the plan's reader wants it (a Latin square).
    f.listing.groupVersion.assign(f.listing.stories.size(), {});
    for (std::size_t s = 0; s < f.listing.stories.size(); ++s)
        for (std::size_t g = 0; g < f.listing.versions.size(); ++g)
            f.listing.groupVersion[s].push_back((s + g) % f.listing.versions.size());
    f.units = studyUnits(f.listing);
    std::vector<std::string> hashes;
    for (const StudyUnit& u : f.units) hashes.push_back("inputs-" + u.id + salt);
    StudyRenderSettings settings{160, 120, "15", 0, 4, 1.0, {}};
    f.plan = studyPlan(f.listing, settings, false, f.units, hashes, "");
    return f;
}

fs::path freshFolder(const std::string& name) {
    const fs::path dir = fs::temp_directory_path() / ("signstim-study-folder-test-" + std::to_string(::getpid())) / name;
    fs::remove_all(dir);
    fs::create_directories(dir);
    return dir;
}

void writePlan(const fs::path& dir, const FolderFixture& study) {
    fs::create_directories(dir / ".signstim" / "units");
    writeFileAtomic(dir / kStudyPlanFile, study.plan.dump(2) + "\n");
}

void writeUnit(const fs::path& dir, const FolderFixture& study, const StudyUnit& unit) {
    std::vector<ListedClip> clips;
    if (unit.kind == StudyUnitKind::Questions) {
        for (const ListedQuestion& q : study.listing.stories[unit.index].questions)
            if (!q.clip.video.empty()) clips.push_back(q.clip);
    } else if (unit.kind == StudyUnitKind::Instructions) {
        for (const ListedInstruction& page : study.listing.instructions)
            if (!page.clip.video.empty()) clips.push_back(page.clip);
    } else if (unit.story) {
        clips = study.listing.stories[unit.index].clips;
    } else {
        clips.push_back(study.listing.sentences[unit.index].clip);
    }
    json files = json::array();
    for (const ListedClip& clip : clips) {
        fs::create_directories((dir / clip.video).parent_path());
        fs::create_directories((dir / clip.poster).parent_path());
        writeBytes(dir / clip.video, "SYNTHETIC clip " + clip.video + "\n");
        writeBytes(dir / clip.poster, "SYNTHETIC poster " + clip.poster + "\n");
        json video = describeFile(dir, clip.video, "video");
        video["frames"] = clip.frameCount;
        video["durationSeconds"] = clip.durationSeconds;
        files.push_back(video);
        files.push_back(describeFile(dir, clip.poster, "poster"));
    }
    fs::create_directories(dir / kStudyUnitFolder);
    writeUnitRecord(dir, unit.id, "inputs-" + unit.id + study.salt, clips.front().frameCount, files);
}

std::string readBytes(const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    std::ostringstream bytes;
    bytes << in.rdbuf();
    return bytes.str();
}

void writeBytes(const fs::path& file, const std::string& bytes) {
    std::ofstream out(file, std::ios::binary | std::ios::trunc);
    out << bytes;
}

}  // namespace signstim::stimuli::testing
