#!/usr/bin/python3
"""Runs a study's jsPsych experiment (DIR/experiment/) in headless Chromium for two participants
with a scripted responder, and checks the CSV each session saves.

  /usr/bin/python3 tests/browser/run_experiment.py DIR [--participants P01 P02] [--screenshots OUT]

Run it with Debian's python3 (/usr/bin/python3), which sees Debian's python3-selenium; it needs
the packages chromium, chromium-driver and python3-selenium. Standard library + selenium only.

The first participant's session runs from disk (file://), the second's from a static web
server on 127.0.0.1 (the study folder served by Python's http.server), so both ways the
experiment is meant to run are exercised, the preload of the videos included. The second is
addressed by its bare number (?participant=2 for P02), as an experimenter may type it.

The responder, deterministic: on each text page it presses the button; on the background form
(the study's session.background, from participants/index.js) it picks an option per question;
on a story's video it
checks there are no controls and nothing to respond with, then seeks to the end; on the
questions it answers some right and some wrong (a rule of participant, trial and question);
on a rating page it checks the video has controls and that Continue waits for the video's end,
seeks to the end, and gives each panel a different rating; there it also checks that the
video, the question, every panel's row and Continue are inside the window without scrolling
(run with --width 1366 --height 768 for the laptop screen the page is laid out for), that the
question is the study's rating prompt, and that the page's labels are at least 16 px. The saved file
(signstim-results_PNN.csv, captured through Chromium's download folder) must then have:
  - exactly the documented header and CRLF line ends, one row per trial, phase 1 then phase 2;
  - the stories, versions, sentences and panel codes of the participant's schedule, in order,
    as both participants/PNN/PNN_conditions.csv and PNN_timeline_variables.json give them;
  - each answer's letter and correct flag (against the answer key of the timeline file) and
    n_correct; each panel's rating, and the ratings unmapped to versions through the panel
    code's letters (P V A U = point vector animator uninflected), computed here independently;
  - empty cells where a column does not apply, and a whole-number rt_ms;
  - the background answers on every row (bg_hearing, bg_asl_age, bg_asl_school, bg_daily_use);
and the browser log no SEVERE entry (console errors, failed loads). Finally the checker is
shown to fail: copies of the first saved CSV with a swapped rating, a flipped correct flag,
two trials swapped, a row missing, an emptied background answer and a renamed column must each
be rejected.

Exit status: 0 pass; 1 a check failed (each failure listed); 77 Chromium, its driver or
selenium is missing or the browser cannot start (a skip for CTest, never a pass); 2 bad usage.
The whole run is bounded by --timeout (default 300 s).
"""

import argparse
import functools
import http.server
import json
import os
import pathlib
import sys
import tempfile
import threading
import time

sys.dont_write_bytecode = True  # importing the modules beside it leaves no __pycache__ in the source tree
sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))
from chromium_session import (INSTALL_HINT, SKIP, chromium_options, find_prerequisites,  # noqa: E402
                              kill_tree, start_failure)
from experiment_responder import Failure, Session  # noqa: E402
from experiment_results import Expected, check_results, mutations, read_conditions  # noqa: E402


def loud(lines):
    bar = "=" * 78
    print(bar, file=sys.stderr)
    for line in lines:
        print("run_experiment: " + line, file=sys.stderr)
    print(bar, file=sys.stderr)


class QuietHandler(http.server.SimpleHTTPRequestHandler):
    def log_message(self, *arguments):
        pass


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("folder", help="the study's output folder (holding experiment/)")
    parser.add_argument("--participants", nargs=2, metavar="ID", help="the two participants (default: the first two)")
    parser.add_argument("--screenshots", metavar="DIR", help="save a phase-1 question page and a phase-2 rating page here")
    parser.add_argument("--results", metavar="DIR", help="keep the saved CSV files here")
    parser.add_argument("--width", type=int, default=1280)
    parser.add_argument("--height", type=int, default=900)
    parser.add_argument("--session-timeout", type=float, default=120.0, help="seconds per session")
    parser.add_argument("--timeout", type=float, default=300.0, help="seconds for the whole run")
    parser.add_argument("--chromium", help="the browser (default: $CHROMIUM, else chromium on PATH)")
    parser.add_argument("--chromedriver", help="the driver (default: $CHROMEDRIVER, else chromedriver on PATH)")
    args = parser.parse_args()

    chromium, chromedriver, missing = find_prerequisites(args)
    if missing:
        loud(["SKIPPED: the experiment's browser run needs what is missing here:"]
             + [f"  - {m}" for m in missing] + [f"install with: {INSTALL_HINT}"])
        return SKIP

    folder = pathlib.Path(args.folder).resolve()
    page = folder / "experiment" / "index.html"
    if not page.is_file():
        print(f"run_experiment: FAIL: {page} does not exist (render the study with --experiment jspsych)", file=sys.stderr)
        return 1
    study = json.loads((folder / "manifest.json").read_text(encoding="utf-8"))["study"]
    ids = args.participants or [p["id"] for p in study["participants"][:2]]
    if len(ids) < 2:
        print("run_experiment: FAIL: the study has fewer than two participants", file=sys.stderr)
        return 1
    all_ids = [p["id"] for p in study["participants"]]
    # The session settings as the page gets them: participants/index.js sets window.signstimStudy.
    index_js = (folder / "experiment" / "participants" / "index.js").read_text(encoding="utf-8")
    settings = json.loads(index_js[index_js.index("=") + 1:].strip().rstrip(";"))

    downloads = tempfile.mkdtemp(prefix="signstim-experiment-downloads-")
    server = http.server.ThreadingHTTPServer(("127.0.0.1", 0), functools.partial(QuietHandler, directory=str(folder)))
    threading.Thread(target=server.serve_forever, daemon=True).start()

    from selenium import webdriver
    from selenium.common.exceptions import WebDriverException
    from selenium.webdriver.chrome.service import Service

    options = chromium_options(chromium, args.width, args.height)
    options.add_experimental_option("prefs", {"download.default_directory": downloads,
                                              "download.prompt_for_download": False})
    service = Service(chromedriver)

    def give_up():
        print(f"run_experiment: FAIL: the run did not finish within {args.timeout:g} s (--timeout); killing the browser",
              file=sys.stderr, flush=True)
        if service.process is not None:
            kill_tree(service.process.pid)
        os._exit(1)

    watchdog = threading.Timer(args.timeout, give_up)
    watchdog.daemon = True
    watchdog.start()
    try:
        driver = webdriver.Chrome(service=service, options=options)
    except WebDriverException as error:
        if service.process is not None:
            kill_tree(service.process.pid)
        loud(start_failure(chromium, chromedriver, error))
        return SKIP

    failures, notes, saved = [], [], {}
    try:
        driver.set_page_load_timeout(60)
        driver.set_script_timeout(60)
        driver.execute_cdp_cmd("Browser.setDownloadBehavior", {"behavior": "allow", "downloadPath": downloads})
        session = Session(driver, args, args.screenshots)
        # Without ?participant= the page lists the participants, each a link to their session.
        driver.get(page.as_uri())
        listed = driver.execute_script(
            "return Array.from(document.querySelectorAll('ul.signstim-participants a'), (a) => [a.innerText, a.href])")
        if [name for name, _ in listed] != all_ids or not all(href.endswith(f"?participant={name}") for name, href in listed):
            failures.append(f"the page without ?participant= lists {listed}, expected links to {all_ids}")
        session.screenshot("participants.png")
        for entry in driver.get_log("browser"):
            if entry.get("level") == "SEVERE":
                failures.append(f"participant list: console error: {entry.get('message', '').strip()}")
        for number, participant in enumerate(ids):
            base = folder / "participants" / participant
            expected = Expected(
                participant,
                json.loads((base / f"{participant}_timeline_variables.json").read_text(encoding="utf-8")),
                read_conditions(base / f"{participant}_conditions.csv"))
            expected.asked = list(settings.get("background", []))
            expected.prompt = settings.get("rating_prompt", "")
            over_http = number == 1
            # The second is addressed as the experimenter may type it: the bare number (P02 -> 2).
            given = (participant.lstrip("P").lstrip("0") or "0") if over_http else participant
            url = (f"http://127.0.0.1:{server.server_address[1]}/experiment/index.html?participant={given}"
                   if over_http else page.as_uri() + f"?participant={participant}")
            start = time.monotonic()
            try:
                data = session.run(url, all_ids.index(participant), expected, downloads, over_http)
            except Failure as failure:
                failures.append(str(failure))
                continue
            finally:
                for entry in driver.get_log("browser"):
                    if entry.get("level") == "SEVERE":
                        failures.append(f"{participant}: console error: {entry.get('message', '').strip()}")
            if args.results:
                pathlib.Path(args.results).mkdir(parents=True, exist_ok=True)
                (pathlib.Path(args.results) / f"signstim-results_{participant}.csv").write_bytes(data)
            problems = check_results(data, expected)
            failures += problems
            saved[participant] = (data.decode("utf-8"), expected)
            if expected.layout:
                boxes = expected.layout["parts"]
                notes.append(f"{participant}: rating page at {expected.layout['viewport'][0]}x"
                             f"{expected.layout['viewport'][1]}: video bottom {boxes['video'][3]:.0f} px, Continue bottom "
                             f"{boxes['continue'][3]:.0f} px; smallest label {min(expected.layout['fonts'].values()):g} px")
            notes.append(f"{participant} ({'http://127.0.0.1' if over_http else 'file://'}, ?participant={given}): "
                         f"{len(expected.answers)} stories, {len(expected.ratings)} rating pages in "
                         f"{time.monotonic() - start:.1f} s; signstim-results_{participant}.csv "
                         f"{'matches' if not problems else 'does NOT match'} the schedule and the responses")
        # The checker must be able to fail: each mutation of a good CSV is rejected.
        if saved and not failures:
            participant, (text, expected) = next(iter(saved.items()))
            for what, bad in mutations(text).items():
                if not check_results(bad, expected):
                    failures.append(f"the checker accepted a CSV with {what}: it cannot catch that mistake")
                else:
                    notes.append(f"negative check: a CSV with {what} is rejected")
    except WebDriverException as error:
        failures.append(f"the browser failed: {str(error).strip().splitlines()[0] if str(error).strip() else error}")
    finally:
        try:
            driver.quit()
        except WebDriverException:
            pass
        server.shutdown()
        watchdog.cancel()
        for leftover in pathlib.Path(downloads).iterdir():
            leftover.unlink()
        os.rmdir(downloads)

    for note in notes:
        print(f"run_experiment: {note}")
    if failures:
        print(f"run_experiment: FAIL: {len(failures)} problem(s) in {folder}/experiment:", file=sys.stderr)
        for failure in failures:
            print(f"  - {failure}", file=sys.stderr)
        return 1
    print(f"run_experiment: PASS: {folder}/experiment")
    return 0


if __name__ == "__main__":
    sys.exit(main())
