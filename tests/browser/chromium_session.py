"""Headless Chromium for the browser tests (check_review_page.py, run_experiment.py): finding the
browser, its driver and selenium; the options both start it with; the message when it cannot
start; and killing what is left of it. Standard library + selenium only (selenium is imported
only where it is used, so a missing selenium is reported, not a traceback).
"""

import os
import shutil
import sys

SKIP = 77
INSTALL_HINT = "apt-get install chromium chromium-driver python3-selenium"


def find_program(explicit, environment, candidates):
    if explicit:
        return explicit if os.access(explicit, os.X_OK) else None
    if os.environ.get(environment):
        path = os.environ[environment]
        return path if os.access(path, os.X_OK) else None
    for candidate in candidates:
        path = candidate if os.path.isabs(candidate) else shutil.which(candidate)
        if path and os.access(path, os.X_OK):
            return path
    return None


def find_prerequisites(args):
    """(chromium, chromedriver, missing): the browser and its driver (--chromium/--chromedriver,
    else $CHROMIUM/$CHROMEDRIVER, else on PATH) and what is missing of them and selenium."""
    missing = []
    try:
        import selenium  # noqa: F401  (only whether it is there)
    except ImportError:
        missing.append(f"the Python package selenium for {sys.executable} (Debian: python3-selenium; "
                       "run this script with /usr/bin/python3)")
    chromium = find_program(args.chromium, "CHROMIUM", ["/usr/bin/chromium", "chromium", "chromium-browser", "google-chrome"])
    if not chromium:
        missing.append("the browser chromium")
    chromedriver = find_program(args.chromedriver, "CHROMEDRIVER", ["/usr/bin/chromedriver", "chromedriver"])
    if not chromedriver:
        missing.append("chromedriver (Debian: chromium-driver)")
    return chromium, chromedriver, missing


def chromium_options(chromium, width, height):
    """Headless Chromium of a width x height window that plays video without a gesture and
    keeps the browser log."""
    from selenium import webdriver

    options = webdriver.ChromeOptions()
    options.binary_location = chromium
    arguments = ["--headless=new", "--disable-gpu", "--autoplay-policy=no-user-gesture-required",
                 f"--window-size={width},{height}", "--hide-scrollbars",
                 "--disable-dev-shm-usage", "--no-first-run", "--mute-audio"]
    if os.geteuid() == 0:
        arguments.append("--no-sandbox")  # Chromium refuses to run as root with its sandbox
    for argument in arguments:
        options.add_argument(argument)
    options.set_capability("goog:loggingPrefs", {"browser": "ALL"})
    return options


def start_failure(chromium, chromedriver, error):
    """The lines of the skip when the browser cannot be started."""
    first = str(error).strip().splitlines()[0] if str(error).strip() else "(no message)"
    return [f"SKIPPED: could not start {chromium} through {chromedriver}:", "  " + first,
            "the browser and its driver must be the same version; install with: " + INSTALL_HINT]


def descendants(pid):
    """Process ids below `pid` (from /proc), deepest last."""
    children = {}
    for entry in os.listdir("/proc"):
        if not entry.isdigit():
            continue
        try:
            with open(f"/proc/{entry}/stat", "rb") as stat:
                fields = stat.read().rsplit(b")", 1)[1].split()
            children.setdefault(int(fields[1]), []).append(int(entry))
        except (OSError, IndexError, ValueError):
            continue
    found, queue = [], [pid]
    while queue:
        for child in children.get(queue.pop(0), []):
            found.append(child)
            queue.append(child)
    return found


def kill_tree(pid):
    for victim in [pid] + descendants(pid):
        try:
            os.kill(victim, 9)
        except OSError:
            pass
