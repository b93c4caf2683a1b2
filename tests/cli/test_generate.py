"""``agrirecipe generate PROMPT -o DIR``."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from agrirecipe.cli import main


def test_generate_writes_the_recipe(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    code = main(
        [
            "generate",
            "a healthy Pink Lady apple orchard in summer next to young Nantes carrots",
            "-o",
            str(tmp_path),
            "--backends",
            "",
            "--resolver",
            "rules",
            "--seed",
            "3",
        ]
    )
    assert code == 0
    out = capsys.readouterr().out
    assert "apple_orchard_1: Pink Lady Apple, " in out
    assert "carrot_field_1: Nantes Carrot, Vegetative" in out
    recipe = json.loads((tmp_path / "recipe.json").read_text(encoding="utf-8"))
    assert recipe["seed"] == 3 and recipe["resolver"] == "rules"
    assert [f["crop"] for f in recipe["fields"]] == ["Apple", "Carrot"]


def test_explain_goes_to_stderr(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    code = main(
        [
            "generate",
            "an appel orchard in autum",
            "-o",
            str(tmp_path),
            "--backends",
            "",
            "--explain",
        ]
    )
    assert code == 0
    err = capsys.readouterr().err
    assert "[normalise]" in err and "'apple'" in err and "[enrich]" in err


def test_warnings_go_to_stderr(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    code = main(
        ["generate", "apple trees in bloom in winter", "-o", str(tmp_path), "--backends", ""]
    )
    assert code == 0
    assert "warning: apple_orchard_1:" in capsys.readouterr().err


def test_latitude(tmp_path: Path) -> None:
    code = main(
        [
            "generate",
            "a vineyard in January",
            "-o",
            str(tmp_path),
            "--backends",
            "",
            "--latitude",
            "-34",
        ]
    )
    assert code == 0
    recipe = json.loads((tmp_path / "recipe.json").read_text(encoding="utf-8"))
    assert recipe["environment"]["hemisphere"] == "south"
    assert recipe["fields"][0]["season"] == "Summer"


@pytest.mark.parametrize(
    ("prompt", "message"),
    [
        ("a mango plantation", "nearest known: Orange, Banana"),
        ("build a parking lot", "not an agricultural scene"),
        ("", "empty"),
    ],
)
def test_bad_prompts_exit_2_with_a_message(
    prompt: str, message: str, tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    assert main(["generate", prompt, "-o", str(tmp_path / "out")]) == 2
    assert message in capsys.readouterr().err
    assert not (tmp_path / "out").exists()


def test_max_plants(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    command = ["generate", "a 2 ha wheat field", "-o", str(tmp_path / "out"), "--backends", ""]
    # ~3 million plants: even one drawn in twenty is more than 100,000
    assert main([*command, "--max-plants", "100000"]) == 2
    assert "more than the cap of 100,000" in capsys.readouterr().err
    assert not (tmp_path / "out").exists()
    assert main(command) == 0  # under the default cap
