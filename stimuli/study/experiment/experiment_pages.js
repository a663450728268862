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

