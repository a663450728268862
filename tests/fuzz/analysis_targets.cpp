// Fuzz targets of the files `signstim analyze` reads: participants' results CSVs (jsPsych,
// PsychoPy, Gorilla exports), the CSV reader under them, and column maps.
#include "analysis/csv_table.hpp"
#include "analysis/results_file.hpp"
#include "stimuli/json_source.hpp"
#include "tests/fuzz/fixtures.hpp"
#include "tests/fuzz/fuzz_target.hpp"

#include <cmath>

using namespace signstim;
using signstim::fuzz::expectRefusalOrSuccess;

SIGNSTIM_FUZZ_TARGET(csv) {
    expectRefusalOrSuccess("data.csv", [&] {
        const analysis::CsvTable table = analysis::parseCsv(input, "data.csv");
        for (const auto& record : table.records)
            if (record.fields.size() != table.header.size()) fuzz::fail("a record with the wrong number of fields");
    });
}

// Against the tiny test study (2 stories x 2 versions, 2 participants): ratings accepted
// must be NaN (not rated) or on the study's scale; answers one of the question's choices or none.
SIGNSTIM_FUZZ_TARGET(results_csv) {
    expectRefusalOrSuccess("P01.csv", [&] {
        std::vector<std::string> warnings;
        const analysis::ParticipantResults results =
            analysis::parseResults(input, "P01.csv", fuzz::studyListing(), analysis::ColumnMap{}, warnings);
        const stimuli::StudyListing& study = fuzz::studyListing();
        for (const auto& trial : results.phase2)
            for (double rating : trial.ratings)
                if (!std::isnan(rating) && !(rating >= study.likertMinimum && rating <= study.likertMaximum))
                    fuzz::fail("accepted a rating of " + std::to_string(rating));
        for (const auto& trial : results.phase1) {
            if (trial.story >= study.stories.size()) fuzz::fail("accepted a story out of range");
            const auto& questions = study.stories[trial.story].questions;
            for (std::size_t q = 0; q < trial.choices.size(); ++q) {
                const int choice = trial.choices[q];
                if (choice == analysis::kNoAnswer) continue;
                if (q >= questions.size() || choice < 0 ||
                    static_cast<std::size_t>(choice) >= questions[q].choices.size())
                    fuzz::fail("accepted choice " + std::to_string(choice) + " of question " + std::to_string(q + 1));
            }
        }
    });
}

SIGNSTIM_FUZZ_TARGET(column_map) {
    expectRefusalOrSuccess("columns.json", [&] {
        analysis::parseColumnMap(stimuli::parseJsonText(std::string(input), "columns.json"));
    });
}
