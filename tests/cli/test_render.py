"""``agrirecipe render SOURCE -o scene.png``: a recipe file or a prompt to a PNG, headless."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest
from PIL import Image

from agrirecipe.cli import main

EXAMPLES = Path(__file__).resolve().parents[2] / "examples" / "recipes"
ORCHARD = EXAMPLES / "pink-lady-orchard-summer.json"


@pytest.mark.slow
def test_renders_a_recipe_file_end_to_end(tmp_path: Path) -> None:
    png = tmp_path / "renders" / "orchard.png"
    script = tmp_path / "orchard_build.py"
    completed = subprocess.run(
        [
            sys.executable,
            "-m",
            "agrirecipe",
            "render",
            str(ORCHARD),
            "-o",
            str(png),
            "--resolution",
            "320x180",
            "--samples",
            "4",
            "--save-script",
            str(script),
        ],
        capture_output=True,
        text=True,
        timeout=600,
        check=False,
    )
    assert completed.returncode == 0, completed.stdout + completed.stderr
    assert f"wrote {png.resolve()}" in completed.stdout.splitlines()
    assert "rendering 1 field(s), up to 1,335 plants" in completed.stderr
    with Image.open(png) as image:
        assert image.size == (320, 180)
        assert np.asarray(image.convert("RGB")).astype(float).std() > 15.0
    assert "RESOLUTION = (320, 180)" in script.read_text(encoding="utf-8")


@pytest.mark.slow
def test_renders_a_prompt(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    png = tmp_path / "lettuce.png"
    code = main(
        [
            "render",
            "a healthy lettuce field in summer",
            "--resolver",
            "rules",
            "-o",
            str(png),
            "--resolution",
            "160x90",
            "--samples",
            "2",
        ]
    )
    assert code == 0
    with Image.open(png) as image:
        assert image.size == (160, 90)
    assert f"wrote {png.resolve()}" in capsys.readouterr().out


def test_a_missing_recipe_file_is_a_clear_error(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    missing = tmp_path / "nope.json"
    assert main(["render", str(missing), "-o", str(tmp_path / "x.png")]) == 2
    error = capsys.readouterr().err
    assert "no recipe file" in error and "nope.json" in error
    assert not (tmp_path / "x.png").exists()


@pytest.mark.parametrize(
    ("options", "message"),
    [
        (["--samples", "0"], "samples 0 is not a sample count"),
        (["--resolution", "0x10"], "resolution (0, 10)"),
        (["-o", "scene.jpg"], "is not a .png file"),
    ],
)
def test_bad_settings_fail_before_any_work(
    options: list[str], message: str, tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    arguments = ["render", str(ORCHARD), "-o", str(tmp_path / "x.png"), *options]
    assert main(arguments) == 2
    assert message in capsys.readouterr().err


def test_resolution_must_be_width_x_height(capsys: pytest.CaptureFixture[str]) -> None:
    with pytest.raises(SystemExit) as caught:
        main(["render", str(ORCHARD), "--resolution", "wide"])
    assert caught.value.code == 2
    assert "is not WIDTHxHEIGHT" in capsys.readouterr().err


def test_help_lists_the_options(capsys: pytest.CaptureFixture[str]) -> None:
    with pytest.raises(SystemExit):
        main(["render", "--help"])
    text = capsys.readouterr().out
    for option in ("--output", "--resolution", "--samples", "--engine", "--save-blend"):
        assert option in text
