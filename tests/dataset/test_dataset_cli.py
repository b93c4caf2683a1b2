"""``agrirecipe dataset`` on the command line (a recipe file as the source)."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from agrirecipe.cli import main


@pytest.mark.slow
def test_the_command_renders_a_robot_dataset(tmp_path: Path) -> None:
    pytest.importorskip("bpy")
    from agrirecipe import dump_recipe, generate

    recipe = tmp_path / "lettuce.json"
    scene = generate("a 6 by 8 m field of young lettuce", resolver="rules")
    recipe.write_text(dump_recipe(scene.recipe), encoding="utf-8")
    out = tmp_path / "data"
    code = main(
        [
            "dataset",
            str(recipe),
            "-o",
            str(out),
            "--views",
            "1",
            "--resolution",
            "64x48",
            "--camera",
            "robot",
            "--robot-height",
            "0.6",
            "--weeds",
            "1/m2",
            "--samples",
            "2",
            "--vary",
            "stage,health",
            "--resolver",
            "rules",
            "--device",
            "gpu",
            "--quiet",
        ]
    )
    assert code == 0
    manifest = json.loads((out / "manifest.json").read_text("utf-8"))
    (image,) = manifest["variants"][0]["images"]
    assert image["camera"]["kind"] == "robot"
    assert image["camera"]["location_m"][2] == pytest.approx(0.6)
    assert manifest["settings"]["weeds_per_m2"] == 1.0
    # No GPU here: asked for one, Cycles falls back to the CPU and says so.
    assert manifest["settings"]["device"] == "gpu"
    assert manifest["variants"][0]["render_device"] == "CPU"
    assert (out / image["files"]["image"]).is_file()
    assert manifest["sources"][0]["prompt"] == "a 6 by 8 m field of young lettuce"
    assert manifest["semantic_classes"]["Lettuce"] == 4
    # "young" stated the stage, so only the health was drawn.
    (varied,) = manifest["variants"][0]["varied"]["attributes"]["fields"].values()
    assert set(varied) == {"health"}
    recipe_file = out / manifest["variants"][0]["files"]["recipe"]
    (field,) = json.loads(recipe_file.read_text("utf-8"))["fields"]
    assert field["stage"] == "Vegetative" and field["health"] == varied["health"]


def test_bad_options_are_one_clear_error(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    code = main(["dataset", "a wheat field", "-o", str(tmp_path / "x"), "--weeds", "heaps"])
    assert code == 2
    assert "weed density 'heaps' is not understood" in capsys.readouterr().err
