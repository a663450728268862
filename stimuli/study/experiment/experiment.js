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

  // ---- what the participant reads --------------------------------------------------------------

  function welcomeHtml(vars) {
    const stories = vars.phase1.length;
    const videos = vars.phase2.length;
    const panels = videos > 0 ? Object.keys(vars.phase2[0].panels).length : 0;
    let html =
      "<h1>Welcome</h1>" + instructionHtml("welcome") +
      "<p>In this study you watch short videos of an animated signer using American Sign Language (ASL).</p>";
    html +=
      "<h2>Part 1 · " + plural(stories, "story", "stories") + "</h2>" +
      "<p>Each story plays <strong>once</strong>: it cannot be paused or replayed, so please watch it closely. " +
      "After each story you answer a few questions about it.</p>";
    if (videos > 0) {
      html +=
        "<h2>Part 2 · " + plural(videos, "video", "videos") + "</h2>" +
        "<p>Each video shows one sentence signed " + panels + " times side by side, in panels " +
        panelList(panels) + "; the panels differ only in how the verb is signed. You may replay it as often " +
        "as you like, and you rate the quality of the verb in each panel, from " + vars.likert.minimum + " to " +
        vars.likert.maximum + ".</p>";
    }
    html += "<p class=\"signstim-note\">At the end your answers are saved as a file on this computer.</p>";
    return html;
  }

  function panelList(count) {
    const letters = LETTERS.slice(0, count).split("");
    return letters.length < 2 ? letters.join("") : letters.slice(0, -1).join(", ") + " and " + letters[letters.length - 1];
  }

  function stepHtml(part, index, count, noun) {
    return "<p class=\"signstim-step\">Part " + part + " · " + noun + " " + (index + 1) + " of " + count + "</p>";
  }

  function storyReadyHtml(index, count) {
    return stepHtml(1, index, count, "Story") +
      "<h1>Ready for the next story?</h1>" +
      "<p>The story plays once, without pause or replay. Questions about it follow.</p>";
  }

  function phase2IntroHtml(vars) {
    const panels = Object.keys(vars.phase2[0].panels).length;
    return "<h1>Part 2</h1>" + instructionHtml("part2") +
      "<p>Each video now shows the same sentence signed " + panels + " times, side by side, in panels " +
      panelList(panels) + ". The panels play together.</p>" +
      "<p>The panels differ only in how the verb is signed. Watch the video to the end; replay it as often as " +
      "you like. Then rate the quality of the verb in each panel, from " + vars.likert.minimum +
      " (very poor) to " + vars.likert.maximum + " (very good).</p>";
  }

  function ratingPreambleHtml(url, index, count) {
    return stepHtml(2, index, count, "Video") +
      "<video id=\"signstim-rating-video\" class=\"signstim-video\" src=\"" + escapeHtml(url) + "\" " +
      "controls autoplay playsinline preload=\"auto\" disablepictureinpicture " +
      "controlslist=\"nodownload noremoteplayback\"></video>";
  }

  function ratingFormHtml(panels, likert, prompt) {
    const values = [];
    for (let v = likert.minimum; v <= likert.maximum; ++v) values.push(v);
    let html =
      "<p class=\"signstim-rating-question\">" + escapeHtml(prompt) + "</p>" +
      "<table class=\"signstim-ratings\"><thead><tr><th scope=\"col\"><span class=\"signstim-hidden\">Panel</span></th>";
    values.forEach((v, i) => {
      const anchor = i === 0 ? "very poor" : i === values.length - 1 ? "very good" : "";
      html += "<th scope=\"col\">" + v + (anchor ? "<span class=\"signstim-anchor\">" + anchor + "</span>" : "") + "</th>";
    });
    html += "</tr></thead><tbody>";
    for (const panel of panels) {
      html += "<tr><th scope=\"row\">Panel " + panel + "</th>";
      for (const v of values) {
        const id = "signstim-rate-" + panel + "-" + v;
        html += "<td><label for=\"" + id + "\"><input type=\"radio\" id=\"" + id + "\" name=\"" + panel +
          "\" value=\"" + v + "\" required aria-label=\"Panel " + panel + ": " + v + "\"></label></td>";
      }
      html += "</tr>";
    }
    html += "</tbody></table>" +
      "<p class=\"signstim-note\" id=\"signstim-rating-wait\">You can continue once the video has played to the end.</p>";
    return html;
  }

  function backgroundFormHtml(ids) {
    let html = "<h1>About you</h1><p>Before the videos, a few questions about you and ASL.</p>";
    for (const id of ids) {
      const question = BACKGROUND[id];
      html += "<fieldset class=\"signstim-background\"><legend>" + escapeHtml(question.prompt) + "</legend>";
      for (const [code, label] of question.options) {
        const inputId = "signstim-bg-" + id + "-" + code;
        html += "<label for=\"" + inputId + "\"><input type=\"radio\" id=\"" + inputId + "\" name=\"" + id +
          "\" value=\"" + escapeHtml(code) + "\" required> " + escapeHtml(label) + "</label>";
      }
      html += "</fieldset>";
    }
    return html;
  }

  function videoProblemHtml(url) {
    return "<h1>This video cannot be played</h1>" +
      "<p>Please tell the experimenter. (The browser could not play <code>" + escapeHtml(url) + "</code>.)</p>";
  }

  // ---- the session ----------------------------------------------------------------------------

  // Keeps a phase-1 story to one uninterrupted viewing: no context menu (which offers controls and
  // loop), no picture-in-picture; a clip that fails to load says so instead of waiting forever.
  function guardStoryVideo(jsPsych, url) {
    const video = document.getElementById("jspsych-video-keyboard-response-stimulus");
    if (!video) return;
    video.classList.add("signstim-video");
    video.disablePictureInPicture = true;
    video.setAttribute("playsinline", "");
    video.addEventListener("contextmenu", (event) => event.preventDefault());
    watchForVideoError(jsPsych, video, url);
  }

  function watchForVideoError(jsPsych, video, url) {
    const fail = () => {
      console.error("signstim: cannot play " + url);
      jsPsych.getDisplayElement().innerHTML = videoProblemHtml(url);
    };
    video.addEventListener("error", fail);
    video.querySelectorAll("source").forEach((source) => source.addEventListener("error", fail));
  }

  // `background`: the answers of the background form by column, copied onto every row.
  let background = {};

  function emptyRow(vars, phase, trial) {
    const row = {};
    for (const column of RESULT_COLUMNS) row[column] = "";
    Object.assign(row, background);
    row.participant = vars.participant;
    row.phase = phase;
    row.trial = trial;
    return row;
  }

  function phase1Row(vars, trial, data) {
    const row = emptyRow(vars, 1, trial.trial);
    row.story_id = trial.story;
    row.version = trial.version;
    let correct = 0;
    trial.questions.forEach((question, q) => {
      const chosen = data.response_index[q];  // the plugin records each answer's 0-based option index
      const letter = chosen >= 0 ? LETTERS[chosen] : "";
      const right = chosen === question.correct ? 1 : 0;
      row["q" + (q + 1) + "_response"] = letter;
      row["q" + (q + 1) + "_correct"] = right;
      correct += right;
    });
    row.n_correct = correct;
    row.rt_ms = Math.round(data.rt);
    return row;
  }

  function phase2Row(vars, trial, panels, data) {
    const row = emptyRow(vars, 2, trial.trial);
    row.sentence_id = trial.sentence;
    row.panel_code = trial.panel_code;
    for (const panel of panels) {
      const rating = data.response[panel];
      row["rating_" + panel.toLowerCase()] = rating;
      row["rating_" + trial.panels[panel]] = rating;  // the panel's version: the ratings unmapped
    }
    row.rt_ms = Math.round(data.rt);
    return row;
  }

  function textPage(html, button) {
    return {
      type: jsPsychHtmlButtonResponse,
      stimulus: "<div class=\"signstim-text\">" + html + "</div>",
      choices: [button],
      data: { signstim_page: "text" },
    };
  }

  // Issue 24: a story's questions asked in ASL, one page each: the question clip plays (with
  // controls: replay allowed), then its choices appear; in "both" the English question is shown
  // too. The story's row is written after its last question, as one page's would be: the
  // answers' indices, and rt_ms summed over the question pages.
  function pushSignedQuestions(jsPsych, timeline, vars, rows, trial, index, stories) {
    const withText = shows((window.signstimStudy || {}).questions, "english");
    const answers = { response_index: [], rt: 0 };
    trial.questions.forEach((question, q) => {
      const url = question.video ? clipUrl(question.video[0]) : null;
      timeline.push({
        type: jsPsychSurveyHtmlForm,
        preamble: () => questionPreambleHtml(url ? (jsPsych.pluginAPI.getVideoBuffer(url) || url) : null, index, stories,
          q, trial.questions.length),
        html: questionFormHtml(question, withText, url !== null),
        button_label: "Continue",
        on_load: () => {
          const video = document.getElementById("signstim-question-video");
          if (!video) return;
          const next = document.getElementById("jspsych-survey-html-form-next");
          next.disabled = true;
          video.addEventListener("contextmenu", (event) => event.preventDefault());
          video.addEventListener("ended", () => {
            next.disabled = false;
            document.getElementById("signstim-question-choices").hidden = false;
            document.getElementById("signstim-question-wait").hidden = true;
          }, { once: true });
          watchForVideoError(jsPsych, video, url);
        },
        data: { signstim_page: "asl-question", story: trial.story, version: trial.version, trial: trial.trial,
                question: q + 1 },
        on_finish: (data) => {
          const chosen = data.response[question.name];
          answers.response_index[q] = chosen === undefined || chosen === "" ? -1 : Number(chosen);
          answers.rt += data.rt;
          if (q === trial.questions.length - 1) rows.push(phase1Row(vars, trial, answers));
        },
      });
    });
  }

  function buildTimeline(jsPsych, vars, rows) {
    const timeline = [];
    const stories = vars.phase1.length;
    const videos = vars.phase2.length;

    // Over HTTP the clips are fetched before the session starts, so none stalls mid-story.
    // From disk they are local files already, and browsers refuse the preload's requests there.
    if (location.protocol !== "file:") {
      timeline.push({
        type: jsPsychPreload,
        video: vars.phase1.concat(vars.phase2).map((trial) => clipUrl(trial.video[0]))
          .concat(vars.phase1.filter(signedQuestions).flatMap((trial) =>
            trial.questions.filter((q) => q.video).map((q) => clipUrl(q.video[0]))))
          .concat(instructionVideos()),
        message: "<p>Loading the videos…</p>",
        error_message: "<p>The videos could not be loaded. Please tell the experimenter.</p>",
        show_detailed_errors: true,
        continue_after_error: false,
      });
    }

    timeline.push(textPage(welcomeHtml(vars), "Begin"));

    const askAbout = ((window.signstimStudy || {}).background || []).filter((id) => BACKGROUND[id]);
    if (askAbout.length > 0) {
      timeline.push({
        type: jsPsychSurveyHtmlForm,
        html: backgroundFormHtml(askAbout),
        button_label: "Continue",
        data: { signstim_page: "background" },
        on_finish: (data) => {
          for (const id of askAbout) background[BACKGROUND[id].column] = data.response[id] || "";
        },
      });
    }

    vars.phase1.forEach((trial, index) => {
      const url = clipUrl(trial.video[0]);
      timeline.push(textPage(storyReadyHtml(index, stories), "Play the story"));
      timeline.push({
        type: jsPsychVideoKeyboardResponse,
        stimulus: [url],
        controls: false,
        autoplay: true,
        choices: "NO_KEYS",
        response_allowed_while_playing: false,
        trial_ends_after_video: true,
        on_load: () => guardStoryVideo(jsPsych, url),
        data: { signstim_page: "story", story: trial.story, version: trial.version, trial: trial.trial },
      });
      if (signedQuestions(trial)) {
        pushSignedQuestions(jsPsych, timeline, vars, rows, trial, index, stories);
        return;
      }
      timeline.push({
        type: jsPsychSurveyMultiChoice,
        preamble: stepHtml(1, index, stories, "Story") + "<h1>Questions about the story</h1>",
        questions: trial.questions.map((question) => ({
          prompt: question.prompt,
          options: question.options,
          required: true,
          name: question.name,
        })),
        button_label: "Continue",
        data: { signstim_page: "questions", story: trial.story, version: trial.version, trial: trial.trial },
        on_finish: (data) => rows.push(phase1Row(vars, trial, data)),
      });
    });

    if (videos > 0) {
      timeline.push(textPage(phase2IntroHtml(vars), "Start part 2"));
      vars.phase2.forEach((trial, index) => {
        const url = clipUrl(trial.video[0]);
        const panels = Object.keys(trial.panels).sort();
        timeline.push({
          type: jsPsychSurveyHtmlForm,
          // A function: evaluated when the trial starts, after the preload has made its copy.
          preamble: () => ratingPreambleHtml(jsPsych.pluginAPI.getVideoBuffer(url) || url, index, videos),
          html: ratingFormHtml(panels, vars.likert, ratingPrompt(window.signstimStudy, trial.verb, vars.likert)),
          button_label: "Continue",
          on_load: () => {
            const video = document.getElementById("signstim-rating-video");
            const next = document.getElementById("jspsych-survey-html-form-next");
            next.disabled = true;
            video.addEventListener("contextmenu", (event) => event.preventDefault());
            video.addEventListener("ended", () => {
              next.disabled = false;
              document.getElementById("signstim-rating-wait").hidden = true;
            }, { once: true });
            watchForVideoError(jsPsych, video, url);
          },
          data: { signstim_page: "ratings", sentence: trial.sentence, panel_code: trial.panel_code, trial: trial.trial },
          on_finish: (data) => rows.push(phase2Row(vars, trial, panels, data)),
        });
      });
    }
    return timeline;
  }

  // ---- saving ---------------------------------------------------------------------------------

  function csvField(value) {
    const text = value === null || value === undefined ? "" : String(value);
    return /[",\r\n]/.test(text) ? "\"" + text.replace(/"/g, "\"\"") + "\"" : text;
  }

  // RFC 4180, CRLF line ends, like the study's other CSV files.
  function resultsCsv(rows) {
    const lines = [RESULT_COLUMNS.join(",")];
    for (const row of rows) lines.push(RESULT_COLUMNS.map((column) => csvField(row[column])).join(","));
    return lines.join("\r\n") + "\r\n";
  }

  function saveFile(text, fileName) {
    const url = URL.createObjectURL(new Blob([text], { type: "text/csv;charset=utf-8" }));
    const link = document.createElement("a");
    link.href = url;
    link.download = fileName;
    link.hidden = true;
    document.body.appendChild(link);
    link.click();
    link.remove();
    setTimeout(() => URL.revokeObjectURL(url), 60000);
  }

  async function finishSession(jsPsych, vars, rows, state) {
    const fileName = "signstim-results_" + vars.participant + ".csv";
    const csv = resultsCsv(rows);
    const hooks = window.signstimHooks || {};
    const display = jsPsych.getDisplayElement();
    if (hooks.saveLocally !== false) saveFile(csv, fileName);
    let serverProblem = null;
    if (typeof hooks.onFinish === "function") {
      display.innerHTML = "<div class=\"signstim-text\"><p>Saving your answers…</p></div>";
      try {
        await hooks.onFinish({ participant: vars.participant, fileName: fileName, csv: csv, rows: rows,
                               data: jsPsych.data.get() });
      } catch (error) {
        serverProblem = error;
        console.error("signstim: signstimHooks.onFinish failed:", error);
        if (hooks.saveLocally === false) saveFile(csv, fileName);
      }
    }
    state.finished = true;
    let html = "<h1>Thank you!</h1><p>You have finished. Please tell the experimenter.</p>";
    if (serverProblem) html += "<p class=\"signstim-problem\">Your answers could not be sent to the server.</p>";
    if (hooks.saveLocally !== false || serverProblem) {
      html += "<p class=\"signstim-note\">Your answers were saved on this computer as <code>" + escapeHtml(fileName) +
        "</code> (usually in the Downloads folder). If no file appeared, save it again:</p>" +
        "<p><button type=\"button\" class=\"jspsych-btn\" id=\"signstim-save-again\">Save the answers again</button></p>";
    }
    display.innerHTML = "<div class=\"signstim-text\">" + html + "</div>";
    const again = document.getElementById("signstim-save-again");
    if (again) again.addEventListener("click", () => saveFile(csv, fileName));
  }

  // ---- start ------------------------------------------------------------------------------------

  function showChooser(study, problem) {
    const start = document.getElementById("signstim-start");
    let html = "<h1>" + escapeHtml(study.title) + "</h1>";
    if (problem) html += "<p class=\"signstim-problem\">" + escapeHtml(problem) + "</p>";
    html +=
      "<p>Each participant runs their own session, in the order of their schedule. Give each participant " +
      "this page's address followed by <code>?participant=</code> and their id, or choose one here:</p>" +
      "<ul class=\"signstim-participants\">";
    for (const id of study.participants)
      html += "<li><a href=\"?participant=" + encodeURIComponent(id) + "\">" + escapeHtml(id) + "</a></li>";
    html += "</ul>";
    start.innerHTML = html;
  }

  function loadParticipant(id) {
    return new Promise((resolve, reject) => {
      const script = document.createElement("script");
      script.src = "participants/" + encodeURIComponent(id) + ".js";
      script.onload = () => resolve(window.signstimTimeline);
      script.onerror = () => reject(new Error("participants/" + id + ".js could not be loaded"));
      document.head.appendChild(script);
    });
  }

  function runSession(vars) {
    document.getElementById("signstim-start").remove();
    document.title = vars.study.title;
    const rows = [];
    const state = { finished: false };
    // Leaving mid-session loses the answers so far: the browser asks first.
    window.addEventListener("beforeunload", (event) => {
      if (state.finished) return;
      event.preventDefault();
      event.returnValue = "";
    });
    const jsPsych = initJsPsych({
      show_progress_bar: true,
      message_progress_bar: "Progress",
      on_finish: () => finishSession(jsPsych, vars, rows, state),
    });
    jsPsych.data.addProperties({ participant: vars.participant, group: vars.group,
                                 design_hash: vars.study.design_hash });
    jsPsych.run(buildTimeline(jsPsych, vars, rows));
  }

  // The study's id for what the experimenter typed: "P07" as is; "7", "P7", "p007" as the
  // participant numbered 7 (ids are "P" and a zero-padded number); null when none matches.
  function findParticipant(study, given) {
    const typed = given.trim();
    if (study.participants.indexOf(typed) >= 0) return typed;
    const number = /^[Pp]?\s*0*(\d+)$/.exec(typed);
    if (!number) return null;
    for (const id of study.participants) {
      const own = /^P0*(\d+)$/.exec(id);
      if (own && own[1] === number[1]) return id;
    }
    return null;
  }

  function main() {
    const study = window.signstimStudy;
    const given = new URLSearchParams(location.search).get("participant");
    if (given === null || given === "") {
      showChooser(study, "");
      return;
    }
    const id = findParticipant(study, given);
    if (id === null) {
      showChooser(study, "This study has no participant \u201c" + given + "\u201d.");
      return;
    }
    loadParticipant(id).then((vars) => {
      if (!vars || vars.participant !== id) throw new Error("participants/" + id + ".js holds another participant");
      runSession(vars);
    }).catch((error) => {
      console.error("signstim: " + error.message);
      showChooser(study, "The session of " + id + " could not be started: " + error.message + ".");
    });
  }

  main();
})();
