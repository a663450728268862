#!/usr/bin/python3
"""Checks a study's review page (DIR/index.html) in headless Chromium, opened from file://.

  /usr/bin/python3 tests/browser/check_review_page.py DIR [--screenshot FILE.png [--full-page]]

Run it with Debian's python3 (/usr/bin/python3), which sees Debian's python3-selenium; it needs
the packages chromium, chromium-driver and python3-selenium. Standard library + selenium only.

Checks:
  (a) the browser log has no SEVERE entry (console errors, uncaught exceptions, failed loads),
      read after the page loads and again at the end;
  (b) every src, poster and relative href names a file or folder that exists under DIR (and
      none leaves DIR), every in-page link (#id) has its target, and nothing is fetched from
      a network (http:, https:, ftp:, //host);
  (c) every distinct video source, loaded by a detached <video preload="auto"> (in batches,
      released after each), reaches readyState >= 2 (a frame decoded) and its duration lies
      within one frame or 0.05 s, whichever is larger, of the page's data-expected-duration
      (one frame = expected duration / data-frames); every element showing the same source
      expects the same duration; the page's own preload="metadata" videos reach readyState >= 1;
      every distinct image (img src, video poster) decodes;
  and it opens every collapsed section once (as a reader would) and checks the log again.

Exit status: 0 all checks pass; 1 a check failed (each failure listed); 77 Chromium, its driver
or selenium is missing or the browser cannot start (a skip for CTest, never a pass); 2 bad
usage. The whole run is bounded by --timeout (default 180 s): past it, the browser is killed
and the run fails.
"""

import argparse
import base64
import os
import pathlib
import re
import sys
import threading
import time
import urllib.parse

sys.dont_write_bytecode = True  # importing chromium_session leaves no __pycache__ in the source tree
sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))
from chromium_session import (INSTALL_HINT, SKIP, chromium_options, find_prerequisites,  # noqa: E402
                              kill_tree, start_failure)

# JavaScript run in the page. Each returns plain JSON values.
COLLECT_REFERENCES_JS = r"""
const found = [];
for (const element of document.querySelectorAll('[src], [poster], [href]')) {
  for (const name of ['src', 'poster', 'href']) {
    const value = element.getAttribute(name);
    if (value !== null) found.push([element.tagName.toLowerCase(), name, value]);
  }
}
const ids = Array.from(document.querySelectorAll('[id]'), e => e.id);
return [found, ids];
"""

COLLECT_VIDEOS_JS = r"""
return Array.from(document.querySelectorAll('video'), v => ({
  attribute: v.getAttribute('src') || '',
  url: v.currentSrc || v.src || '',
  expected: v.getAttribute('data-expected-duration'),
  frames: v.getAttribute('data-frames'),
  preload: v.getAttribute('preload') || '',
}));
"""

START_LOADS_JS = r"""
const urls = arguments[0];
window.__reviewCheck = window.__reviewCheck || {};
for (const url of urls) {
  const video = document.createElement('video');
  video.muted = true;
  video.preload = 'auto';
  video.src = url;
  video.load();
  window.__reviewCheck[url] = video;
}
"""

POLL_LOADS_JS = r"""
return arguments[0].map(url => {
  const v = window.__reviewCheck[url];
  return {url: url, readyState: v.readyState, duration: v.duration,
          error: v.error ? v.error.code : 0, message: v.error ? v.error.message : ''};
});
"""

RELEASE_LOADS_JS = r"""
for (const url of arguments[0]) {
  const v = window.__reviewCheck[url];
  v.removeAttribute('src');
  v.load();
  delete window.__reviewCheck[url];
}
"""

PAGE_METADATA_JS = r"""
return Array.from(document.querySelectorAll('video[preload="metadata"]'), v =>
  ({url: v.currentSrc || v.src, readyState: v.readyState, error: v.error ? v.error.code : 0}));
"""

CHECK_IMAGES_JS = r"""
const urls = arguments[0];
const done = arguments[arguments.length - 1];
Promise.all(urls.map(url => new Promise(resolve => {
  const image = new Image();
  image.onload = () => resolve([url, image.naturalWidth, image.naturalHeight]);
  image.onerror = () => resolve([url, 0, 0]);
  image.src = url;
}))).then(done);
"""

MEDIA_ERRORS = {1: "MEDIA_ERR_ABORTED", 2: "MEDIA_ERR_NETWORK", 3: "MEDIA_ERR_DECODE",
                4: "MEDIA_ERR_SRC_NOT_SUPPORTED"}


def loud(lines):
    bar = "=" * 78
    print(bar, file=sys.stderr)
    for line in lines:
        print("check_review_page: " + line, file=sys.stderr)
    print(bar, file=sys.stderr)


class Checker:
    def __init__(self, folder, args):
        self.folder = folder
        self.args = args
        self.failures = []
        self.notes = []
        self.driver = None

    def fail(self, message):
        self.failures.append(message)

    # -- browser ------------------------------------------------------------------------------

    def start(self, chromium, chromedriver):
        from selenium import webdriver
        from selenium.webdriver.chrome.service import Service

        options = chromium_options(chromium, self.args.width, self.args.height)
        self.service = Service(chromedriver)
        self.driver = webdriver.Chrome(service=self.service, options=options)
        self.driver.set_page_load_timeout(60)
        self.driver.set_script_timeout(60)

    def stop(self):
        if self.driver is not None:
            try:
                self.driver.quit()
            except Exception:  # the browser may already be gone; nothing more to do
                pass
            self.driver = None

    def browser_pid(self):
        process = getattr(getattr(self, "service", None), "process", None)
        return process.pid if process is not None else None

    def console_errors(self, when):
        for entry in self.driver.get_log("browser"):
            if entry.get("level") == "SEVERE":
                self.fail(f"console error {when}: {entry.get('message', '').strip()}")

    # -- checks -------------------------------------------------------------------------------

    def open_page(self):
        url = (self.folder / "index.html").as_uri()
        self.driver.get(url)
        deadline = time.monotonic() + 30
        while self.driver.execute_script("return document.readyState") != "complete":
            if time.monotonic() > deadline:
                self.fail("index.html did not finish loading within 30 s")
                break
            time.sleep(0.1)
        self.page_url = self.driver.execute_script("return location.href")

    def check_references(self):
        references, ids = self.driver.execute_script(COLLECT_REFERENCES_JS)
        ids = set(ids)
        root = os.path.realpath(self.folder)
        checked = set()
        for tag, attribute, value in references:
            where = f"<{tag} {attribute}=\"{value}\">"
            if value.startswith("#"):
                target = urllib.parse.unquote(value[1:])
                if target and target not in ids:
                    self.fail(f"in-page link {where}: no element has id \"{target}\"")
                continue
            scheme = re.match(r"^([A-Za-z][A-Za-z0-9+.-]*):", value)
            if value.startswith("//") or (scheme and scheme.group(1).lower() in ("http", "https", "ftp", "ws", "wss")):
                self.fail(f"network reference {where}: the page must work without a network")
                continue
            if scheme:
                if scheme.group(1).lower() not in ("data", "blob", "mailto", "javascript"):
                    self.fail(f"reference {where}: the page must use paths relative to its folder")
                continue
            path = urllib.parse.unquote(value.split("#", 1)[0].split("?", 1)[0])
            if not path or path in checked:
                continue
            checked.add(path)
            if path.startswith("/"):
                self.fail(f"absolute path {where}: the page must use paths relative to its folder")
                continue
            resolved = os.path.normpath(os.path.join(root, path))
            if resolved != root and not resolved.startswith(root + os.sep):
                self.fail(f"reference {where} leaves the output folder")
            elif not os.path.exists(resolved):
                self.fail(f"missing file {path} (referenced by {where})")
        self.notes.append(f"{len(checked)} distinct local files referenced")

    def check_videos(self):
        videos = self.driver.execute_script(COLLECT_VIDEOS_JS)
        by_url = {}
        for video in videos:
            if not video["attribute"]:
                self.fail("a <video> without a src attribute")
                continue
            expected = video["expected"]
            if expected is None or not re.fullmatch(r"\d+\.\d{3}", expected):
                self.fail(f"<video src=\"{video['attribute']}\"> has no data-expected-duration with 3 decimals "
                          f"(got {expected!r})")
                continue
            entry = by_url.setdefault(video["url"], {"attribute": video["attribute"], "expected": set(),
                                                     "frames": set()})
            entry["expected"].add(expected)
            entry["frames"].add(video["frames"])
        for url, entry in sorted(by_url.items()):
            if len(entry["expected"]) > 1:
                self.fail(f"video {entry['attribute']}: elements disagree on its duration: "
                          f"{', '.join(sorted(entry['expected']))}")

        urls = sorted(by_url)
        h264 = self.driver.execute_script(
            "return document.createElement('video').canPlayType('video/mp4; codecs=\"avc1.640028\"')")
        self.notes.append(f"{len(videos)} <video> elements, {len(urls)} distinct sources; "
                          f"canPlayType(H.264 High) = \"{h264}\"")
        batch = max(1, self.args.batch)
        for start in range(0, len(urls), batch):
            chunk = urls[start:start + batch]
            self.driver.execute_script(START_LOADS_JS, chunk)
            deadline = time.monotonic() + self.args.video_timeout
            while True:
                states = self.driver.execute_script(POLL_LOADS_JS, chunk)
                pending = [s for s in states if s["readyState"] < 2 and not s["error"]]
                if not pending or time.monotonic() > deadline:
                    break
                time.sleep(0.05)
            self.driver.execute_script(RELEASE_LOADS_JS, chunk)
            for state in states:
                self.judge_video(by_url[state["url"]], state, h264)

    def judge_video(self, entry, state, h264):
        name = urllib.parse.unquote(entry["attribute"])
        if state["error"]:
            why = MEDIA_ERRORS.get(state["error"], f"error {state['error']}")
            hint = ""
            if state["error"] in (3, 4) and not h264:
                hint = " (this Chromium reports no H.264 support: canPlayType is empty)"
            self.fail(f"video {name} does not load: {why} {state['message']}{hint}".rstrip())
            return
        if state["readyState"] < 2:
            self.fail(f"video {name} did not decode a frame within {self.args.video_timeout:g} s "
                      f"(readyState {state['readyState']})")
            return
        expected = float(next(iter(entry["expected"])))
        frames_text = next(iter(entry["frames"]))
        frames = int(frames_text) if frames_text and frames_text.isdigit() else 0
        one_frame = expected / frames if frames > 0 else 0.0
        tolerance = max(one_frame, 0.05)
        duration = state["duration"]
        if duration is None or not isinstance(duration, (int, float)) or abs(duration - expected) > tolerance:
            self.fail(f"video {name}: the browser reads {duration} s, the page expects {expected:.3f} s "
                      f"(tolerance {tolerance:.3f} s)")

    def check_page_metadata(self):
        deadline = time.monotonic() + self.args.video_timeout
        while True:
            states = self.driver.execute_script(PAGE_METADATA_JS)
            pending = [s for s in states if s["readyState"] < 1 and not s["error"]]
            if not pending or time.monotonic() > deadline:
                break
            time.sleep(0.05)
        for state in states:
            if state["error"] or state["readyState"] < 1:
                name = urllib.parse.unquote(state["url"][len(self.page_url.rsplit("/", 1)[0]) + 1:])
                self.fail(f"the page's own <video preload=\"metadata\" src=\"{name}\"> did not load its metadata "
                          f"({MEDIA_ERRORS.get(state['error'], 'no error, still loading')})")

    def check_images(self):
        urls = self.driver.execute_script(
            "return Array.from(new Set([...Array.from(document.images, i => i.src),"
            " ...Array.from(document.querySelectorAll('video[poster]'), v => v.poster)])).filter(u => u).sort()")
        results = self.driver.execute_async_script(CHECK_IMAGES_JS, urls)
        base = self.page_url.rsplit("/", 1)[0] + "/"
        for url, width, height in results:
            if width == 0 or height == 0:
                name = urllib.parse.unquote(url[len(base):] if url.startswith(base) else url)
                self.fail(f"image {name} does not decode")
        self.notes.append(f"{len(urls)} distinct images decoded")

    def open_every_section(self):
        closed = self.driver.execute_script(
            "const closed = Array.from(document.querySelectorAll('details:not([open])'));"
            "closed.forEach(d => { d.open = true; }); return closed.length")
        time.sleep(0.5)  # toggle events are queued; let them run
        self.console_errors("after opening every section")
        self.driver.execute_script(
            "document.querySelectorAll('details[open]').forEach(d => { d.open = false; }); window.scrollTo(0, 0)")
        self.notes.append(f"opened and closed {closed} collapsed sections")

    def screenshot(self, path):
        if self.args.open:
            self.driver.execute_script(
                "Array.from(document.querySelectorAll('details:not([open])')).slice(0, arguments[0])"
                ".forEach(d => { d.open = true; }); window.scrollTo(0, 0)", self.args.open)
        # Shown thumbnails load now (a full-page picture reaches below the window, where lazy
        # images would wait for a scroll), and arrive before the picture is taken.
        self.driver.execute_script(
            "document.querySelectorAll('img[loading=\"lazy\"]').forEach(i => {"
            " if (i.getClientRects().length) i.loading = 'eager'; })")
        deadline = time.monotonic() + 10
        while time.monotonic() < deadline:
            if self.driver.execute_script(
                    "return Array.from(document.images).every(i => i.complete || i.getClientRects().length === 0)"):
                break
            time.sleep(0.1)
        time.sleep(0.3)
        path = pathlib.Path(path)
        path.parent.mkdir(parents=True, exist_ok=True)
        if self.args.full_page:
            metrics = self.driver.execute_cdp_cmd("Page.getLayoutMetrics", {})
            size = metrics.get("cssContentSize") or metrics["contentSize"]
            height = min(int(size["height"]), self.args.max_height)
            shot = self.driver.execute_cdp_cmd("Page.captureScreenshot", {
                "format": "png", "captureBeyondViewport": True,
                "clip": {"x": 0, "y": 0, "width": int(size["width"]), "height": height, "scale": 1}})
            path.write_bytes(base64.b64decode(shot["data"]))
        else:
            if not self.driver.save_screenshot(str(path)):
                self.fail(f"could not write the screenshot {path}")
                return
        self.notes.append(f"screenshot written to {path}")


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("folder", help="the study's output folder (holding index.html)")
    parser.add_argument("--screenshot", metavar="FILE.png", help="save a screenshot after the checks")
    parser.add_argument("--full-page", action="store_true", help="screenshot the whole page, not the window")
    parser.add_argument("--max-height", type=int, default=12000, help="cap of a full-page screenshot (pixels)")
    parser.add_argument("--open", type=int, default=1, metavar="N",
                        help="collapsed sections opened for the screenshot (default 1)")
    parser.add_argument("--width", type=int, default=1280)
    parser.add_argument("--height", type=int, default=900)
    parser.add_argument("--batch", type=int, default=6, help="videos loaded at once (default 6)")
    parser.add_argument("--video-timeout", type=float, default=20.0, help="seconds per batch of videos")
    parser.add_argument("--timeout", type=float, default=180.0, help="seconds for the whole run")
    parser.add_argument("--chromium", help="the browser (default: $CHROMIUM, else chromium on PATH)")
    parser.add_argument("--chromedriver", help="the driver (default: $CHROMEDRIVER, else chromedriver on PATH)")
    args = parser.parse_args()

    chromium, chromedriver, missing = find_prerequisites(args)
    if missing:
        loud(["SKIPPED: the review-page browser check needs what is missing here:"]
             + [f"  - {m}" for m in missing] + [f"install with: {INSTALL_HINT}"])
        return SKIP

    folder = pathlib.Path(args.folder).resolve()
    if not (folder / "index.html").is_file():
        print(f"check_review_page: FAIL: {folder}/index.html does not exist", file=sys.stderr)
        return 1

    checker = Checker(folder, args)

    def give_up():
        print(f"check_review_page: FAIL: the check did not finish within {args.timeout:g} s "
              "(--timeout); killing the browser", file=sys.stderr, flush=True)
        pid = checker.browser_pid()
        if pid:
            kill_tree(pid)
        os._exit(1)

    watchdog = threading.Timer(args.timeout, give_up)
    watchdog.daemon = True
    watchdog.start()

    from selenium.common.exceptions import WebDriverException
    try:
        checker.start(chromium, chromedriver)
    except WebDriverException as error:
        pid = checker.browser_pid()
        if pid:
            kill_tree(pid)
        loud(start_failure(chromium, chromedriver, error))
        return SKIP

    try:
        checker.open_page()
        checker.console_errors("while loading the page")
        checker.check_references()
        checker.check_page_metadata()
        checker.console_errors("while the page preloaded its videos")
        checker.check_videos()
        checker.console_errors("while each video was loaded")
        checker.check_images()
        checker.console_errors("while each image was loaded")
        checker.open_every_section()
        if args.screenshot:
            checker.screenshot(args.screenshot)
        checker.console_errors("at the end")
    except WebDriverException as error:
        checker.fail(f"the browser failed: {str(error).strip().splitlines()[0] if str(error).strip() else error}")
    finally:
        checker.stop()
        watchdog.cancel()

    for note in checker.notes:
        print(f"check_review_page: {note}")
    if checker.failures:
        print(f"check_review_page: FAIL: {len(checker.failures)} problem(s) in {folder}/index.html:", file=sys.stderr)
        for failure in checker.failures:
            print(f"  - {failure}", file=sys.stderr)
        return 1
    print(f"check_review_page: PASS: {folder}/index.html")
    return 0


if __name__ == "__main__":
    sys.exit(main())
