// espeak-ng for mouthing (stimuli/story/mouthing.hpp): the phonemes of a word and their stress.
// espeak-ng keeps its state in globals and is not reentrant, so one process-wide engine
// loads it once and serialises every use behind a mutex.
#include "stimuli/story/mouthing_espeak.hpp"

#include "common/error.hpp"

#include <espeak-ng/espeak_ng.h>
#include <espeak-ng/speak_lib.h>

#include <algorithm>
#include <clocale>
#include <filesystem>
#include <mutex>
#include <stdexcept>

namespace signstim::stimuli::mouthing_detail {
namespace {

constexpr const char* kSetupHint =
    "mouthing needs espeak-ng's data (Debian: apt-get install espeak-ng-data, or scripts/setup.sh)";

// The files espeak-ng reads when it loads (LoadPhData, the English dictionary): checked first,
// because a missing one makes espeak_Initialize print to stderr rather than return an error.
constexpr const char* kDataFiles[] = {"phontab", "phonindex", "phondata", "intonations", "en_dict"};

// espeak-ng's own resolution of an explicit folder (espeak_ng_InitializePath, 1.51): FOLDER/
// espeak-ng-data when that is a folder, else FOLDER itself.
std::filesystem::path dataFolderOf(const std::string& requested) {
    std::error_code error;
    const std::filesystem::path inside = std::filesystem::path(requested) / "espeak-ng-data";
    return std::filesystem::is_directory(inside, error) ? inside : std::filesystem::path(requested);
}

void requireDataFiles(const std::filesystem::path& folder) {
    std::error_code error;
    if (!std::filesystem::is_directory(folder, error))
        throw EnvironmentError("espeak-ng: its data folder " + folder.string() + " is missing; " + kSetupHint);
    for (const char* name : kDataFiles)
        if (!std::filesystem::is_regular_file(folder / name, error))
            throw EnvironmentError("espeak-ng: " + (folder / name).string() + " is missing; " + kSetupHint);
}

class Engine {
public:
    void load(const std::string& requested) {
        std::lock_guard<std::mutex> lock(mutex_);
        loadLocked(requested);
    }

    std::vector<SpokenPhoneme> say(const std::string& text) {
        std::lock_guard<std::mutex> lock(mutex_);
        if (!loaded_) loadLocked({});
        // espeak_TextToPhonemes: espeak-ng's own translation (dictionary and rules) of the text
        // into its phoneme names, "|" between phonemes, " " between words, a stress mark (' or ,)
        // before a stressed vowel. It synthesizes no sound, so it is the same whatever was said
        // before (the phoneme events of a synthesis are not: their times move by 1 ms to tens of
        // ms with the wave generator's state, measured with 1.51; docs/mouthing.md, step 3).
        std::string phonemes;
        const void* next = text.c_str();
        while (next != nullptr) {
            const char* chunk = espeak_TextToPhonemes(&next, espeakCHARS_UTF8, '|' << 8);
            if (chunk == nullptr) break;
            if (!phonemes.empty()) phonemes += ' ';
            phonemes += chunk;
        }
        std::vector<SpokenPhoneme> spoken;
        SpokenPhoneme current;
        auto flush = [&spoken, &current] {
            if (!current.name.empty()) spoken.push_back(current);
            current = SpokenPhoneme();
        };
        for (const char c : phonemes) {
            if (c == '|' || c == ' ' || c == '\n') {
                flush();
            } else if (c == '\'' && current.name.empty()) {
                current.stress = 2;
            } else if (c == ',' && current.name.empty()) {
                current.stress = std::max(current.stress, 1);
            } else if ((c == '%' || c == '=') && current.name.empty()) {
                // unstressed / stress on the next syllable: no stress of its own
            } else {
                current.name += c;
            }
        }
        flush();
        return spoken;
    }

private:
    void loadLocked(const std::string& requested) {
        if (loaded_) {
            if (requested.empty() || requested == requested_) return;
            requireDataFiles(dataFolderOf(requested));
            throw std::logic_error("espeak-ng is already loaded from " + loadedFolder_ + "; cannot load it from " +
                                   requested);
        }
        // A named folder must hold the data itself: espeak-ng would quietly fall back to its own
        // search when it does not.
        if (!requested.empty()) requireDataFiles(dataFolderOf(requested));
        // Where espeak-ng will read from: its own search when no folder is named ($ESPEAK_DATA_PATH,
        // ~/espeak-ng-data, the compiled-in folder), read back through espeak_Info.
        espeak_ng_InitializePath(requested.empty() ? nullptr : requested.c_str());
        const char* folder = nullptr;
        espeak_Info(&folder);
        const std::filesystem::path dataFolder = folder != nullptr ? std::filesystem::path(folder) : dataFolderOf(requested);
        requireDataFiles(dataFolder);

        // espeak-ng sets the process's LC_CTYPE to a UTF-8 locale when it loads; put it back, so
        // that loading mouthing changes nothing else in signstim (we give it ASCII only).
        const char* ctype = std::setlocale(LC_CTYPE, nullptr);
        const std::string savedCtype = ctype != nullptr ? ctype : "C";
        // DONT_EXIT: espeak-ng would otherwise exit(1) on a load error. SYNCHRONOUS: no audio
        // device is opened.
        const int sampleRate = espeak_Initialize(AUDIO_OUTPUT_SYNCHRONOUS, 0, requested.empty() ? nullptr : requested.c_str(),
                                                 espeakINITIALIZE_DONT_EXIT);
        std::setlocale(LC_CTYPE, savedCtype.c_str());
        if (sampleRate <= 0)
            throw EnvironmentError("espeak-ng: could not load its data from " + dataFolder.string() + "; " + kSetupHint);
        if (espeak_SetVoiceByName("en-us") != EE_OK)
            throw EnvironmentError("espeak-ng: its American English voice (en-us) is missing from " + dataFolder.string() +
                                   "; " + kSetupHint);
        loaded_ = true;
        requested_ = requested;
        loadedFolder_ = dataFolder.string();
    }

    std::mutex mutex_;
    bool loaded_ = false;
    std::string requested_, loadedFolder_;
};

Engine& engine() {
    // Never terminated: espeak_Terminate joins espeak-ng's queue thread, and hung after a
    // second load in 1.51; the process's exit frees it all.
    static Engine instance;
    return instance;
}

}  // namespace

void loadSynthesizer(const std::string& espeakDataPath) { engine().load(espeakDataPath); }

std::vector<SpokenPhoneme> sayWord(const std::string& text) { return engine().say(text); }

}  // namespace signstim::stimuli::mouthing_detail
