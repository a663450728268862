// signstim: a study's jsPsych 8 experiment (docs/experiment.md). `signstim study
// --experiment jspsych` writes this file unchanged into every study's experiment/ folder; what
// differs between studies and participants is in participants/*.js.
//
// index.html?participant=P07 (or ?participant=7, P7) runs P07's session, in the order of their
// schedule:
//   background: the study's background questions (hearing status, age of ASL acquisition,
//            schooling, daily use; study file "session.background"), saved on every row;
//   phase 1: each story's video plays once (no controls, no pause, no replay), then its
//            multiple-choice questions: on one page in English, or (issue 24, study file
//            "session.questions": "asl" or "both") one page per question, its signed clip
//            playing first and the choices shown when it has ended;
//   phase 2: each side-by-side video (controls: replay allowed) with a rating of every panel,
//            asked in the study's words (study file "session.ratingPrompt"; by default the
//            paper's: the quality of the verb).
// At the end the answers are saved as signstim-results_P07.csv (one row per trial) on the
// participant's machine, and handed to window.signstimHooks.onFinish when a page defines it
// (a server: JATOS, Pavlovia, your own; docs/experiment.md). Without ?participant= the page
// lists the study's participants.
//
// A classic script, no modules and no fetch(): browsers refuse both from file://, and the
// folder must run from disk as well as from any static web server. The participant's timeline
// arrives as participants/P07.js (a <script> setting window.signstimTimeline).
(function () {
  "use strict";

  // The saved data's columns, in this order (docs/experiment.md). The analysis reads them by name.
  const RESULT_COLUMNS = [
    "participant", "phase", "trial", "story_id", "sentence_id", "version", "panel_code",
    "q1_response", "q1_correct", "q2_response", "q2_correct", "q3_response", "q3_correct",
    "q4_response", "q4_correct", "n_correct",
    "rating_a", "rating_b", "rating_c", "rating_d",
    "rating_point", "rating_vector", "rating_animator", "rating_uninflected",
    "rt_ms",
    "bg_hearing", "bg_asl_age", "bg_asl_school", "bg_daily_use",
  ];
  const LETTERS = "ABCDEFGHIJKLMNOPQRSTUVWXYZ";
  // The timeline files name clips relative to the study folder; this page is one level down.
  const STUDY_FOLDER = "../";
  // Huenerfauth, Lu & Kacorri 2015 §4: 1-to-10 ratings of "the quality of the verb". Used when
  // participants/index.js (from an older signstim) carries no prompt.
  const DEFAULT_RATING_PROMPT = "How would you rate the quality of the verb {verb} in each panel?";

  // The background questions a study may ask (study file "session.background", docs/experiment.md):
  // what Kacorri & Huenerfauth (2015) advise reporting of participants of ASL animation studies,
  // asked as facts about a person's life rather than as a self-rating of fluency. Each answer is
  // saved under `column` as the option's short code.
  const BACKGROUND = {
    hearing: {
      column: "bg_hearing",
      prompt: "Which describes you?",
      options: [["deaf", "Deaf or deaf"], ["hard-of-hearing", "Hard of hearing"], ["hearing", "Hearing"],
                ["no-answer", "I prefer not to say"]],
    },
    aslAge: {
      column: "bg_asl_age",
      prompt: "How old were you when you began using ASL?",
      options: [["0-2", "I have used ASL since I was a baby"], ["3-7", "Age 3 to 7"], ["8-12", "Age 8 to 12"],
                ["13-17", "Age 13 to 17"], ["18+", "Age 18 or older"]],
    },
    aslSchool: {
      column: "bg_asl_school",
      prompt: "Did you go to a school where classes were taught mainly in ASL?",
      options: [["yes", "Yes"], ["part", "For part of my schooling"], ["no", "No"]],
    },
    dailyUse: {
      column: "bg_daily_use",
      prompt: "Do you use ASL every day (at home, at work, or with family, a partner or friends)?",
      options: [["daily", "Yes, every day"], ["weekly", "Often, but not every day"], ["rarely", "Rarely"]],
    },
  };

  function escapeHtml(text) {
    return String(text).replace(/[&<>"']/g, (c) =>
      ({ "&": "&amp;", "<": "&lt;", ">": "&gt;", '"': "&quot;", "'": "&#39;" })[c]);
  }

  function clipUrl(path) {
    return STUDY_FOLDER + path.split("/").map(encodeURIComponent).join("/");
  }

  // The study's phase-2 question with {verb}, {minimum} and {maximum} filled in.
  function ratingPrompt(study, verb, likert) {
    const template = study && typeof study.rating_prompt === "string" && study.rating_prompt !== ""
      ? study.rating_prompt : DEFAULT_RATING_PROMPT;
    return template.replace(/\{(verb|minimum|maximum)\}/g, (match, name) =>
      name === "verb" ? verb : String(likert[name]));
  }

  // Issue 24: whether the study shows the questions or instructions signed ("asl") or as text
  // ("english"); "both" shows both. Without the choice (an older study): English only.
  function shows(choice, what) {
    const c = choice || "english";
    return c === "both" || c === what;
  }

  function paragraphs(text) {
    return String(text).split(/\n\s*\n/).map((p) => "<p class=\"signstim-instruction-text\">" + escapeHtml(p.trim()) +
      "</p>").join("");
  }

  // An instruction page's signed clip (replay allowed) and its English text, as the study shows them.
  function instructionHtml(name) {
    const instructions = (window.signstimStudy || {}).instructions || {};
    const page = (instructions.pages || {})[name];
    if (!page) return "";
    let html = "";
    if (page.video && shows(instructions.show, "asl")) {
      html += "<video id=\"signstim-instruction-video\" class=\"signstim-video signstim-instruction-video\" src=\"" +
        escapeHtml(clipUrl(page.video)) + "\" controls autoplay playsinline preload=\"auto\" disablepictureinpicture " +
        "controlslist=\"nodownload noremoteplayback\"></video>";
    }
    if (page.text && shows(instructions.show, "english")) html += paragraphs(page.text);
    return html;
  }

  function instructionVideos() {
    const instructions = (window.signstimStudy || {}).instructions || {};
    if (!shows(instructions.show, "asl")) return [];
    return Object.values(instructions.pages || {}).filter((page) => page.video).map((page) => clipUrl(page.video));
  }

  // The signed questions of a story trial, when the study shows them: their clips' URLs.
  function signedQuestions(trial) {
    return shows((window.signstimStudy || {}).questions, "asl") && trial.questions.some((q) => q.video);
  }

  function questionPreambleHtml(url, index, count, q, questions) {
    return stepHtml(1, index, count, "Story") +
      "<h1>Question " + (q + 1) + " of " + questions + "</h1>" +
      (url ? "<video id=\"signstim-question-video\" class=\"signstim-video\" src=\"" + escapeHtml(url) + "\" " +
        "controls autoplay playsinline preload=\"auto\" disablepictureinpicture " +
        "controlslist=\"nodownload noremoteplayback\"></video>" : "");
  }

  // The choices, hidden until the question clip has ended (shown at once without a clip). The
  // prompt and options arrive HTML-escaped from the timeline file.
  function questionFormHtml(question, withText, hasVideo) {
    let html = withText ? "<p class=\"signstim-question-text\">" + question.prompt + "</p>" : "";
    html += "<fieldset class=\"signstim-choices\" id=\"signstim-question-choices\"" + (hasVideo ? " hidden" : "") + ">" +
      "<legend class=\"signstim-hidden\">Choices</legend>";
    question.options.forEach((option, i) => {
      const id = "signstim-choice-" + i;
      html += "<label for=\"" + id + "\"><input type=\"radio\" id=\"" + id + "\" name=\"" + question.name + "\" value=\"" +
        i + "\" required> <span class=\"signstim-letter\">" + LETTERS[i] + "</span> " + option + "</label>";
    });
    html += "</fieldset>";
    if (hasVideo) {
      html += "<p class=\"signstim-note\" id=\"signstim-question-wait\">The choices appear when the question has been " +
        "signed. You may replay it.</p>";
    }
    return html;
  }

  function plural(count, one, many) {
    return count + " " + (count === 1 ? one : many);
  }

