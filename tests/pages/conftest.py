"""What the page tests share: the tools (from CTest's environment), Debian's headless Chromium, and
reading the state a page reports in its #plascap-status element."""
import contextlib
import html.parser
import json
import os
import shutil
import subprocess
import tempfile
import time

import pytest

PLASTIC_SIM = os.environ.get("PLASCAP_PLASTIC_SIM", "plastic-sim")
SECTION_CALC = os.environ.get("PLASCAP_SECTION_CALC", "section-calc")
SOURCE_DIR = os.environ.get("PLASCAP_SOURCE_DIR", os.path.join(os.path.dirname(__file__), "..", ".."))
CHROMIUM = os.environ.get("PLASCAP_CHROMIUM") or shutil.which("chromium") or "/usr/bin/chromium"
# Where the screenshots go: docs/images to refresh the documentation's (docs/replay.md).
SHOTS = os.environ.get("PLASCAP_PAGE_SHOTS")
WINDOW = (1280, 800)


def example(name):
    return os.path.join(SOURCE_DIR, "examples", name)


class StatusReader(html.parser.HTMLParser):
    """The attributes and text of the element with id plascap-status."""

    def __init__(self):
        super().__init__()
        self.attributes, self.text, self._inside = None, "", False

    def handle_starttag(self, tag, attrs):
        attrs = dict(attrs)
        if attrs.get("id") == "plascap-status":
            self.attributes, self._inside = attrs, True

    def handle_endtag(self, tag):
        self._inside = False

    def handle_data(self, data):
        if self._inside:
            self.text += data


class Browser:
    """Debian's Chromium, headless, with its own empty profile and no network of its own."""

    def __init__(self, profile):
        if not os.path.exists(CHROMIUM):
            pytest.fail(f"chromium not found at {CHROMIUM}: install Debian's chromium (scripts/install-deps.sh)")
        self.profile = profile

    def run(self, url, *args, timeout=600, window=WINDOW):
        command = [CHROMIUM, "--headless", "--no-sandbox", "--disable-gpu", "--use-angle=swiftshader",
                   "--enable-unsafe-swiftshader", "--disable-quic", "--no-first-run", "--disable-background-networking",
                   "--disable-component-update", "--disable-sync", "--hide-scrollbars",
                   f"--user-data-dir={self.profile}", f"--window-size={window[0]},{window[1]}", *args, url]
        result = subprocess.run(command, capture_output=True, text=True, timeout=timeout)
        assert result.returncode == 0, f"chromium failed ({result.returncode}): {result.stderr[-2000:]}"
        return result.stdout

    def state(self, path, fragment="", budget_ms=120000):
        """The page's #plascap-status after it ran for `budget_ms` of virtual time: (data-*, text, DOM)."""
        dom = self.run(f"file://{os.path.abspath(path)}{fragment}", f"--virtual-time-budget={budget_ms}", "--dump-dom")
        reader = StatusReader()
        reader.feed(dom)
        assert reader.attributes is not None, "the page has no #plascap-status element"
        data = {k[5:]: v for k, v in reader.attributes.items() if k.startswith("data-")}
        return data, reader.text, dom

    def screenshot(self, path, png, fragment="", budget_ms=120000, window=WINDOW):
        self.run(f"file://{os.path.abspath(path)}{fragment}", f"--virtual-time-budget={budget_ms}", f"--screenshot={png}",
                 window=window)
        assert os.path.getsize(png) > 0
        if SHOTS:
            os.makedirs(SHOTS, exist_ok=True)
            shutil.copy(png, os.path.join(SHOTS, os.path.basename(png)))
        return png


@contextlib.contextmanager
def chromium_profile(prefix):
    """A profile directory, removed afterwards. Chromium's child processes can outlive the browser
    for a moment and still write into it, so the removal is retried for a few seconds."""
    profile = tempfile.mkdtemp(prefix=prefix)
    try:
        yield profile
    finally:
        for _ in range(20):
            shutil.rmtree(profile, ignore_errors=True)
            if not os.path.exists(profile):
                break
            time.sleep(0.25)


@pytest.fixture(scope="session")
def browser():
    with chromium_profile("plascap-chromium-") as profile:
        yield Browser(profile)


def run_tool(*command, check=True):
    result = subprocess.run(list(command), capture_output=True, text=True, timeout=900)
    if check:
        assert result.returncode == 0, f"{command} failed: {result.stderr}"
    return result


def replay(tmp, scene, engine="bullet", *extra):
    """plastic-sim SCENE --html: the page's path and the run's --json summary."""
    page = os.path.join(tmp, os.path.splitext(os.path.basename(scene))[0] + f"-{engine}.html")
    result = run_tool(PLASTIC_SIM, scene, "--engine", engine, "--html", page, "--json", "--quiet", *extra)
    return page, json.loads(result.stdout)


class LiveBrowser:
    """Chromium in real time, driven over the DevTools protocol on a pipe (--remote-debugging-pipe:
    NUL-separated JSON on file descriptors 3 and 4), for what virtual time cannot measure: the
    frame rate a page reaches when the browser also composites what it draws."""

    def __init__(self, profile):
        if not os.path.exists(CHROMIUM):
            pytest.fail(f"chromium not found at {CHROMIUM}: install Debian's chromium (scripts/install-deps.sh)")
        to_browser, self._to_browser = os.pipe()
        self._from_browser, from_browser = os.pipe()

        def descriptors():
            os.dup2(to_browser, 3)
            os.dup2(from_browser, 4)

        self.process = subprocess.Popen(
            [CHROMIUM, "--headless", "--no-sandbox", "--disable-gpu", "--use-angle=swiftshader", "--enable-unsafe-swiftshader",
             "--disable-quic", "--no-first-run", "--disable-background-networking", "--disable-component-update",
             "--disable-sync", "--hide-scrollbars", f"--user-data-dir={profile}", f"--window-size={WINDOW[0]},{WINDOW[1]}",
             "--remote-debugging-pipe", "about:blank"],
            pass_fds=(3, 4), preexec_fn=descriptors, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        os.close(to_browser)
        os.close(from_browser)
        self._buffer, self._id = b"", 0

    def _call(self, method, params=None, session=None):
        self._id += 1
        message = {"id": self._id, "method": method, "params": params or {}}
        if session:
            message["sessionId"] = session
        os.write(self._to_browser, json.dumps(message).encode() + b"\0")
        while True:
            while b"\0" in self._buffer:
                text, self._buffer = self._buffer.split(b"\0", 1)
                reply = json.loads(text)
                if reply.get("id") == self._id:
                    assert "error" not in reply, reply
                    return reply["result"]
            chunk = os.read(self._from_browser, 1 << 16)
            assert chunk, "chromium closed its DevTools pipe"
            self._buffer += chunk

    def state_when(self, path, fragment, states=("done", "error"), timeout_s=600):
        """Opens the page and returns its #plascap-status data once data-state is one of `states`."""
        target = self._call("Target.createTarget", {"url": f"file://{os.path.abspath(path)}{fragment}"})["targetId"]
        session = self._call("Target.attachToTarget", {"targetId": target, "flatten": True})["sessionId"]
        expression = "JSON.stringify(Object.assign({}, document.getElementById('plascap-status').dataset))"
        start = time.monotonic()
        while time.monotonic() - start < timeout_s:
            value = self._call("Runtime.evaluate", {"expression": expression, "returnByValue": True}, session)["result"].get("value")
            if value and json.loads(value).get("state") in states:
                self._call("Target.closeTarget", {"targetId": target})
                return json.loads(value)
            time.sleep(0.5)
        pytest.fail(f"{path}: no state {states} after {timeout_s} s")

    def click(self, path, fragment, x, y, expression):
        """Opens the page in a 1280 × 800 viewport (as the screenshots), clicks at (x, y) once it is
        ready, and returns `expression` evaluated after the click."""
        target = self._call("Target.createTarget", {"url": "about:blank"})["targetId"]
        session = self._call("Target.attachToTarget", {"targetId": target, "flatten": True})["sessionId"]
        self._call("Emulation.setDeviceMetricsOverride",
                   {"width": WINDOW[0], "height": WINDOW[1], "deviceScaleFactor": 1, "mobile": False}, session)
        self._call("Page.navigate", {"url": f"file://{os.path.abspath(path)}{fragment}"}, session)
        ready = "document.getElementById('plascap-status') && document.getElementById('plascap-status').dataset.state"
        for _ in range(120):
            state = self._call("Runtime.evaluate", {"expression": ready, "returnByValue": True}, session)["result"].get("value")
            if state in ("ready", "done", "error"):
                break
            time.sleep(0.25)
        time.sleep(0.5)  # the first frame drawn
        for kind in ("mousePressed", "mouseReleased"):
            self._call("Input.dispatchMouseEvent", {"type": kind, "x": x, "y": y, "button": "left", "clickCount": 1}, session)
        time.sleep(0.5)
        value = self._call("Runtime.evaluate", {"expression": expression, "returnByValue": True}, session)["result"].get("value")
        self._call("Target.closeTarget", {"targetId": target})
        return value

    def close(self):
        """Asks chromium to quit, so that it stops its child processes (a kill leaves them writing
        into the profile while it is removed); kills it if it has not quit within 20 s."""
        try:
            os.write(self._to_browser, json.dumps({"id": self._id + 1, "method": "Browser.close"}).encode() + b"\0")
            self.process.wait(timeout=20)
        except (OSError, subprocess.TimeoutExpired):
            self.process.kill()
            self.process.wait()


@pytest.fixture(scope="session")
def live_browser():
    with chromium_profile("plascap-chromium-live-") as profile:
        browser = LiveBrowser(profile)
        yield browser
        browser.close()
