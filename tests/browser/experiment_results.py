"""The results file of run_experiment.py's sessions: what the responder expected, and the checks of
one saved CSV against it and the participant's schedule (check_results); mutations() makes the
wrong copies the checker must reject. Standard library only.
"""

import csv
import io

RESULT_COLUMNS = (
    "participant,phase,trial,story_id,sentence_id,version,panel_code,"
    "q1_response,q1_correct,q2_response,q2_correct,q3_response,q3_correct,q4_response,q4_correct,n_correct,"
    "rating_a,rating_b,rating_c,rating_d,rating_point,rating_vector,rating_animator,rating_uninflected,rt_ms,"
    "bg_hearing,bg_asl_age,bg_asl_school,bg_daily_use"
).split(",")
BACKGROUND_COLUMN = {"hearing": "bg_hearing", "aslAge": "bg_asl_age", "aslSchool": "bg_asl_school",
                     "dailyUse": "bg_daily_use"}
VERSION_OF_LETTER = {"P": "point", "V": "vector", "A": "animator", "U": "uninflected"}
LETTERS = "ABCDEFGHIJ"


def read_conditions(path):
    with open(path, newline="", encoding="utf-8") as handle:
        return list(csv.DictReader(handle))


class Expected:
    """What one participant's session answered, as the responder chose it."""

    def __init__(self, participant, timeline, conditions):
        self.participant = participant
        self.timeline = timeline
        self.conditions = conditions
        self.answers = []   # per phase-1 trial: list of chosen 0-based option indices
        self.ratings = []   # per phase-2 trial: list of ratings, panel A first
        self.asked = []     # the study's background question ids (participants/index.js)
        self.background = None  # the answers given, by result column
        self.prompt = ""    # the study's rating prompt
        self.layout = None  # the first rating page's layout (LAYOUT_JS)


def check_results(data, expected):
    """Failures of one saved CSV against what the responder did and the participant's schedule."""
    failures = []
    who = expected.participant
    text = data.decode("utf-8") if isinstance(data, bytes) else data
    lines = text.split("\r\n")
    if lines[-1] != "" or any("\n" in line for line in lines):
        failures.append(f"{who}: lines must end in CRLF, the last one too")
    rows = list(csv.reader(io.StringIO(text, newline="")))
    if not rows or rows[0] != RESULT_COLUMNS:
        failures.append(f"{who}: header {','.join(rows[0]) if rows else '(none)'}; expected {','.join(RESULT_COLUMNS)}")
        return failures
    records = [dict(zip(RESULT_COLUMNS, row)) for row in rows[1:]]
    for number, row in enumerate(rows[1:], start=2):
        if len(row) != len(RESULT_COLUMNS):
            failures.append(f"{who}: line {number} has {len(row)} fields, the header {len(RESULT_COLUMNS)}")
    phase1 = expected.timeline["phase1"]
    phase2 = expected.timeline["phase2"]
    if len(records) != len(phase1) + len(phase2):
        failures.append(f"{who}: {len(records)} rows; the schedule has {len(phase1)} + {len(phase2)} trials")
    conditions1 = [c for c in expected.conditions if c["phase"] == "1"]
    conditions2 = [c for c in expected.conditions if c["phase"] == "2"]

    def empty(row, columns, where):
        for column in columns:
            if row.get(column, "") != "":
                failures.append(f"{where}: {column} is {row[column]!r}, expected empty")

    def whole_ms(row, where):
        if not row.get("rt_ms", "").isdigit():
            failures.append(f"{where}: rt_ms {row.get('rt_ms')!r} is not a whole number of milliseconds")

    answers = expected.background or {}
    for number, row in enumerate(records, start=2):
        for column in BACKGROUND_COLUMN.values():
            if row.get(column, "") != answers.get(column, ""):
                failures.append(f"{who}: line {number}: {column} is {row.get(column)!r}, the background form was "
                                f"answered {answers.get(column, '')!r}")
    if expected.asked and expected.background is None:
        failures.append(f"{who}: the study asks {expected.asked} but no background form was shown")
    rating_columns = [c for c in RESULT_COLUMNS if c.startswith("rating_")]
    question_columns = [c for c in RESULT_COLUMNS if c.startswith("q") or c == "n_correct"]
    for i, trial in enumerate(phase1):
        if i >= len(records):
            break
        row, where = records[i], f"{who} phase-1 row {i + 1}"
        scheduled = conditions1[i] if i < len(conditions1) else {}
        wanted = {"participant": who, "phase": "1", "trial": str(i + 1), "story_id": trial["story"],
                  "version": trial["version"]}
        for column, value in wanted.items():
            if row[column] != value:
                failures.append(f"{where}: {column} is {row[column]!r}, expected {value!r}")
        if scheduled.get("story_id") != trial["story"] or scheduled.get("version") != trial["version"]:
            failures.append(f"{where}: the conditions CSV and the timeline file disagree on trial {i + 1}")
        empty(row, ["sentence_id", "panel_code"] + rating_columns, where)
        answers = expected.answers[i] if i < len(expected.answers) else []
        correct = 0
        for q in range(4):
            response, flag = row[f"q{q + 1}_response"], row[f"q{q + 1}_correct"]
            if q >= len(trial["questions"]):
                empty(row, [f"q{q + 1}_response", f"q{q + 1}_correct"], where)
                continue
            question = trial["questions"][q]
            letter = LETTERS[answers[q]] if q < len(answers) else "?"
            right = "1" if letter == question["correct_letter"] else "0"
            correct += int(right)
            if response != letter:
                failures.append(f"{where}: q{q + 1}_response is {response!r}, the responder chose {letter}")
            if flag != right:
                failures.append(f"{where}: q{q + 1}_correct is {flag!r}; {letter} against the key "
                                f"{question['correct_letter']} is {right}")
        if row["n_correct"] != str(correct):
            failures.append(f"{where}: n_correct is {row['n_correct']!r}, expected {correct}")
        whole_ms(row, where)
    for i, trial in enumerate(phase2):
        if len(phase1) + i >= len(records):
            break
        row, where = records[len(phase1) + i], f"{who} phase-2 row {i + 1}"
        scheduled = conditions2[i] if i < len(conditions2) else {}
        code = scheduled.get("panel_code", "")
        wanted = {"participant": who, "phase": "2", "trial": str(i + 1), "sentence_id": trial["sentence"],
                  "panel_code": code}
        for column, value in wanted.items():
            if row[column] != value:
                failures.append(f"{where}: {column} is {row[column]!r}, expected {value!r}")
        if scheduled.get("sentence_id") != trial["sentence"] or code != trial["panel_code"]:
            failures.append(f"{where}: the conditions CSV and the timeline file disagree on trial {i + 1}")
        empty(row, ["story_id", "version"] + question_columns, where)
        given = expected.ratings[i] if i < len(expected.ratings) else []
        by_version = {}
        for k, letter in enumerate(code):
            panel = "abcdefghij"[k]
            value = str(given[k]) if k < len(given) else "?"
            if row.get(f"rating_{panel}") != value:
                failures.append(f"{where}: rating_{panel} is {row.get(f'rating_{panel}')!r}, the responder gave {value}")
            by_version[VERSION_OF_LETTER[letter]] = value
        for panel in "abcd"[len(code):]:
            empty(row, [f"rating_{panel}"], where)
        for version in VERSION_OF_LETTER.values():
            value = by_version.get(version, "")
            if row[f"rating_{version}"] != value:
                failures.append(f"{where}: rating_{version} is {row[f'rating_{version}']!r}; panel code {code} "
                                f"puts {version} where the responder gave {value or '(nothing)'}")
        whole_ms(row, where)
    return failures


def mutations(text):
    """Copies of a correct CSV, each wrong in one way the checker must notice."""
    lines = text.split("\r\n")
    header, body = lines[0], [line for line in lines[1:] if line]
    columns = header.split(",")
    out = {}

    def rows_to_text(rows):
        return "\r\n".join([header] + rows) + "\r\n"

    def edit(row_index, change):
        fields = body[row_index].split(",")
        change(fields)
        rows = list(body)
        rows[row_index] = ",".join(fields)
        return rows_to_text(rows)

    phase2_rows = [i for i, line in enumerate(body) if line.split(",")[1] == "2"]
    phase1_rows = [i for i, line in enumerate(body) if line.split(",")[1] == "1"]
    if phase2_rows:
        point, vector = columns.index("rating_point"), columns.index("rating_vector")

        def swap(fields):
            fields[point], fields[vector] = fields[vector], fields[point]
        out["rating_point and rating_vector swapped in the first phase-2 row"] = edit(phase2_rows[0], swap)
    if phase1_rows:
        flag = columns.index("q1_correct")

        def flip(fields):
            fields[flag] = "0" if fields[flag] == "1" else "1"
        out["q1_correct flipped in the first phase-1 row"] = edit(phase1_rows[0], flip)
    if len(phase1_rows) >= 2:
        rows = list(body)
        rows[phase1_rows[0]], rows[phase1_rows[1]] = rows[phase1_rows[1]], rows[phase1_rows[0]]
        out["the first two phase-1 rows swapped"] = rows_to_text(rows)
    out["the last row missing"] = rows_to_text(body[:-1])
    hearing = columns.index("bg_hearing")

    def forget(fields):
        fields[hearing] = ""
    out["bg_hearing emptied in the first row"] = edit(0, forget)
    out["a column renamed (rating_a -> rating_A)"] = text.replace("rating_a,", "rating_A,", 1)
    return out
