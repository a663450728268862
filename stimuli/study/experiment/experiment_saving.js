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
