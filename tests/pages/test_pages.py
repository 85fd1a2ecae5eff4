"""plastic-sim --html and section-calc --html in Debian's headless Chromium: the pages report their
own state into the DOM (read through --dump-dom after a virtual time budget), and their screenshots'
pixels are checked (docs/replay.md)."""
import json
import os
import re

import pytest
from PIL import Image

from conftest import SECTION_CALC, PLASTIC_SIM, example, replay, run_tool

BROKEN = (255, 0, 255)  # the replay's colour of a broken joint (replay.js)
CURVE = (0x2B, 0x6C, 0xB0)  # the section page's exact-surface curve (section.js)


def broken_in(summary):
    return sum(1 for j in summary["joints"].values() if j["broken"])


def box_of(state, key):
    x, y, w, h = (int(v) for v in state[key].split(","))
    return x, y, x + w, y + h


def pixels_near(image, box, colour, tolerance=40, leave_out=None):
    """Pixels of `image` inside `box` (but not in `leave_out`) within `tolerance` (per channel) of `colour`."""
    rgb = image.convert("RGB")
    if leave_out:
        rgb.paste((0, 0, 0), leave_out)
    region = rgb.crop(box)
    return sum(1 for p in region.getdata() if all(abs(p[c] - colour[c]) <= tolerance for c in range(3)))


def assert_not_blank(image, box):
    region = image.convert("RGB").crop(box)
    colours = region.getcolors(maxcolors=1 << 20)
    assert colours is not None and len(colours) > 30, "the view is (nearly) one colour"
    background = max(colours)[1]
    drawn = sum(n for n, c in colours if max(abs(c[i] - background[i]) for i in range(3)) > 24)
    assert drawn > 0.002 * region.width * region.height, f"only {drawn} pixels differ from the background"


@pytest.mark.parametrize("engine", ["bullet", "ode"])
def test_collapse_replay_draws_every_frame_and_shows_the_joints_that_broke(browser, tmp_path, engine):
    page, summary = replay(str(tmp_path), example("scenes/collapsing-stack.json"), engine)
    state, _, _ = browser.state(page, "#autoplay")
    assert state["state"] == "done", state
    assert state["errors"] == "0", state.get("lasterror")
    frames = int(state["frames"])
    assert frames == min(summary["steps"] + 1, 600)  # the start, then evenly spaced steps; default budget
    assert int(state["frames-drawn"]) >= frames
    assert int(state["broken-end"]) == broken_in(summary) > 0
    assert int(state["joints"]) == len(summary["joints"])
    assert float(state["fps"]) > 0


def test_replay_screenshots_show_broken_joints_in_the_collapse_and_none_when_elastic(browser, tmp_path):
    collapse, summary = replay(str(tmp_path), example("scenes/collapsing-stack.json"))
    assert broken_in(summary) > 0
    elastic, elastic_summary = replay(str(tmp_path), example("scenes/cantilever-bending.json"))
    assert broken_in(elastic_summary) == 0
    for page, png, expect_broken in ((collapse, "replay-collapsing-stack.png", True), (elastic, "replay-cantilever.png", False)):
        state, _, _ = browser.state(page, "#autoplay")
        shot = browser.screenshot(page, str(tmp_path / png), "#autoplay")  # the last frame
        image = Image.open(shot)
        # The view as the page laid it out; the screenshot's window may be taller than --dump-dom's
        # (the view grows down to the controls, 40 px above the bottom).
        left, top, right, _ = box_of(state, "view")
        box = (left, top, right, image.height - 45)
        assert_not_blank(image, box)
        broken_pixels = pixels_near(image, box, BROKEN, leave_out=box_of(state, "legend"))  # its swatch is that colour
        if expect_broken:
            assert broken_pixels >= 3 * 20, f"{png}: {broken_pixels} pixels of the broken joints' colour"
        else:
            assert broken_pixels == 0, f"{png}: {broken_pixels} pixels of the broken joints' colour"


def test_structure_replay_draws_members_as_their_extruded_sections(browser, tmp_path):
    page, summary = replay(str(tmp_path), example("scenes/simply-supported-beam.json"), "bullet", "--html-frames", "40")
    with open(page, encoding="utf-8") as f:
        text = f.read()
    data = json.loads(re.search(r'<script type="application/json" id="plascap-data">(.*?)</script>', text, re.S).group(1))
    assert len(data["outlines"]) == 1  # one IPE 200 for every segment
    ipe = data["outlines"][0][0]["outer"]
    depth = max(p[1] for p in ipe) - min(p[1] for p in ipe)
    width = max(p[0] for p in ipe) - min(p[0] for p in ipe)
    assert depth == pytest.approx(0.200, abs=1e-9) and width == pytest.approx(0.100, abs=1e-9)  # h and b of IPE 200
    assert all(b["outline"] == 0 for b in data["bodies"])
    assert data["frames"]["count"] == 40
    state, _, _ = browser.state(page, "#autoplay")
    assert state["state"] == "done" and state["errors"] == "0", state
    assert int(state["broken-end"]) == broken_in(summary) == 0


def test_the_page_is_self_contained(tmp_path):
    page, _ = replay(str(tmp_path), example("scenes/charpy-impact.json"), "bullet", "--html-frames", "20")
    with open(page, encoding="utf-8") as f:
        text = f.read()
    assert not re.search(r"<script[^>]*\ssrc=", text) and "<link" not in text and "<iframe" not in text
    assert "THREE.OrbitControls" in text and "Chart.js v3" in text


def tampered(page, tmp_path, name, change):
    with open(page, encoding="utf-8") as f:
        text = f.read()
    start = text.index('id="plascap-data">') + len('id="plascap-data">')
    end = text.index("</script>", start)
    bad = tmp_path / name
    bad.write_text(text[:start] + change(text[start:end]) + text[end:], encoding="utf-8")
    return str(bad)


def test_a_replay_it_cannot_read_says_why_instead_of_a_blank_canvas(browser, tmp_path):
    page, _ = replay(str(tmp_path), example("scenes/collapsing-stack.json"), "bullet", "--html-frames", "30")

    def cut_poses(data):
        d = json.loads(data)
        d["frames"]["poses"]["data"] = d["frames"]["poses"]["data"][:-40]
        return json.dumps(d)

    def other_version(data):
        d = json.loads(data)
        d["version"] = 7
        return json.dumps(d)

    cases = [
        ("not-json.html", lambda data: data[: len(data) // 2], "not valid JSON"),
        ("poses-cut.html", cut_poses, "the body poses"),
        ("version.html", other_version, "version 7"),
        ("csv.html", lambda data: "time,a.x\n0,1\n", "not valid JSON"),
    ]
    for name, change, words in cases:
        state, text, dom = browser.state(tampered(page, tmp_path, name, change), budget_ms=5000)
        assert state["state"] == "error", (name, state)
        assert words in state["message"], (name, state["message"])
        assert text.startswith("This replay cannot be shown: ") and words in text, (name, text)
        assert "<canvas" not in dom, name
    shot = Image.open(browser.screenshot(tampered(page, tmp_path, "shot.html", cut_poses), str(tmp_path / "error.png"),
                                         budget_ms=5000))
    assert pixels_near(shot, (0, 0, shot.width, shot.height), (0xC5, 0x30, 0x30), tolerance=10) > 200  # the message's red frame


def test_html_options_are_checked_before_the_run(tmp_path):
    scene = example("scenes/charpy-impact.json")
    cases = [
        ([scene, "--html-frames", "50"], "--html-frames goes with --html"),
        ([scene, "--html", str(tmp_path / "a.html"), "--html-frames", "1"], "--html-frames 1: expected 2 to 100000"),
        ([scene, "--html", str(tmp_path / "no" / "such" / "dir.html")], "cannot be written"),
    ]
    for args, words in cases:
        result = run_tool(PLASTIC_SIM, *args, "--quiet", check=False)
        assert result.returncode == 2, (args, result.stderr)
        assert words in result.stderr and result.stderr.count("\n") == 1, result.stderr


def shown_value(dom, key):
    """The capacity row of `key` in the section page: its value in SI units."""
    match = re.search(r'<td>([-0-9.e+]+) ([kMG]?)(N·m|N)</td><td class="name note">' + re.escape(key) + "</td>", dom)
    assert match, f"no row {key}"
    return float(match.group(1)) * {"": 1, "k": 1e3, "M": 1e6, "G": 1e9}[match.group(2)]


def test_section_page_shows_the_drawing_the_capacities_and_the_interaction_diagrams(browser, tmp_path):
    page = str(tmp_path / "section-ipe300.html")
    result = run_tool(SECTION_CALC, "--shape", "IPE 300", "--material", "S355", "--elastic", "--html", page, "--json")
    report = json.loads(result.stdout)
    state, _, dom = browser.state(page, budget_ms=10000)
    assert state["state"] == "ready" and state["errors"] == "0", state
    assert state["charts"] == "3" and int(state["curve-points"]) == 3 * 72
    assert int(state["rows"]) >= 18
    assert "<svg" in dom
    # IPE 300: Wpl,y = 628.4 cm³ (EN 10365; ArcelorMittal's sales programme), Mx = Wpl·fy with fy = 355 MPa;
    # the page shows three significant digits.
    assert shown_value(dom, "Mx") == pytest.approx(628.4e-6 * 355e6, rel=5e-3)
    assert shown_value(dom, "N") == pytest.approx(report["N"], rel=5e-3)
    shot = Image.open(browser.screenshot(page, str(tmp_path / "section-ipe300.png"), budget_ms=10000, window=(1280, 1100)))
    assert_not_blank(shot, (0, 0, shot.width, shot.height))
    assert pixels_near(shot, (0, 0, shot.width, shot.height), CURVE, tolerance=20) > 300  # the three curves


def test_section_page_on_the_cubature_route_says_where_the_diagrams_are(browser, tmp_path):
    page = str(tmp_path / "rect.html")
    run_tool(SECTION_CALC, "--rect", "0.1", "0.2", "--fy", "355e6", "--method", "cubature", "--html", page)
    state, _, dom = browser.state(page, budget_ms=10000)
    assert state["state"] == "ready" and state["charts"] == "0", state
    assert "run without --method cubature" in dom
    # N = fy·b·h = 355e6 · 0.1 · 0.2 (paper eq. 2.10)
    assert shown_value(dom, "N") == pytest.approx(355e6 * 0.02, rel=5e-3)


def test_a_section_page_it_cannot_read_says_why(browser, tmp_path):
    page = str(tmp_path / "rect.html")
    run_tool(SECTION_CALC, "--rect", "0.1", "0.2", "--fy", "355e6", "--html", page)
    bad = tampered(page, tmp_path, "bad-section.html", lambda data: json.dumps({"format": "plascap-replay", "version": 1}))
    state, text, _ = browser.state(bad, budget_ms=5000)
    assert state["state"] == "error"
    assert text.startswith("This section report cannot be shown: its data is not a section-calc report"), text


def test_a_click_on_a_broken_joint_shows_its_dofs_capacities_and_energy(browser, live_browser, tmp_path):
    page, summary = replay(str(tmp_path), example("scenes/collapsing-stack.json"), "bullet", "--html-frames", "50")
    shot = Image.open(browser.screenshot(page, str(tmp_path / "end.png"), "#end", budget_ms=10000)).convert("RGB")
    state, _, _ = browser.state(page, "#end", budget_ms=10000)
    lx0, ly0, lx1, ly1 = box_of(state, "legend")
    left, top, right, _ = box_of(state, "view")
    magenta = [(x, y) for x in range(left, right) for y in range(top, shot.height - 45)
               if shot.getpixel((x, y)) == BROKEN and not (lx0 <= x < lx1 and ly0 <= y < ly1)]
    assert magenta, "no broken joint drawn"
    x, y = magenta[len(magenta) // 2]
    info = live_browser.click(page, "#end", x, y, "JSON.stringify([document.getElementById('plascap-status').dataset.selected, "
                                                 "document.getElementById('info').innerText])")
    name, text = json.loads(info)
    assert summary["joints"][name]["broken"], name
    assert "now\tbroken" in text
    assert "Mx\tplastic\t2.50 kN·m\t2.50 kN·m\trigid-plastic" in text  # the scene's 2,500 N·m, both ways
    shown_kj = float(re.search(r"dissipated\t([0-9.]+) kJ", text).group(1))
    assert shown_kj * 1e3 == pytest.approx(summary["joints"][name]["dissipated"], rel=5e-3)  # three digits
