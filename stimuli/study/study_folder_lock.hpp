#pragma once
// Who may write into a study folder (docs/study.md, "One folder, one study"): runs of one study
// with the same settings at once (the shards of a Slurm array writing into one shared folder),
// never two different studies or settings, which would leave the folder mixed. Two advisory
// locks (flock) in .signstim/:
//   lock     exclusive, held for moments: while a run checks and writes the plan, and while it
//            (or a merge) writes the documents and the manifest;
//   running  shared by every run rendering into the folder, for the run's whole time; a run
//            whose plan differs from the folder's may rewrite it only when it can take this one
//            exclusively (no other run is rendering), and so may a merge.
// The kernel releases a lock when its process ends, however it ends, so the lock of a run that
// was killed (or of a node lost) is taken over at once. Each holder writes its host and PID into
// `running`, for the message that refuses a second run.
#include <filesystem>
#include <string>

namespace signstim::stimuli {

class StudyFolderLock {
public:
    // Creates DIR/.signstim/ when missing and takes `lock` (waiting while another run holds it:
    // a moment). Throws IoError (exit 3) when the lock files cannot be created.
    explicit StudyFolderLock(const std::filesystem::path& dir);
    ~StudyFolderLock();
    StudyFolderLock(const StudyFolderLock&) = delete;
    StudyFolderLock& operator=(const StudyFolderLock&) = delete;

    // Whether another run is rendering into the folder. When none is, this one now holds
    // `running` exclusively until beginRun or the end.
    bool othersRunning();
    // Holds `running` shared (with the other runs of the same plan) and says who we are.
    void beginRun();
    // Takes or gives back `lock` (the checks and the final files happen under it).
    void lock();
    void unlock();
    // "PID 1234 on host node07": the run that last said so in `running`, or "another signstim run".
    std::string holder() const;

private:
    std::filesystem::path dir_;
    int lockFd_ = -1, runningFd_ = -1;
    bool locked_ = false;
};

// Refuses (InputError naming --out, exit 2) an output folder that is the file system's root, the
// home folder or the working directory itself, and one that holds files that are not a study
// folder's (no .signstim/plan.json) unless `force`, which writes beside them and never deletes
// them. An absent or empty folder is fine.
void checkStudyOutFolder(const std::filesystem::path& dir, bool force);

}  // namespace signstim::stimuli
