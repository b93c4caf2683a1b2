"""``Scene.write``: recipe.json plus every backend's outputs, atomically and reproducibly."""

from __future__ import annotations

import os
from pathlib import Path

import pytest

from agrirecipe import ConfigurationError, Scene, load_recipe
from agrirecipe._scene import DEFAULT_BACKENDS
from agrirecipe.backends import get_backend
from agrirecipe.backends.usd import BINARY_ABOVE

EXAMPLE = (
    Path(__file__).resolve().parents[1]
    / "examples"
    / "recipes"
    / "yellow-rust-wheat-north-of-potatoes.json"
)


@pytest.fixture(scope="module")
def scene() -> Scene:
    return Scene.from_file(EXAMPLE)


def test_write_produces_the_recipe_and_the_ground_truth_outputs(
    scene: Scene, tmp_path: Path
) -> None:
    written = scene.write(tmp_path / "out", backends=["usd", "annotations"])
    names = [p.name for p in written]
    # a scene of more than BINARY_ABOVE plants keeps its per-plant arrays in binary beside
    assert scene.layout.plant_count > BINARY_ABOVE
    assert names == [
        "recipe.json",
        "scene.usda",
        "scene_plants.usdc",
        "plants.csv",
        "fields.geojson",
        "preview.png",
    ]
    for path in written:
        assert path.parent == tmp_path / "out" and path.stat().st_size > 0
    assert load_recipe(tmp_path / "out" / "recipe.json") == scene.recipe
    # Atomic writes leave no temporary files behind; the plant meshes are beside.
    assert sorted(p.name for p in (tmp_path / "out").iterdir()) == sorted([*names, "assets"])
    assert not list((tmp_path / "out").rglob(".*"))
    rows = (tmp_path / "out" / "plants.csv").read_text(encoding="utf-8").count("\n") - 1
    assert rows == scene.layout.plant_count


def test_same_recipe_and_seed_give_byte_identical_files(scene: Scene, tmp_path: Path) -> None:
    first = scene.write(tmp_path / "a", backends=["usd", "annotations"])
    second = Scene(load_recipe(first[0])).write(tmp_path / "b", backends=["usd", "annotations"])
    for a, b in zip(first, second, strict=True):
        assert a.read_bytes() == b.read_bytes(), a.name


def test_default_write_runs_every_default_backend(scene: Scene, tmp_path: Path) -> None:
    written = {p.name for p in scene.write(tmp_path)}
    expected = {"recipe.json", "scene_plants.usdc"}  # the example is a large scene
    for name in DEFAULT_BACKENDS:
        expected |= set(get_backend(name).outputs)
    assert written == expected
    assert {"scene.usda", "plants.csv", "fields.geojson", "preview.png"} <= written


def test_writing_over_a_file_is_refused(scene: Scene, tmp_path: Path) -> None:
    blocker = tmp_path / "taken"
    blocker.write_text("")
    with pytest.raises(ConfigurationError, match="not a folder"):
        scene.write(blocker, backends=["annotations"])


def test_outputs_are_readable_by_others(scene: Scene, tmp_path: Path) -> None:
    # Atomic writes go through mkstemp, whose files are private (0600) unless changed.
    for path in scene.write(tmp_path, backends=["usd", "annotations"]):
        assert path.stat().st_mode & 0o044 == 0o044, path.name


def test_a_write_removes_what_a_killed_write_left(scene: Scene, tmp_path: Path) -> None:
    import subprocess
    import sys

    out = tmp_path / "out"
    (out / "assets").mkdir(parents=True)
    child = subprocess.run(
        [sys.executable, "-c", "import os; print(os.getpid())"],
        capture_output=True,
        text=True,
        check=True,
    )
    dead = int(child.stdout)  # a process that has exited
    stale = [
        out / f".scene.usda.{dead}.abcd1234.usda",
        out / "assets" / f".x.glb.{dead}.q1w2e3r4.tmp",
    ]
    live = out / f".plants.csv.{os.getpid()}.zzzz9999.tmp"  # a write still running
    other = out / ".hidden-by-the-user"
    for path in (*stale, live, other):
        path.write_bytes(b"partial")
    scene.write(out, backends=["annotations"])
    assert not any(path.exists() for path in stale)
    assert live.exists() and other.exists()
