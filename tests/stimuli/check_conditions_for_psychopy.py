#!/usr/bin/python3
"""Reads a study's conditions files the way PsychoPy's Builder does and checks that nothing is lost
or changed on the way in (docs/exports.md, issue 24 §5).

  python3 tests/stimuli/check_conditions_for_psychopy.py FILE.csv ...   check the files
  python3 tests/stimuli/check_conditions_for_psychopy.py --self-test     the checker must fail on the
                                                                         two mistakes the lab met

The rules are those of psychopy.data.utils.importConditions (PsychoPy 2021-2024) for a .csv file:
  1. pandas.read_csv(file, encoding='utf-8-sig', sep=',', decimal='.'): a column whose cells are
     all whole numbers is int64; one with any empty cell among numbers is float64 (1 -> 1.0);
     other columns hold text (object), an empty cell being NaN;
  2. every text cell that float() accepts after ',' -> '.' becomes a float;
  3. columns named 'Unnamed: N' are dropped;
  4. header names must be non-empty, must not start with a digit, and must not contain a
     non-word character (re '\\W'); otherwise ConditionsImportError;
  5. in each text cell the two characters '\\n' become a line break; a text cell that starts with
     '[' and ends with ']' is eval()ed; a non-text NaN becomes None.
Builder then makes each column a variable of the experiment script, and its data file puts the
session dialog's fields (expInfo: participant, session, date, expName, psychopyVersion,
frameRate, expStart) beside the loop's columns under the same names, so a column called like
one of them is lost in the saved data. Builder's namespace (psychopy/experiment/_experiment.py
NameSpace) also reserves Python keywords and builtins, the numpy names the script imports, and
its own variables.

With pandas installed (Debian: python3-pandas) rule 1 is pandas itself; without it, a
reimplementation of read_csv's type inference for these files (RFC 4180 via the csv module).

What this checks of each conditions file:
  - PsychoPy accepts the header (rule 4) and no column name collides with expInfo or Builder's
    namespace;
  - every whole-number column (phase, trial, group, qN_answer_index) arrives as an integer, so
    that `choices[q1_answer_index]` indexes a list (issue 24: 1.0 broke it);
  - participant_id arrives as the participant's id (P01), the file's own;
  - the text columns arrive as the text the file holds (rules 2 and 5 change nothing);
  - qN_answer_text is the choice at qN_answer_index (the text a button response returns).
Exit 0 pass, 1 a check failed, 2 bad usage. Standard library only (pandas when present).
"""

import builtins
import csv
import io
import keyword
import math
import pathlib
import re
import sys

try:
    import pandas  # noqa: F401
    HAVE_PANDAS = True
except ImportError:
    HAVE_PANDAS = False

# Rule 4 (psychopy.data.utils._nonalphanumeric_re and isValidVariableName).
NON_WORD = re.compile(r"\W")
# PsychoPy's session dialog and the fields Builder adds to expInfo (psychopy/experiment
# _experiment.py, the script template): saved under these names beside the conditions' columns.
EXP_INFO = {"participant", "session", "date", "expName", "psychopyVersion", "frameRate", "expStart"}
# Builder's namespace (psychopy/experiment/_experiment.py NameSpace.builder and the numpy names
# the generated script imports: _numpyImports, _numpyRandomImports).
BUILDER = {"KeyResponse", "keyboard", "key_resp", "buttons", "continueRoutine", "expInfo", "expName", "thisExp",
           "filename", "logFile", "paramName", "t", "frameN", "currentLoop", "dlg", "_thisDir", "endExpNow",
           "globalClock", "routineTimer", "frameDur", "theseKeys", "win", "x", "y", "level", "component",
           "thisComponent", "trials", "thisTrial"}
NUMPY = {"sin", "cos", "tan", "log", "log10", "pi", "average", "sqrt", "std", "deg2rad", "rad2deg", "linspace",
         "asarray", "random", "randint", "normal", "shuffle", "randchoice", "np"}
PSYCHOPY = {"psychopy", "os", "core", "data", "visual", "event", "gui", "sound", "logging", "clock", "colors",
            "layout", "hardware", "monitors", "misc", "microphone", "NOT_STARTED", "STARTED", "PLAYING", "PAUSED",
            "STOPPED", "FINISHED", "PRESSED", "RELEASED", "FOREVER"}
RESERVED = EXP_INFO | BUILDER | NUMPY | PSYCHOPY | set(keyword.kwlist) | set(dir(builtins))

WHOLE_NUMBER_COLUMNS = re.compile(r"^(phase|trial|group|q\d+_answer_index)$")
TEXT_COLUMNS = re.compile(r"^(display|participant_id|story_id|story_title|version|sentence_id|gloss|verb|video_file|"
                          r"video_name|poster_file|poster_name|q\d+_(text|video_file|video_name|choice_[a-z]|answer|answer_text)|"
                          r"panel_[a-z]_version|panel_code)$")
NAN = float("nan")


def is_nan(value):
    return isinstance(value, float) and math.isnan(value)


# ---- rule 1 without pandas: read_csv's type inference --------------------------------------------

INT_TEXT = re.compile(r"^\s*[+-]?\d+\s*$")
# read_csv's default na_values: cells that become NaN (and so None in PsychoPy).
NA_TEXT = {"", "#N/A", "#N/A N/A", "#NA", "-1.#IND", "-1.#QNAN", "-NaN", "-nan", "1.#IND", "1.#QNAN", "<NA>", "N/A",
           "NA", "NULL", "NaN", "None", "n/a", "nan", "null"}


def float_or_none(text):
    try:
        return float(text)
    except ValueError:
        return None


def read_csv_like_pandas(text):
    """(columns, rows of values) as pandas.read_csv types them: int, float (NaN for empty) or str."""
    if text.startswith("\ufeff"):
        text = text[1:]  # encoding='utf-8-sig'
    records = list(csv.reader(io.StringIO(text, newline="")))
    header, body = records[0], records[1:]
    # pandas names a nameless column 'Unnamed: N' and a repeated one 'name.1'.
    seen, columns = {}, []
    for i, name in enumerate(header):
        name = name if name != "" else f"Unnamed: {i}"
        if name in seen:
            seen[name] += 1
            name = f"{name}.{seen[name]}"
        else:
            seen[name] = 0
        columns.append(name)
    width = len(columns)
    cells = [[row[i] if i < len(row) else "" for i in range(width)] for row in body if row != []]
    typed = [[None] * width for _ in cells]
    for c in range(width):
        values = ["" if row[c] in NA_TEXT else row[c] for row in cells]
        present = [v for v in values if v != ""]
        if present and all(INT_TEXT.match(v) for v in present) and len(present) == len(values):
            kind = int
        elif present and all(float_or_none(v) is not None for v in present):
            kind = float
        else:
            kind = str
        for r, v in enumerate(values):
            if v == "":
                typed[r][c] = NAN
            elif kind is int:
                typed[r][c] = int(v)
            elif kind is float:
                typed[r][c] = float(v)
            else:
                typed[r][c] = v
    return columns, typed


def read_csv_with_pandas(path_or_text):
    import pandas as pd
    frame = pd.read_csv(io.StringIO(path_or_text), encoding="utf-8-sig", sep=",", decimal=".")
    columns = list(frame.columns)
    rows = []
    for record in frame.itertuples(index=False):
        row = []
        for value in record:
            if hasattr(value, "item"):
                value = value.item()  # numpy scalar -> Python int/float, as list indexing sees it
            row.append(value)
        rows.append(row)
    return columns, rows


# ---- rules 2 to 5: importConditions ------------------------------------------------------------

class ConditionsImportError(Exception):
    pass


def import_conditions(text):
    """The list of dicts and the field names importConditions returns for a .csv file's text."""
    columns, rows = read_csv_with_pandas(text) if HAVE_PANDAS else read_csv_like_pandas(text)
    # rule 2: text cells that read as numbers (a decimal comma too) become floats
    for row in rows:
        for c, value in enumerate(row):
            if isinstance(value, str):
                number = float_or_none(value.replace(",", "."))
                if number is not None:
                    row[c] = number
    # rule 3
    keep = [c for c, name in enumerate(columns) if not str(name).startswith("Unnamed: ")]
    columns = [columns[c] for c in keep]
    rows = [[row[c] for c in keep] for row in rows]
    # rule 4
    if not all(columns):
        raise ConditionsImportError("Missing parameter name(s); empty cell(s) in the first row?")
    for name in columns:
        if name[0].isdigit():
            raise ConditionsImportError(f'Parameters (column headers) cannot begin with numeric character: "{name}"')
        if NON_WORD.search(name):
            raise ConditionsImportError(f'Parameters (column headers) cannot contain punctuation or spaces: "{name}"')
    # rule 5
    trials = []
    for row in rows:
        trial = {}
        for name, value in zip(columns, row):
            if isinstance(value, str):
                value = value.replace("\\n", "\n")
                if value.startswith("[") and value.endswith("]"):
                    value = eval(value)  # what PsychoPy does; the check below fails the file first
            elif is_nan(value):
                value = None
            trial[name] = value
        trials.append(trial)
    return trials, columns


# ---- the checks ---------------------------------------------------------------------------------

def check(text, name, participant=None):
    """Failures of one conditions file's text."""
    failures = []
    raw = list(csv.DictReader(io.StringIO(text.lstrip("\ufeff"), newline="")))
    for row in raw:
        for column, value in row.items():
            if TEXT_COLUMNS.match(column or "") and value.startswith("[") and value.endswith("]"):
                failures.append(f"{name}: {column} {value!r} would be eval()ed by PsychoPy")
                return failures
    try:
        trials, columns = import_conditions(text)
    except ConditionsImportError as error:
        return [f"{name}: PsychoPy refuses the file: {error}"]
    for column in columns:
        if column in RESERVED:
            why = ("PsychoPy's session field of that name overwrites it in the saved data" if column in EXP_INFO
                   else "a name Builder's script already uses")
            failures.append(f"{name}: column '{column}': {why}")
    if participant is None:
        match = re.search(r"(P\d+)_conditions\.csv$", name)
        participant = match.group(1) if match else None
    for number, (trial, source) in enumerate(zip(trials, raw), start=2):
        where = f"{name}: line {number}"
        for column, value in trial.items():
            if WHOLE_NUMBER_COLUMNS.match(column):
                if not isinstance(value, int) or isinstance(value, bool):
                    failures.append(f"{where}: {column} arrives as {value!r} ({type(value).__name__}), not an integer: "
                                    "it cannot index a list")
            elif TEXT_COLUMNS.match(column):
                wanted = source[column] if source[column] != "" else None
                if value != wanted:
                    failures.append(f"{where}: {column} {source[column]!r} arrives as {value!r}")
        if participant and trial.get("participant_id") != participant:
            failures.append(f"{where}: participant_id arrives as {trial.get('participant_id')!r}, the file is "
                            f"{participant}'s")
        for column in columns:
            found = re.match(r"^(q\d+)_answer_index$", column)
            if not found or trial[column] is None or not isinstance(trial[column], int) or trial[column] < 0:
                continue
            q = found.group(1)
            choices = [trial[c] for c in columns if re.match(rf"^{q}_choice_[a-z]$", c) and trial[c] is not None]
            if trial[column] >= len(choices):
                failures.append(f"{where}: {column} {trial[column]} is past the {len(choices)} choices")
            elif trial.get(f"{q}_answer_text") != choices[trial[column]]:
                failures.append(f"{where}: {q}_answer_text {trial.get(f'{q}_answer_text')!r} is not choice "
                                f"{trial[column]} {choices[trial[column]]!r}")
    return failures


# What the issue-24 lab met: a `participant` column, and an answer index left empty in phase-2
# rows (pandas then reads the whole column as floats). Synthetic rows.
SELF_TEST_BAD = {
    "a participant column":
        "display,phase,trial,participant,q1_text,q1_choice_a,q1_choice_b,q1_answer_index,q1_answer_text\r\n"
        "story,1,1,P01,Who?,John,Mary,1,Mary\r\n",
    "an empty answer index in a phase-2 row":
        "display,phase,trial,participant_id,q1_text,q1_choice_a,q1_choice_b,q1_answer_index,q1_answer_text\r\n"
        "story,1,1,P01,Who?,John,Mary,1,Mary\r\n"
        "likert,2,1,P01,,,,,\r\n",
    "a choice that reads as a number":
        "display,phase,trial,participant_id,q1_text,q1_choice_a,q1_choice_b,q1_answer_index,q1_answer_text\r\n"
        "story,1,1,P01,How many?,\"3,5\",4,1,4\r\n",
    "a header PsychoPy refuses":
        "display,phase,trial,participant id\r\nstory,1,1,P01\r\n",
}
SELF_TEST_GOOD = (
    "display,phase,trial,participant_id,q1_text,q1_choice_a,q1_choice_b,q1_answer_index,q1_answer_text\r\n"
    "story,1,1,P01,Who?,John,Mary,1,Mary\r\n"
    "likert,2,1,P01,,,,-1,\r\n")


def self_test():
    failures = []
    if check(SELF_TEST_GOOD, "good.csv", "P01"):
        failures.append(f"a good file is refused: {check(SELF_TEST_GOOD, 'good.csv', 'P01')}")
    for what, text in SELF_TEST_BAD.items():
        found = check(text, "bad.csv", "P01")
        if not found:
            failures.append(f"the checker accepts a file with {what}")
        else:
            print(f"check_conditions_for_psychopy: a file with {what} is refused: {found[0]}")
    return failures


def main(argv):
    if argv == ["--self-test"]:
        failures = self_test()
    elif argv and not any(a.startswith("-") for a in argv):
        failures = []
        for file in argv:
            failures += check(pathlib.Path(file).read_text(encoding="utf-8"), file)
        if not failures:
            print(f"check_conditions_for_psychopy: {len(argv)} file(s) arrive in PsychoPy unchanged "
                  f"({'pandas' if HAVE_PANDAS else 'read_csv reimplemented; pandas is not installed'})")
    else:
        print(__doc__.split("\n\n")[1], file=sys.stderr)
        return 2
    for failure in failures:
        print(f"check_conditions_for_psychopy: FAIL: {failure}", file=sys.stderr)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
