"""The page in a real browser (headless Debian chromium, WebGL through SwiftShader).

One flow per test, as a user would: type a prompt, see the field table, change a
season and see the map change, refine by words, look at the 3D view, download
the zip; a bad prompt; two tabs working at once.
"""

from __future__ import annotations

import io
import zipfile
from pathlib import Path
from typing import Any

import numpy as np
import pytest
from PIL import Image

VIEW_READY = (
    "window.agrirecipeViewer && window.agrirecipeViewer.ready && "
    "location.hash.endsWith(window.agrirecipeViewer.sceneId)"
)
PROMPT = "a healthy Pink Lady apple orchard in summer next to young Nantes carrots"
TIMEOUT_MS = 60_000


@pytest.fixture
def page(browser: Any, app_server: Any) -> Any:
    """A fresh tab on the app's page."""
    context = browser.new_context(viewport={"width": 1400, "height": 1000}, accept_downloads=True)
    tab = context.new_page()
    tab.set_default_timeout(TIMEOUT_MS)
    errors: list[str] = []
    tab.on("pageerror", lambda exc: errors.append(str(exc)))
    tab.goto(app_server.url)
    tab.wait_for_selector("body[data-ready]")  # the page's handlers are attached
    yield tab
    context.close()
    assert errors == []


def _scene_id(tab: Any) -> str:
    return str(tab.evaluate("location.hash.split('=')[1]"))


def _make(tab: Any, prompt: str) -> None:
    tab.fill("#prompt", prompt)
    tab.click("#make")
    tab.wait_for_selector("#fields tbody tr")


def _variance(png: bytes) -> float:
    pixels = np.asarray(Image.open(io.BytesIO(png)).convert("RGB"), dtype=np.float64)
    return float(pixels.var(axis=(0, 1)).sum())


def test_prompt_table_edit_map_refine_3d_and_download(page: Any, tmp_path: Path) -> None:
    _make(page, PROMPT)
    rows = page.locator("#fields tbody tr")
    assert rows.count() == 2
    season = page.locator('select[data-field="apple_orchard_1"][data-attr="season"]')
    assert season.input_value() == "Summer"
    assert page.locator(
        'select[data-field="apple_orchard_1"][data-attr="variety"]'
    ).input_value() == ("Pink Lady")
    assert "decompose" in page.inner_text("#explanation").lower()
    page.wait_for_function("document.getElementById('map').naturalWidth > 0")
    map_before = page.locator("#map").screenshot()
    first = _scene_id(page)

    # an edit in the table: a new scene, a new map
    season.select_option("Winter")
    page.wait_for_function(f"!location.hash.endsWith('{first}')")
    page.wait_for_function("document.getElementById('map').complete")
    page.wait_for_function("document.getElementById('map').naturalWidth > 0")
    edited = page.locator('select[data-field="apple_orchard_1"][data-attr="season"]')
    assert edited.input_value() == "Winter"
    assert page.locator("#map").screenshot() != map_before
    assert "season Summer -> Winter" in page.inner_text("#changes")

    # refine by words
    second = _scene_id(page)
    page.fill("#refine", "make the apples ill")
    page.click("#refine-apply")
    page.wait_for_function(f"!location.hash.endsWith('{second}')")
    health = page.locator('select[data-field="apple_orchard_1"][data-attr="health"]')
    assert health.input_value() == "Ill"
    assert page.locator(
        'select[data-field="apple_orchard_1"][data-attr="season"]'
    ).input_value() == ("Winter")

    # the 3D view draws the plants: the canvas is not blank
    page.wait_for_function(VIEW_READY)
    page.wait_for_timeout(500)
    assert "plants" in page.inner_text("#view-status")
    assert _variance(page.locator("#viewport").screenshot()) > 200.0
    page.click("#walk")
    page.wait_for_timeout(800)
    assert page.evaluate("window.agrirecipeViewer.camera.position.y") < 3.0  # eye height
    page.click("#reset-view")

    # the download holds every output
    with page.expect_download() as caught:
        page.click("#download")
    target = tmp_path / "scene.zip"
    caught.value.save_as(target)
    names = zipfile.ZipFile(target).namelist()
    scene_id = _scene_id(page)
    for name in ("recipe.json", "plants.csv", "scene.usda", "unreal_build.py", "preview.png"):
        assert f"agrirecipe-{scene_id}/{name}" in names

    # the history lists what this tab made
    page.wait_for_selector(f'#history li[data-scene="{first}"]')


def test_a_bad_prompt_shows_the_message_and_hint(page: Any) -> None:
    page.fill("#prompt", "a field of unicorns")
    page.click("#make")
    page.wait_for_selector("#error:not([hidden])")
    message = page.inner_text("#error-message")
    assert "unicorns" in message
    assert "nearest known" in page.inner_text("#error-hint")
    assert "Traceback" not in page.inner_text("body")


def test_two_tabs_work_at_once(browser: Any, app_server: Any) -> None:
    context = browser.new_context(viewport={"width": 1200, "height": 900})
    try:
        tabs = [context.new_page(), context.new_page()]
        for tab in tabs:
            tab.set_default_timeout(TIMEOUT_MS)
            tab.goto(app_server.url)
            tab.wait_for_selector("body[data-ready]")
        prompts = ["Conference pears in autumn", "a field of Nantes carrots in spring"]
        for tab, prompt in zip(tabs, prompts, strict=True):
            tab.fill("#prompt", prompt)
        for tab in tabs:  # both requests in flight together
            tab.click("#make")
        for tab in tabs:
            tab.wait_for_selector("#fields tbody tr")
        crops = [
            tab.locator('#fields select[data-attr="crop"]').first.input_value() for tab in tabs
        ]
        assert crops == ["Pear", "Carrot"]
        assert _scene_id(tabs[0]) != _scene_id(tabs[1])
    finally:
        context.close()
