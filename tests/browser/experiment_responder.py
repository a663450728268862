"""The scripted participant of tests/browser/run_experiment.py: reads what is on screen in the
jsPsych experiment (STATE_JS), acts on each page once (text, background form, story video, its
questions in English or signed, rating page), checks what run_experiment.py's docstring lists
about each page, and returns the CSV the session saved. Standard library + selenium only.
"""

import html
import json
import pathlib
import time

from experiment_results import BACKGROUND_COLUMN, LETTERS

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
