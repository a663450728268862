// signstim: the review page's script (stimuli/study/review_page.hpp), embedded at build time
// (cmake/Embed.cmake) and written inline into the page. Opens every collapsed section while
// printing (and closes them again); pauses a section's videos when it is closed; lets one video
// play at a time; expands or collapses all participants; opens the section a link points into.
(function () {
  'use strict';
  var openedForPrint = [];
  window.addEventListener('beforeprint', function () {
    document.querySelectorAll('details:not([open])').forEach(function (d) { d.open = true; openedForPrint.push(d); });
  });
  window.addEventListener('afterprint', function () {
    openedForPrint.forEach(function (d) { d.open = false; });
    openedForPrint = [];
  });
  document.addEventListener('toggle', function (event) {
    var d = event.target;
    if (d.tagName === 'DETAILS' && !d.open) d.querySelectorAll('video').forEach(function (v) { v.pause(); });
  }, true);
  document.addEventListener('play', function (event) {
    document.querySelectorAll('video').forEach(function (v) { if (v !== event.target) v.pause(); });
  }, true);
  document.querySelectorAll('[data-participants]').forEach(function (button) {
    button.addEventListener('click', function () {
      var open = button.getAttribute('data-participants') === 'open';
      document.querySelectorAll('details.participant').forEach(function (d) { d.open = open; });
    });
  });
  // A link to a trial or participant inside a collapsed section opens it.
  function openTarget() {
    var id = decodeURIComponent(location.hash.slice(1));
    var target = id && document.getElementById(id);
    for (var node = target; node; node = node.parentElement) if (node.tagName === 'DETAILS') node.open = true;
    if (target) target.scrollIntoView();
  }
  window.addEventListener('hashchange', openTarget);
  openTarget();
})();
