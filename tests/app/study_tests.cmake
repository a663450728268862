# `signstim study` end to end (the built binary, validation on): check, render, resume, verify,
# shards and merge, interruption.
# Eye-tracking regions and ELAN files beside a study's clips (issue 24 §3-4), end to end, in the
# same binary: its test of every clip's regions reads the same reference run.
signstim_add_test(signstim_app_study_tests
  SOURCES study_cli_test.cpp study_annotations_cli_test.cpp
  LIBS nlohmann_json::nlohmann_json signstim_test_run_command signstim_stimuli
  # The five tests that compare against or read one uninterrupted run of the small study
  # (tests/app/study_reference_run.hpp) share it in one process (signstim_add_test,
  # ONE_PROCESS) instead of rendering it five times.
  ONE_PROCESS
    StudyCli.AgainstOneReferenceRun
    "StudyCli.RendersPlayableClipsResumesAndVerifyCatchesAChangedByte:\
StudyCli.ThreeShardsMergedEqualOneRunByteForByte:\
StudyCli.InterruptedRunLeavesNoBrokenFileAndResumesToTheSameBytes:\
StudyCli.ExperimentIsWrittenWithTheStudyIntoTheManifestAndKeptByLaterRuns:\
StudyAnnotationsCli.EveryClipHasRegionsAndAnElanFileListedBesideIt"
  COST 150)  # the five sharing the reference run: ~90 s of CPU under gcc (ThreeShards* alone ~65 s), more under ASan
add_dependencies(signstim_app_study_tests signstim)

# The review page and the jsPsych experiment of a rendered study in headless Chromium (label
# browser; one browser at a time; a missing browser, or jsPsych not fetched, is a skip, shown as
# such by CTest).
add_executable(signstim_app_study_browser_tests study_browser_test.cpp)
target_link_libraries(signstim_app_study_browser_tests PRIVATE signstim_test_run_command GTest::gtest_main)
target_include_directories(signstim_app_study_browser_tests PRIVATE ${PROJECT_SOURCE_DIR})
target_compile_definitions(signstim_app_study_browser_tests PRIVATE
  SIGNSTIM_SOURCE_DIR="${PROJECT_SOURCE_DIR}" SIGNSTIM_BINARY_DIR="${PROJECT_BINARY_DIR}"
  SIGNSTIM_BROWSER_PYTHON="${SIGNSTIM_BROWSER_PYTHON}")
add_dependencies(signstim_app_study_browser_tests signstim)
gtest_discover_tests(signstim_app_study_browser_tests DISCOVERY_TIMEOUT 60
  PROPERTIES ENVIRONMENT "SIGNSTIM_SOURCE_DIR=${PROJECT_SOURCE_DIR}" LABELS browser RESOURCE_LOCK chromium
    SKIP_REGULAR_EXPRESSION "\\[  SKIPPED \\]" TIMEOUT 300)

# `signstim analyze` and `simulate-results` end to end on the small study (analysis area).
signstim_add_test(signstim_app_analysis_tests
  SOURCES analysis_cli_test.cpp
  LIBS nlohmann_json::nlohmann_json signstim_test_run_command
  # Every test analyses the same rendered small study: one process renders it once (ONE_PROCESS).
  ONE_PROCESS AnalysisCli.OnOneRenderedSmallStudy "AnalysisCli.*")
add_dependencies(signstim_app_analysis_tests signstim)

# Human-video versions (issue 24 §2): synthetic recordings probed, normalised, hashed, resumed, sharded.
signstim_add_test(signstim_app_study_human_tests
  SOURCES study_human_cli_test.cpp
  LIBS nlohmann_json::nlohmann_json signstim_test_run_command)
add_dependencies(signstim_app_study_human_tests signstim)
# Issue 24's "Done when" in one small study: ASL questions and a synthetic human-video version
# render, verify, shard (2 shards merged = one run, byte for byte) and resume (interrupted; a
# changed question re-renders only its unit).
signstim_add_test(signstim_app_study_done_when_tests
  SOURCES study_done_when_cli_test.cpp
  LIBS nlohmann_json::nlohmann_json signstim_test_run_command)
add_dependencies(signstim_app_study_done_when_tests signstim)
# The probes of a study's recordings kept in its folder: probed once per content (a stand-in prober).
signstim_add_test(signstim_app_study_human_probe_cache_tests
  SOURCES study_human_probe_cache_test.cpp
  LIBS signstim_app)
