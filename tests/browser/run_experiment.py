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
import html
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
from experiment_results import BACKGROUND_COLUMN, LETTERS, Expected, check_results, mutations, read_conditions  # noqa: E402

MIN_LABEL_PX = 16  # issue 24 §6: the rating page's labels were 12 px

# What is on screen now, as plain JSON. The responder marks the element it acted on
# (data-responder), so a page is handled once even while jsPsych has not replaced it yet.
STATE_JS = r"""
const q = (s) => document.querySelector(s);
const mark = (e) => e ? e.dataset.responder === 'done' : false;
const saveAgain = q('#signstim-save-again');
if (saveAgain) return {page: 'end'};
const story = q('#jspsych-video-keyboard-response-stimulus');
if (story) return {page: 'story', seen: mark(story), controls: story.controls,
  controlsAttribute: story.hasAttribute('controls'), loop: story.loop, paused: story.paused,
  readyState: story.readyState, duration: story.duration, src: story.currentSrc,
  inputs: document.querySelectorAll('#jspsych-content button, #jspsych-content input').length};
const questions = q('#jspsych-survey-multi-choice_form');
if (questions) return {page: 'questions', seen: mark(questions),
  prompts: Array.from(document.querySelectorAll('.jspsych-survey-multi-choice-question'), (e) => ({
    name: e.dataset.name, prompt: e.querySelector('p.jspsych-survey-multi-choice-text').innerText.trim(),
    options: Array.from(e.querySelectorAll('input[type=radio]'), (i) => i.value)}))};
const choices = q('#signstim-question-choices');
if (choices) { const v = q('#signstim-question-video'); const next = q('#jspsych-survey-html-form-next');
  const text = q('.signstim-question-text');
  return {page: 'asl-question', seen: mark(q('#jspsych-survey-html-form')), hasVideo: !!v,
    controls: v ? v.controls : null, readyState: v ? v.readyState : 0, src: v ? v.currentSrc : '',
    ended: v ? v.ended : false, choicesHidden: choices.hidden, nextDisabled: next ? next.disabled : null,
    prompt: text ? text.innerText.trim() : null,
    options: Array.from(choices.querySelectorAll('label'), (l) => l.innerText.trim())}; }
const background = q('fieldset.signstim-background');
if (background) return {page: 'background', seen: mark(q('#jspsych-survey-html-form')),
  questions: Array.from(document.querySelectorAll('fieldset.signstim-background'), (f) => ({
    legend: f.querySelector('legend').innerText.trim(),
    options: Array.from(f.querySelectorAll('input[type=radio]'), (i) => [i.name, i.value, i.id])}))};
const ratings = q('#jspsych-survey-html-form');
if (ratings) { const v = q('#signstim-rating-video'); const next = q('#jspsych-survey-html-form-next');
  return {page: 'ratings', seen: mark(ratings), controls: v ? v.controls : null, readyState: v ? v.readyState : 0,
    duration: v ? v.duration : 0, src: v ? v.currentSrc : '', ended: v ? v.ended : false,
    nextDisabled: next ? next.disabled : null,
    panels: Array.from(document.querySelectorAll('table.signstim-ratings tbody th'), (e) => e.innerText.trim()),
    values: Array.from(document.querySelectorAll('table.signstim-ratings thead th'), (e) => e.innerText.trim())}; }
const buttons = q('#jspsych-html-button-response-btngroup');
if (buttons) return {page: 'text', seen: mark(buttons), text: q('#jspsych-html-button-response-stimulus').innerText,
  instructionVideo: !!q('#signstim-instruction-video')};
if (q('#jspsych-loading-progress-bar-container')) return {page: 'loading'};
const start = q('#signstim-start');
if (start) return {page: 'start', text: start.innerText};
return {page: 'other', text: document.body ? document.body.innerText.slice(0, 300) : ''};
"""

MARK_JS = "arguments[0].dataset.responder = 'done';"
# Where the rating page's parts are, at the top of the page as it opens (no scrolling): the video,
# every panel's row, the question and Continue, each a rectangle; the viewport; the smallest font
# among the page's labels.
LAYOUT_JS = r"""
window.scrollTo(0, 0);
const rect = (e) => { const r = e.getBoundingClientRect(); return [r.left, r.top, r.right, r.bottom]; };
const parts = {video: document.querySelector('#signstim-rating-video'),
  question: document.querySelector('.signstim-rating-question'),
  continue: document.querySelector('#jspsych-survey-html-form-next')};
document.querySelectorAll('table.signstim-ratings tbody tr').forEach((row, i) => { parts['row ' + (i + 1)] = row; });
const out = {viewport: [window.innerWidth, window.innerHeight], scrollY: window.scrollY, parts: {}, fonts: {}};
for (const [name, e] of Object.entries(parts)) out.parts[name] = e ? rect(e) : null;
const labelled = document.querySelectorAll(
  '.signstim-rating-question, table.signstim-ratings th, table.signstim-ratings .signstim-anchor, .signstim-step, ' +
  '.signstim-note, #jspsych-progressbar-container span');
for (const e of labelled) {
  const size = parseFloat(getComputedStyle(e).fontSize);
  const name = e.className || e.tagName.toLowerCase();
  out.fonts[name] = Math.min(out.fonts[name] || 1e9, size);
}
return out;
"""
SEEK_END_JS = r"""
const v = arguments[0];
v.playbackRate = 16;
v.currentTime = Math.max(0, v.duration - 0.05);
"""


class Failure(Exception):
    pass


def loud(lines):
    bar = "=" * 78
    print(bar, file=sys.stderr)
    for line in lines:
        print("run_experiment: " + line, file=sys.stderr)
    print(bar, file=sys.stderr)


def unescape(text):
    return html.unescape(text)


def answer_plan(person, trial, question, correct, options):
    """Right unless (person + trial + question) % 3 == 0: then a wrong option, deterministically."""
    if (person + trial + question) % 3 != 0:
        return correct
    return (correct + 1 + trial % (options - 1)) % options


def rating_plan(person, trial, panels, minimum, maximum):
    span = maximum - minimum + 1
    step = 3 if span >= 10 else 1  # 0, 3, 6, 9: distinct on a 10-point scale
    base = person * 5 + trial * 3
    return [minimum + (base + k * step) % span for k in range(panels)]


class Session:
    def __init__(self, driver, args, screenshots):
        self.driver = driver
        self.args = args
        self.screenshots = screenshots
        self.shots = set()  # the pages already pictured: each kind once

    def state(self):
        return self.driver.execute_script(STATE_JS)

    def element(self, selector):
        from selenium.webdriver.common.by import By
        return self.driver.find_element(By.CSS_SELECTOR, selector)

    def screenshot(self, name):
        if not self.screenshots or name in self.shots:
            return
        self.shots.add(name)
        path = pathlib.Path(self.screenshots) / name
        path.parent.mkdir(parents=True, exist_ok=True)
        metrics = self.driver.execute_cdp_cmd("Page.getLayoutMetrics", {})
        size = metrics.get("cssContentSize") or metrics["contentSize"]
        import base64
        shot = self.driver.execute_cdp_cmd("Page.captureScreenshot", {
            "format": "png", "captureBeyondViewport": True,
            "clip": {"x": 0, "y": 0, "width": int(size["width"]), "height": min(int(size["height"]), 4000), "scale": 1}})
        path.write_bytes(base64.b64decode(shot["data"]))

    def run(self, url, person, expected, downloads, over_http):
        self.pending = []  # issue 24: the answers given so far to the current story's signed questions
        vars_ = expected.timeline
        phase1, phase2 = vars_["phase1"], vars_["phase2"]
        story_index = 0
        rating_index = 0
        texts = 0
        deadline = time.monotonic() + self.args.session_timeout
        self.driver.get(url)
        while True:
            if time.monotonic() > deadline:
                raise Failure(f"{expected.participant}: the session did not end within {self.args.session_timeout:g} s "
                              f"(last page: {self.state()})")
            state = self.state()
            page = state["page"]
            if page == "end":
                break
            if page in ("loading", "other") or state.get("seen"):
                time.sleep(0.05)
                continue
            if page == "start":
                raise Failure(f"{expected.participant}: the page shows the participant list instead of a session: "
                              f"{state['text'][:200]!r}")
            if page == "text":
                self.instruction_clip(state, texts, story_index == len(phase1) and texts > 0, expected)
                self.screenshot(["welcome.png", "phase1-ready.png"][texts] if texts < 2 else
                                "phase2-intro.png" if story_index == len(phase1) else "phase1-ready.png")
                self.driver.execute_script(MARK_JS, self.element("#jspsych-html-button-response-btngroup"))
                self.element("#jspsych-html-button-response-btngroup button").click()
                texts += 1
            elif page == "story":
                self.story(state, phase1, story_index, expected, over_http)
            elif page == "questions":
                self.questions(state, phase1, story_index, person, expected)
                story_index += 1
            elif page == "asl-question":
                if self.asl_question(state, phase1, story_index, person, expected, over_http):
                    story_index += 1
            elif page == "background":
                self.background(state, person, expected)
            elif page == "ratings":
                self.ratings(state, phase2, rating_index, person, expected, over_http)
                rating_index += 1
        self.screenshot("end.png")
        if story_index != len(phase1) or rating_index != len(phase2):
            raise Failure(f"{expected.participant}: the session showed {story_index} stories and {rating_index} rating "
                          f"pages; the schedule has {len(phase1)} and {len(phase2)}")
        expected_texts = 1 + len(phase1) + (1 if phase2 else 0)
        if texts != expected_texts:
            raise Failure(f"{expected.participant}: {texts} text pages, expected {expected_texts} "
                          "(welcome, one before each story, one before part 2)")
        return self.wait_for_download(downloads, f"signstim-results_{expected.participant}.csv")

    def story(self, state, phase1, index, expected, over_http):
        who = f"{expected.participant} story {index + 1}"
        if index >= len(phase1):
            raise Failure(f"{who}: more stories than the schedule's {len(phase1)}")
        if state["controls"] or state["controlsAttribute"] or state["loop"]:
            raise Failure(f"{who}: the story video has controls or loops: it must play once, without replay")
        if state["inputs"]:
            raise Failure(f"{who}: {state['inputs']} button(s)/input(s) while the story plays: no response before its end")
        # Autoplay, then to the end at once (the test has no time to watch).
        video = self.element("#jspsych-video-keyboard-response-stimulus")
        end = time.monotonic() + 20
        while True:
            state = self.state()
            if state["page"] != "story":
                raise Failure(f"{who}: the video trial ended before the video was played to its end")
            if state["readyState"] >= 1 and not state["paused"]:
                break  # the source is chosen (currentSrc is set asynchronously) and it plays
            if time.monotonic() > end:
                raise Failure(f"{who}: the video did not start playing by itself within 20 s "
                              f"(readyState {state['readyState']}, paused {state['paused']})")
            time.sleep(0.05)
        self.check_source(who, state["src"], phase1[index]["video"][0], over_http)
        self.screenshot("phase1-story.png")
        self.driver.execute_script(MARK_JS, video)
        self.driver.execute_script(SEEK_END_JS, video)

    def check_source(self, who, src, clip, over_http):
        if over_http:
            if not src.startswith("blob:"):
                raise Failure(f"{who}: over HTTP the video should play from the preloaded copy (blob:), not {src}")
        elif not src.endswith("/" + clip):
            raise Failure(f"{who}: plays {src}, the schedule says {clip}")

    def questions(self, state, phase1, index, person, expected):
        who = f"{expected.participant} story {index + 1} questions"
        trial = phase1[index]
        if self.study_setting("questions") in ("asl", "both") and any("video" in q for q in trial["questions"]):
            raise Failure(f"{who}: the questions are shown in English only; the study asks them in ASL")
        questions = trial["questions"]
        shown = state["prompts"]
        if len(shown) != len(questions):
            raise Failure(f"{who}: {len(shown)} questions shown, the story has {len(questions)}")
        chosen = []
        for q, (question, page) in enumerate(zip(questions, shown)):
            if page["prompt"] != unescape(question["prompt"]):
                raise Failure(f"{who}: question {q + 1} reads {page['prompt']!r}, expected {unescape(question['prompt'])!r}")
            if page["options"] != [unescape(o) for o in question["options"]]:
                raise Failure(f"{who}: question {q + 1} offers {page['options']}, expected the story's choices in order")
            pick = answer_plan(person, index, q, question["correct"], len(question["options"]))
            self.element(f"#jspsych-survey-multi-choice-response-{q}-{pick}").click()
            chosen.append(pick)
        expected.answers.append(chosen)
        self.screenshot("phase1-questions.png")
        self.driver.execute_script(MARK_JS, self.element("#jspsych-survey-multi-choice_form"))
        self.element("#jspsych-survey-multi-choice-next").click()

    def study_setting(self, name):
        return self.driver.execute_script(f"return (window.signstimStudy || {{}})[{json.dumps(name)}]")

    def instruction_clip(self, state, texts, part2, expected):
        """Issue 24: the welcome and part-2 pages play their instruction clip when the study signs them."""
        instructions = self.study_setting("instructions") or {}
        page = "welcome" if texts == 0 else "part2" if part2 else None
        signed = instructions.get("show") in ("asl", "both")
        if page and (instructions.get("pages") or {}).get(page, {}).get("video") and signed:
            if not state.get("instructionVideo"):
                raise Failure(f"{expected.participant}: the {page} page has no instruction clip; the study signs its "
                              "instructions")
        elif state.get("instructionVideo") and page is None:
            raise Failure(f"{expected.participant}: an instruction clip on a page that has none")

    def asl_question(self, state, phase1, index, person, expected, over_http):
        """Issue 24: one signed question: its clip plays before the choices appear. True after the story's last."""
        q = len(self.pending)
        who = f"{expected.participant} story {index + 1} question {q + 1} (ASL)"
        if index >= len(phase1):
            raise Failure(f"{who}: more stories than the schedule's {len(phase1)}")
        questions = phase1[index]["questions"]
        if q >= len(questions):
            raise Failure(f"{who}: more question pages than the story's {len(questions)} questions")
        question = questions[q]
        shown = self.study_setting("questions")
        if "video" in question:
            if not state["hasVideo"] or state["controls"] is not True:
                raise Failure(f"{who}: the question's clip is missing or has no controls (replay allowed)")
            if not state["ended"] and (not state["choicesHidden"] or state["nextDisabled"] is not True):
                raise Failure(f"{who}: the choices or Continue are available before the question clip has ended")
        expected_prompt = unescape(question["prompt"]) if shown in ("both", "english") else None
        if state["prompt"] != expected_prompt:
            raise Failure(f"{who}: the English question reads {state['prompt']!r}, expected {expected_prompt!r} "
                          f"(questions shown: {shown})")
        want = [f"{LETTERS[i]} {unescape(o)}" for i, o in enumerate(question["options"])]
        if state["options"] != want:
            raise Failure(f"{who}: choices {state['options']}, expected {want}")
        if "video" in question:
            video = self.element("#signstim-question-video")
            end = time.monotonic() + 20
            while (state := self.state()).get("readyState", 0) < 1:
                if time.monotonic() > end:
                    raise Failure(f"{who}: the question clip's metadata did not load within 20 s")
                time.sleep(0.05)
            self.check_source(who, state["src"], question["video"][0], over_http)
            self.screenshot("phase1-asl-question-playing.png")
            self.driver.execute_script(SEEK_END_JS, video)  # the test skips the watching
            end = time.monotonic() + 20
            while (state := self.state()).get("choicesHidden") or state.get("nextDisabled"):
                if time.monotonic() > end:
                    raise Failure(f"{who}: the choices did not appear 20 s after the clip was sought to its end")
                time.sleep(0.05)
        pick = answer_plan(person, index, q, question["correct"], len(question["options"]))
        self.element(f"#signstim-choice-{pick}").click()
        self.pending.append(pick)
        self.screenshot("phase1-asl-question.png")
        if self.screenshots and "phase1-asl-question-window.png" not in self.shots:
            self.shots.add("phase1-asl-question-window.png")
            self.driver.get_screenshot_as_file(str(pathlib.Path(self.screenshots) / "phase1-asl-question-window.png"))
        self.driver.execute_script(MARK_JS, self.element("#jspsych-survey-html-form"))
        self.element("#jspsych-survey-html-form-next").click()
        if len(self.pending) < len(questions):
            return False
        expected.answers.append(self.pending)
        self.pending = []
        return True

    def background(self, state, person, expected):
        who = f"{expected.participant} background"
        if expected.background is not None:
            raise Failure(f"{who}: the background form came twice")
        asked = [q["options"][0][0] for q in state["questions"]]
        if asked != expected.asked:
            raise Failure(f"{who}: asks {asked}, the study's session.background is {expected.asked}")
        expected.background = {}
        for k, question in enumerate(state["questions"]):
            name, value, input_id = question["options"][(person + k) % len(question["options"])]
            self.element("#" + input_id).click()
            expected.background[BACKGROUND_COLUMN[name]] = value
        self.screenshot("background.png")
        self.driver.execute_script(MARK_JS, self.element("#jspsych-survey-html-form"))
        self.element("#jspsych-survey-html-form-next").click()

    def check_layout(self, who):
        """The rating page fits the window: video, question, every panel's row and Continue in view
        without scrolling; its labels at least MIN_LABEL_PX."""
        layout = self.driver.execute_script(LAYOUT_JS)
        width, height = layout["viewport"]
        for name, box in layout["parts"].items():
            if box is None:
                raise Failure(f"{who}: the rating page has no {name}")
            left, top, right, bottom = box
            if top < 0 or left < 0 or bottom > height + 0.5 or right > width + 0.5:
                raise Failure(f"{who}: the {name} is out of view at {width}x{height} "
                              f"(at x {left:.0f}-{right:.0f}, y {top:.0f}-{bottom:.0f}): it must fit without scrolling")
        for name, size in layout["fonts"].items():
            if size < MIN_LABEL_PX:
                raise Failure(f"{who}: text '{name}' is {size:g} px; labels must be at least {MIN_LABEL_PX} px")
        return layout

    def ratings(self, state, phase2, index, person, expected, over_http):
        who = f"{expected.participant} rating {index + 1}"
        if index >= len(phase2):
            raise Failure(f"{who}: more rating pages than the schedule's {len(phase2)}")
        trial = phase2[index]
        panels = sorted(trial["panels"])
        likert = expected.timeline["likert"]
        if state["controls"] is not True:
            raise Failure(f"{who}: the side-by-side video must have controls (replay allowed)")
        if state["panels"] != [f"Panel {p}" for p in panels]:
            raise Failure(f"{who}: rows {state['panels']}, expected {['Panel ' + p for p in panels]}")
        scale = [str(v) for v in range(likert["minimum"], likert["maximum"] + 1)]
        if [v.split()[0] for v in state["values"][1:]] != scale:
            raise Failure(f"{who}: scale {state['values'][1:]}, expected {scale}")
        if state["nextDisabled"] is not True and not state["ended"]:
            raise Failure(f"{who}: Continue is enabled before the video has played to its end")
        given = rating_plan(person, index, len(panels), likert["minimum"], likert["maximum"])
        for panel, value in zip(panels, given):
            self.element(f"#signstim-rate-{panel}-{value}").click()
        expected.ratings.append(given)
        video = self.element("#signstim-rating-video")
        end = time.monotonic() + 20
        while (state := self.state()).get("readyState", 0) < 1:
            if time.monotonic() > end:
                raise Failure(f"{who}: the video's metadata did not load within 20 s")
            time.sleep(0.05)
        self.check_source(who, state["src"], trial["video"][0], over_http)
        self.driver.execute_script(SEEK_END_JS, video)
        end = time.monotonic() + 20
        while self.state().get("nextDisabled"):
            if time.monotonic() > end:
                raise Failure(f"{who}: Continue stayed disabled 20 s after the video was sought to its end")
            time.sleep(0.05)
        layout = self.check_layout(who)
        if index == 0:
            expected.layout = layout
        prompt = self.driver.execute_script("return document.querySelector('.signstim-rating-question').innerText")
        if expected.prompt.replace("{verb}", trial["verb"]).replace("{minimum}", str(likert["minimum"])).replace(
                "{maximum}", str(likert["maximum"])) != prompt:
            raise Failure(f"{who}: the question reads {prompt!r}; the study's prompt is {expected.prompt!r}")
        self.screenshot("phase2-ratings.png")
        if self.screenshots and index == 0 and "phase2-ratings-window.png" not in self.shots:
            self.shots.add("phase2-ratings-window.png")
            self.driver.get_screenshot_as_file(str(pathlib.Path(self.screenshots) / "phase2-ratings-window.png"))
        self.driver.execute_script(MARK_JS, self.element("#jspsych-survey-html-form"))
        self.element("#jspsych-survey-html-form-next").click()

    def wait_for_download(self, downloads, name):
        path = pathlib.Path(downloads) / name
        end = time.monotonic() + 20
        while not path.is_file() or any(pathlib.Path(downloads).glob("*.crdownload")):
            if time.monotonic() > end:
                present = sorted(p.name for p in pathlib.Path(downloads).iterdir())
                raise Failure(f"the session ended but {name} was not saved within 20 s (downloads: {present})")
            time.sleep(0.05)
        return path.read_bytes()


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
