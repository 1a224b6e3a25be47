"""The HTML replay page in a real browser: headless Chromium driven by Playwright, from file://.

Needs the Debian package ``chromium`` (/usr/bin/chromium) and ``pip install playwright`` (the dev
extra; never ``playwright install``). Without them the test is skipped, except under CI=true,
where it fails.
"""

from __future__ import annotations

import os
from pathlib import Path

import pytest
from replay_helpers import EMPTY, SNAKE, play, write_jsonl

from glyphbench_rl.replay.html import write_html
from glyphbench_rl.replay.index import EpisodeIndex

CHROMIUM = Path("/usr/bin/chromium")


def _require_browser():
    missing = []
    if not CHROMIUM.exists():
        missing.append(f"{CHROMIUM} (apt-get install chromium)")
    try:
        from playwright.sync_api import sync_playwright
    except ImportError:
        sync_playwright = None
        missing.append("the playwright package (pip install playwright)")
    if missing:
        reason = "browser test needs " + " and ".join(missing)
        if os.environ.get("CI") == "true":
            pytest.fail(reason)
        pytest.skip(reason)
    return sync_playwright


@pytest.fixture(scope="module")
def page_file(tmp_path_factory):
    out = tmp_path_factory.mktemp("browser") / "replay.html"
    path = write_jsonl(out.with_name("episodes.jsonl"), play((SNAKE, EMPTY), (1, 2)))
    write_html(EpisodeIndex(path), out)
    return out


def test_page_in_headless_chromium(page_file, tmp_path):
    sync_playwright = _require_browser()
    with sync_playwright() as p:
        browser = p.chromium.launch(executable_path=str(CHROMIUM), args=["--no-sandbox"])
        try:
            page = browser.new_page(viewport={"width": 1400, "height": 900})
            errors: list[str] = []
            page.on("pageerror", lambda e: errors.append(str(e)))
            page.on("console", lambda m: errors.append(m.text) if m.type == "error" else None)
            page.goto(page_file.as_uri())
            title = page.title()
            step = lambda: page.input_value("#step-input")   # noqa: E731
            assert step() == "0" and page.text_content("#ep-title") == SNAKE
            hud0 = page.text_content("#hud")

            page.keyboard.press("ArrowRight")                 # turn 2 of the script is a forfeit
            assert step() == "1" and page.text_content("#hud") != hud0
            assert "forfeit" in page.get_attribute("#board", "class")
            assert "forfeit" in page.text_content("#turn-head")
            page.keyboard.press("ArrowLeft")
            assert step() == "0" and page.text_content("#hud") == hud0

            # the injected markup shows as text and never ran
            reply = page.text_content("#reply")
            assert "<script>window.__pwned = 1;" in reply and "<img src=x onerror=" in reply
            assert page.evaluate("typeof window.__pwned") == "undefined"
            assert page.title() == title and "pwned" not in title
            assert page.evaluate("document.querySelectorAll('#reply *:not(span), img').length") == 0

            page.keyboard.press("End")
            length = page.evaluate("document.getElementById('step-input').max")
            assert step() == length and "Episode over" in page.text_content("#turn-head")
            page.keyboard.press("Home")
            assert step() == "0"

            page.select_option("#speed", "16")
            page.keyboard.press(" ")
            for _ in range(100):          # polled from here: the page's CSP forbids evaluating strings
                if int(step()) >= 3:
                    break
                page.wait_for_timeout(100)
            assert int(step()) >= 3 and "Pause" in page.text_content("#play")
            page.keyboard.press(" ")
            assert "Play" in page.text_content("#play")

            page.fill("#f-task", "minigrid")
            assert page.text_content("#count").startswith("2 of 4")
            page.click("#episodes li:not([hidden])")
            assert page.text_content("#ep-title") == EMPTY and step() == "0"
            # a small board (5x5) is drawn to the panel's size, not as a postage stamp
            board = page.locator("#board").bounding_box()
            grid = page.locator("#grid").bounding_box()
            assert grid["width"] >= 0.35 * board["width"], (grid, board)
            # the action badge names the action, with no arrow that reads as a direction
            page.keyboard.press("ArrowRight")
            page.keyboard.press("ArrowRight")
            badge = page.text_content("#turn-head .badge.action")
            assert badge.startswith("action ") and "\u2192" not in badge
            page.fill("#f-task", "")
            page.fill("#f-min", "0.01")
            assert page.text_content("#count").startswith("0 of 4")
            page.keyboard.press("n")                        # nothing matches: stays put
            assert page.text_content("#ep-title") == EMPTY

            # escaping alone keeps the markup inert: the same page with its CSP switched off
            bare = browser.new_context(bypass_csp=True).new_page()
            bare.goto(page_file.as_uri())
            bare.wait_for_timeout(200)
            assert "<script>window.__pwned = 1;" in bare.text_content("#reply")
            assert bare.evaluate("typeof window.__pwned") == "undefined" and bare.title() == title
            assert bare.evaluate("document.querySelectorAll('img').length") == 0

            shot = tmp_path / "replay.png"
            page.screenshot(path=str(shot), full_page=True)
            assert shot.stat().st_size > 1000 and shot.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
            assert errors == []
        finally:
            browser.close()
