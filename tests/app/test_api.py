"""The app's HTTP API against a real server: prompt, edits, files, limits, history."""

from __future__ import annotations

import io
import json
import time
import zipfile
from pathlib import Path
from typing import Any

import pytest

PROMPT = "a healthy Pink Lady apple orchard in summer next to young Nantes carrots"
PNG_MAGIC = b"\x89PNG\r\n\x1a\n"


@pytest.fixture(scope="module")
def orchard(app_server: Any) -> dict[str, Any]:
    """The scene of the apple-and-carrots prompt."""
    answer = app_server.call("POST", "/api/scenes", {"prompt": PROMPT})
    assert answer.status == 200, answer.body
    return dict(answer.json())


def _field(scene: dict[str, Any], crop: str) -> dict[str, Any]:
    return next(f for f in scene["fields"] if f["crop"] == crop)


def test_a_prompt_gives_the_field_table_the_stages_and_the_map(
    app_server: Any, orchard: dict[str, Any]
) -> None:
    apple, carrot = _field(orchard, "Apple"), _field(orchard, "Carrot")
    assert (apple["variety"], apple["season"], apple["health"]) == (
        "Pink Lady",
        "Summer",
        "Healthy",
    )
    assert carrot["variety"] == "Nantes"
    assert {"crop", "variety", "season", "health"} <= set(apple["stated"])
    assert "stage" in apple["inferred"]
    assert orchard["relations"] == [
        {"kind": "next_to", "subject": "apple_orchard_1", "objects": ["carrot_field_1"]}
    ]
    stages = [stage["stage"] for stage in orchard["explanation"]]
    assert {"decompose", "normalise", "enrich", "layout"} <= set(stages)
    png = app_server.call("GET", f"/api/scenes/{orchard['scene']['id']}/files/preview.png")
    assert png.status == 200 and png.body.startswith(PNG_MAGIC)
    assert png.headers["content-type"] == "image/png"


def test_an_unknown_crop_is_its_message_and_hint_never_a_traceback(app_server: Any) -> None:
    answer = app_server.call("POST", "/api/scenes", {"prompt": "a field of unicorns"})
    assert answer.status == 422
    error = answer.json()["error"]
    assert error["type"] == "UnknownCropError"
    assert "unicorns" in error["message"]
    assert error["hint"].startswith("nearest known:")
    assert b"Traceback" not in answer.body


def test_prompt_and_body_sizes_are_limited(app_server: Any) -> None:
    long_prompt = app_server.call("POST", "/api/scenes", {"prompt": "wheat " * 500})
    assert long_prompt.status == 422
    assert "at most 2,000" in long_prompt.json()["error"]["message"]
    huge = b'{"prompt": "' + b"a" * 3_000_000 + b'"}'
    too_large = app_server.call("POST", "/api/scenes", raw=huge)
    assert too_large.status == 413
    assert "larger than" in too_large.json()["error"]["message"]


def test_requests_from_another_site_or_not_json_are_refused(app_server: Any) -> None:
    foreign = app_server.call(
        "POST", "/api/scenes", {"prompt": PROMPT}, headers={"Origin": "http://evil.example"}
    )
    assert foreign.status == 403
    form = app_server.call(
        "POST",
        "/api/scenes",
        raw=b"prompt=wheat",
        headers={"Content-Type": "application/x-www-form-urlencoded"},
    )
    assert form.status == 415


@pytest.mark.parametrize(
    "path",
    [
        "../../history.sqlite3",
        "..%2F..%2Fhistory.sqlite3",
        "%2e%2e/%2e%2e/history.sqlite3",
        "assets/../../../history.sqlite3",
        "%2Fetc%2Fpasswd",
        "/etc/passwd",
    ],
)
def test_file_routes_never_leave_the_scene_folder(
    app_server: Any, orchard: dict[str, Any], path: str
) -> None:
    answer = app_server.call("GET", f"/api/scenes/{orchard['scene']['id']}/files/{path}")
    assert answer.status in (403, 404)
    assert b"SQLite" not in answer.body and b"root:" not in answer.body


def test_a_symbolic_link_out_of_the_folder_is_refused(
    app_server: Any, orchard: dict[str, Any]
) -> None:
    from agrirecipe.app import UnsafePathError

    store = app_server.service.store
    folder = store.folder(orchard["scene"]["id"])
    link = folder / "escape.txt"
    link.symlink_to(store.database)
    try:
        answer = app_server.call("GET", f"/api/scenes/{orchard['scene']['id']}/files/escape.txt")
        assert answer.status == 403
        with pytest.raises(UnsafePathError):
            store.file(orchard["scene"]["id"], "escape.txt")
    finally:
        link.unlink()


def test_unknown_scenes_and_bad_ids_are_404(app_server: Any) -> None:
    for scene_id in ("000000000000", "..", "not-an-id"):
        answer = app_server.call("GET", f"/api/scenes/{scene_id}")
        assert answer.status == 404, scene_id
        assert answer.json()["error"]["type"] == "SceneNotFoundError"


def test_editing_a_season_recompiles_a_new_scene(app_server: Any, orchard: dict[str, Any]) -> None:
    scene_id = orchard["scene"]["id"]
    answer = app_server.call(
        "POST", f"/api/scenes/{scene_id}/fields/apple_orchard_1", {"season": "Winter"}
    )
    assert answer.status == 200, answer.body
    edited = answer.json()
    apple = _field(edited, "Apple")
    assert apple["season"] == "Winter"
    assert "season" in apple["stated"]
    # a new asset with agronomy for the new key; the other field is untouched
    assert "/Winter/" in apple["asset_path"]
    assert _field(edited, "Carrot") == _field(orchard, "Carrot")
    assert edited["scene"]["parent"] == scene_id
    assert edited["scene"]["changes"] == ["~ apple_orchard_1: season Summer -> Winter"]
    before = app_server.call("GET", f"/api/scenes/{scene_id}/files/preview.png").body
    after = app_server.call("GET", f"/api/scenes/{edited['scene']['id']}/files/preview.png").body
    assert after.startswith(PNG_MAGIC) and after != before


def test_field_choices_are_limited_to_the_hierarchy(
    app_server: Any, orchard: dict[str, Any]
) -> None:
    scene_id = orchard["scene"]["id"]
    bad = app_server.call(
        "POST", f"/api/scenes/{scene_id}/fields/apple_orchard_1", {"crop": "Unicorn"}
    )
    assert bad.status == 422
    assert "Unicorn" in bad.json()["error"]["message"]
    season = app_server.call(
        "POST", f"/api/scenes/{scene_id}/fields/apple_orchard_1", {"season": "Monsoon"}
    )
    assert season.status == 422
    choices = app_server.call("GET", "/api/choices").json()
    assert choices["seasons"] == ["Spring", "Summer", "Fall", "Winter"]
    assert "Pink Lady" in choices["crops"]["Apple"]["varieties"]


def test_a_new_crop_takes_its_default_variety(app_server: Any, orchard: dict[str, Any]) -> None:
    answer = app_server.call(
        "POST", f"/api/scenes/{orchard['scene']['id']}/fields/carrot_field_1", {"crop": "Potato"}
    )
    assert answer.status == 200, answer.body
    field = next(f for f in answer.json()["fields"] if f["id"] == "carrot_field_1")
    assert field["crop"] == "Potato"
    choices = app_server.call("GET", "/api/choices").json()
    assert field["variety"] == choices["crops"]["Potato"]["default_variety"]
    assert "variety" in field["inferred"] and "crop" in field["stated"]


def test_a_larger_field_repacks_the_farm_without_overlap(
    app_server: Any, orchard: dict[str, Any]
) -> None:
    answer = app_server.call(
        "POST",
        f"/api/scenes/{orchard['scene']['id']}/fields/carrot_field_1",
        {"size_m": [50, 120]},
    )
    assert answer.status == 200, answer.body
    carrot = _field(answer.json(), "Carrot")
    assert carrot["size_m"] == [50.0, 120.0] and "size" in carrot["stated"]
    recipe = app_server.service.scene(answer.json()["scene"]["id"]).recipe
    assert recipe.fields[1].geometry.size_m == (50.0, 120.0)  # validated, so no overlap


def test_relations_are_editable_and_repack(app_server: Any, orchard: dict[str, Any]) -> None:
    relation = {"kind": "north_of", "subject": "carrot_field_1", "objects": ["apple_orchard_1"]}
    answer = app_server.call(
        "PUT", f"/api/scenes/{orchard['scene']['id']}/relations", {"relations": [relation]}
    )
    assert answer.status == 200, answer.body
    scene = app_server.service.scene(answer.json()["scene"]["id"]).recipe
    apple, carrot = scene.fields
    assert carrot.geometry.origin_m[1] >= apple.geometry.origin_m[1] + apple.geometry.size_m[1]
    bad = app_server.call(
        "PUT",
        f"/api/scenes/{orchard['scene']['id']}/relations",
        {"relations": [{"kind": "north_of", "subject": "carrot_field_1", "objects": ["nowhere"]}]},
    )
    assert bad.status == 422


def test_an_upload_is_validated_like_agrirecipe_validate(app_server: Any, repo_root: Path) -> None:
    text = (repo_root / "examples/recipes/pinot-noir-vineyard-harvest.json").read_text("utf-8")
    good = app_server.call("POST", "/api/scenes/upload", {"recipe": text})
    assert good.status == 200, good.body
    assert good.json()["fields"][0]["crop"] == "Grape"
    data = json.loads(text)
    data["fields"][0]["season"] = "Monsoon"
    data["fields"][0]["crop"] = "Unicorn"
    bad = app_server.call("POST", "/api/scenes/upload", {"recipe": json.dumps(data)})
    assert bad.status == 422
    error = bad.json()["error"]
    assert error["type"] == "RecipeValidationError"
    paths = [path for path, _ in error["problems"]]
    assert "fields[0].season" in paths
    assert app_server.call("POST", "/api/scenes/upload", {"recipe": "{not json"}).status == 422


def test_the_3d_view_gets_compact_plants_and_a_sample_above_the_limit(
    app_server: Any, orchard: dict[str, Any]
) -> None:
    scene_id = orchard["scene"]["id"]
    view = app_server.call("GET", f"/api/scenes/{scene_id}/view").json()
    total = orchard["scene"]["plant_count"]
    assert view["total_plants"] == view["shown_plants"] == total and not view["sampled"]
    apple = view["fields"][0]
    assert len(apple["files"]) == 3 and all(f.endswith(".glb") for f in apple["files"])
    glb = app_server.call("GET", f"/api/scenes/{scene_id}/files/{apple['files'][0]}")
    assert glb.body[:4] == b"glTF"
    plants = app_server.call("GET", f"/api/scenes/{scene_id}/plants.bin").body
    assert len(plants) == total * 6 * 4
    sampled = app_server.call("GET", f"/api/scenes/{scene_id}/view?max_plants=1000").json()
    assert sampled["sampled"] and sampled["shown_plants"] <= 1000
    assert sum(f["shown"] for f in sampled["fields"]) == sampled["shown_plants"]
    few = app_server.call("GET", f"/api/scenes/{scene_id}/plants.bin?max_plants=1000").body
    assert len(few) == sampled["shown_plants"] * 24
    again = app_server.call("GET", f"/api/scenes/{scene_id}/plants.bin?max_plants=1000").body
    assert few == again  # the sample is seeded
    assert view["walk"]["field_id"] == "apple_orchard_1"


def test_the_download_holds_every_output(app_server: Any, orchard: dict[str, Any]) -> None:
    scene_id = orchard["scene"]["id"]
    answer = app_server.call("GET", f"/api/scenes/{scene_id}/download")
    assert answer.status == 200
    assert answer.headers["content-type"] == "application/zip"
    names = zipfile.ZipFile(io.BytesIO(answer.body)).namelist()
    prefix = f"agrirecipe-{scene_id}/"
    for name in (
        "recipe.json",
        "unreal_build.py",
        "blender_build.py",
        "scene.usda",
        "plants.csv",
        "fields.geojson",
        "preview.png",
    ):
        assert prefix + name in names
    assert any(n.startswith(prefix + "assets/") and n.endswith(".glb") for n in names)
    assert not any("/." in n for n in names)
    assert app_server.call("GET", f"/api/scenes/{scene_id}").json()["outputs"] == "ready"


def test_the_history_survives_a_restart(app_server: Any, orchard: dict[str, Any]) -> None:
    from agrirecipe.app import AppConfig, AppService

    listed = app_server.call("GET", "/api/history").json()["scenes"]
    assert orchard["scene"]["id"] in [s["id"] for s in listed]
    restarted = AppService(AppConfig(root=app_server.service.store.root))
    try:
        again = restarted.describe(orchard["scene"]["id"])
        assert again["fields"] == orchard["fields"]
        assert again["explanation"] == orchard["explanation"]
    finally:
        restarted.close()


def test_refine_by_words_is_an_edit(app_server: Any, orchard: dict[str, Any]) -> None:
    answer = app_server.call(
        "POST",
        f"/api/scenes/{orchard['scene']['id']}/refine",
        {"instruction": "make the apples ill"},
    )
    assert answer.status == 200, answer.body
    refined = answer.json()
    assert _field(refined, "Apple")["health"] == "Ill"
    assert _field(refined, "Carrot")["health"] == "Healthy"
    assert refined["scene"]["action"] == "refine"
    assert any("apple" in line.lower() for line in refined["scene"]["changes"])
    nothing = app_server.call(
        "POST", f"/api/scenes/{orchard['scene']['id']}/refine", {"instruction": "xyzzy"}
    )
    assert nothing.status == 422
    assert nothing.json()["error"]["message"]


@pytest.mark.slow
def test_a_render_reports_progress_and_can_be_cancelled(app_server: Any) -> None:
    pytest.importorskip("bpy")
    scene = app_server.call("POST", "/api/scenes", {"prompt": "a small lettuce field"}).json()
    scene_id = scene["scene"]["id"]
    job = app_server.call(
        "POST", f"/api/scenes/{scene_id}/render", {"width": 160, "height": 90, "samples": 2}
    ).json()
    progress = []
    deadline = time.monotonic() + 240
    while job["state"] in ("queued", "running") and time.monotonic() < deadline:
        time.sleep(0.3)
        job = app_server.call("GET", f"/api/renders/{job['id']}").json()
        progress.append(job["progress"])
    assert job["state"] == "done", job
    assert progress == sorted(progress) and job["progress"] == 1.0
    image = app_server.call("GET", f"/api/scenes/{scene_id}/files/render.png")
    assert image.body.startswith(PNG_MAGIC)
    slow = app_server.call(
        "POST", f"/api/scenes/{scene_id}/render", {"width": 1280, "height": 720, "samples": 512}
    ).json()
    time.sleep(1.0)
    cancelled = app_server.call("POST", f"/api/renders/{slow['id']}/cancel").json()
    deadline = time.monotonic() + 30
    while cancelled["state"] in ("queued", "running") and time.monotonic() < deadline:
        time.sleep(0.2)
        cancelled = app_server.call("GET", f"/api/renders/{slow['id']}").json()
    assert cancelled["state"] == "cancelled"
    # the finished render is still the one on disk
    assert app_server.call("GET", f"/api/scenes/{scene_id}/files/render.png").body == image.body
    assert (app_server.service.store.folder(scene_id) / "render.png").stat().st_size > 0
