#!/usr/bin/python3
"""Runs the examples of docs/exports.md on a study folder's files, with a stand-in for the
program each example is written for, and checks what they compute.

  python3 tests/stimuli/check_export_examples.py docs/exports.md STUDY_FOLDER

Every fenced block whose first line is `# example: NAME` is an example; each NAME below must be
there (a renamed or deleted example fails the check, as does one that computes the wrong thing):
  psychopy-begin-experiment  PsychoPy Builder, Begin Experiment: given expInfo['participant'] as
                             P07, 7 or P7 and _thisDir the study folder, conditions_file must be
                             participants/P07/P07_conditions.csv, and it must exist;
  psychopy-begin-routine     PsychoPy Builder, Begin Routine, once per row of that file as
                             PsychoPy's importConditions gives it (check_conditions_for_psychopy):
                             correct_choice must be the row's q1_answer_text (None in phase 2);
  opensesame-prepare         OpenSesame inline_script: with var.subject_nr 7, var.conditions_file
                             must be P07_conditions.csv, a file of the study.
  psychopy-question-movie    (issue 24; run only on a study that signs its questions) Begin Routine
                             of a question routine: question_movie must be the study folder's path
                             of the row's q1_video_file (None where the row has no question 1);
  psychopy-instruction-movies (run only on a study that signs its instructions) welcome_movie and
                             part2_movie must be the clips the Gorilla sheet's instructions and
                             break rows carry, in the study folder.
Exit 0 pass, 1 a check failed, 2 bad usage. Standard library only.
"""

import os
import pathlib
import re
import sys
import types

sys.dont_write_bytecode = True
sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))
from check_conditions_for_psychopy import import_conditions  # noqa: E402

EXAMPLE = re.compile(r"^( *)```python\n\1# example: ([a-z0-9-]+)\n(.*?)^\1```", re.M | re.S)


def examples(markdown):
    found = {}
    for match in EXAMPLE.finditer(markdown):
        indent, name, body = match.group(1), match.group(2), match.group(3)
        found[name] = "\n".join(line[len(indent):] for line in body.splitlines())
    return found


def run(name, source, scope, failures):
    """exec() an example; an exception is a failure naming the example."""
    try:
        exec(source, scope)
        return True
    except Exception as error:  # noqa: BLE001 -- any error of the example is its failure
        failures.append(f"{name}: raises {type(error).__name__}: {error}")
        return False


def main(argv):
    if len(argv) != 2:
        print(__doc__.split("\n\n")[1], file=sys.stderr)
        return 2
    docs, folder = pathlib.Path(argv[0]), pathlib.Path(argv[1]).resolve()
    code = examples(docs.read_text(encoding="utf-8"))
    failures = []
    for name in ("psychopy-begin-experiment", "psychopy-begin-routine", "opensesame-prepare"):
        if name not in code:
            failures.append(f"{docs}: no example '{name}'")
    if failures:
        return report(failures)

    participants = sorted(p.name for p in (folder / "participants").iterdir())
    target = participants[6] if len(participants) > 6 else participants[-1]  # P07 when there are 7 or more
    number = int(target[1:])
    expected_file = folder / "participants" / target / f"{target}_conditions.csv"

    # PsychoPy: the session dialog's participant as the experimenter may type it.
    conditions_file = None
    for typed in (target, str(number), "P" + str(number)):
        scope = {"_thisDir": str(folder), "expInfo": {"participant": typed}}
        if not run("psychopy-begin-experiment", code["psychopy-begin-experiment"], scope, failures):
            return report(failures)
        if pathlib.Path(scope.get("conditions_file", "")) != expected_file:
            failures.append(f"psychopy-begin-experiment: participant {typed!r} gives "
                            f"{scope.get('conditions_file')!r}, expected {expected_file}")
        conditions_file = scope.get("conditions_file")
        study_folder = scope.get("study_folder")
    if not expected_file.is_file():
        failures.append(f"{expected_file} does not exist")
        return report(failures)

    trials, _ = import_conditions(expected_file.read_text(encoding="utf-8"))
    phase1 = 0
    for row, trial in enumerate(trials, start=2):
        scope = dict(trial)
        if not run("psychopy-begin-routine", code["psychopy-begin-routine"], scope, failures):
            continue
        wanted = trial["q1_answer_text"] if trial["display"] == "story" else None
        if scope.get("correct_choice") != wanted:
            failures.append(f"psychopy-begin-routine: row {row} of {conditions_file}: correct_choice is "
                            f"{scope.get('correct_choice')!r}, expected {wanted!r}")
        phase1 += trial["display"] == "story"
        clip = os.path.join(study_folder, trial["video_file"])
        if not clip.startswith(str(folder / "clips") + os.sep):
            failures.append(f"psychopy: the movie path {clip} is not in the study's clips/ folder")
    if phase1 == 0:
        failures.append(f"{conditions_file} has no phase-1 row: the example was not exercised")
    signed_examples(code, folder, study_folder, trials, target, failures)

    # OpenSesame: the subject number asked at the start, and the study's participant count.
    var = types.SimpleNamespace(subject_nr=number, participant_count=len(participants))
    run("opensesame-prepare", code["opensesame-prepare"], {"var": var}, failures)
    if getattr(var, "conditions_file", None) != expected_file.name:
        failures.append(f"opensesame-prepare: subject_nr {number} gives {getattr(var, 'conditions_file', None)!r}, "
                        f"expected {expected_file.name}")
    if not failures:
        print(f"check_export_examples: the PsychoPy and OpenSesame examples of {docs} find {target}'s file and "
              f"score its {phase1} phase-1 rows ({len(trials)} rows)")
    return report(failures)


def signed_examples(code, folder, study_folder, trials, target, failures):
    """Issue 24: the question and instruction clips of a study that signs them."""
    import csv
    signed = [t for t in trials if t.get("q1_video_file")]
    if "q1_video_file" in (trials[0] if trials else {}):
        if not signed:
            failures.append("the file has q1_video_file but no row fills it")
        for trial in trials:
            scope = dict(trial, os=os, study_folder=study_folder)
            if not run("psychopy-question-movie", code.get("psychopy-question-movie", "missing()"), scope, failures):
                return
            wanted = os.path.join(study_folder, trial["q1_video_file"]) if trial.get("q1_video_file") else None
            if scope.get("question_movie") != wanted:
                failures.append(f"psychopy-question-movie: {trial['display']} row gives {scope.get('question_movie')!r}, "
                                f"expected {wanted!r}")
            if wanted and not wanted.startswith(str(folder / "clips") + os.sep):
                failures.append(f"psychopy-question-movie: {wanted} is not in the study's clips/ folder")
    sheet = folder / "participants" / target / f"{target}_gorilla.csv"
    rows = list(csv.DictReader(sheet.open(encoding="utf-8", newline="")))
    pages = {r["display"]: r["video_file"] for r in rows if r["display"] in ("instructions", "break") and r["video_file"]}
    if not pages:
        return
    scope = {"os": os, "study_folder": study_folder}
    if not run("psychopy-instruction-movies", code.get("psychopy-instruction-movies", "missing()"), scope, failures):
        return
    for display, variable in (("instructions", "welcome_movie"), ("break", "part2_movie")):
        if display in pages and scope.get(variable) != os.path.join(study_folder, pages[display]):
            failures.append(f"psychopy-instruction-movies: {variable} is {scope.get(variable)!r}, the {display} row's "
                            f"clip is {pages[display]}")
    print(f"check_export_examples: the signed question and instruction examples find their clips")


def report(failures):
    for failure in failures:
        print(f"check_export_examples: FAIL: {failure}", file=sys.stderr)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
