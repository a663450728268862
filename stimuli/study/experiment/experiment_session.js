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

