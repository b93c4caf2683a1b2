"""``agrirecipe build RECIPE -o DIR`` and ``agrirecipe edit RECIPE "..." -o DIR``."""

from __future__ import annotations

import csv
import json
from pathlib import Path

import pytest

from agrirecipe.cli import main

PROMPT = "a Conference pear orchard next to Nantes carrots"


def _files(folder: Path) -> dict[str, bytes]:
    return {
        str(path.relative_to(folder)): path.read_bytes()
        for path in sorted(folder.rglob("*"))
        if path.is_file()
    }


@pytest.fixture(scope="module")
def generated(tmp_path_factory: pytest.TempPathFactory) -> Path:
    folder = tmp_path_factory.mktemp("generated")
    assert main(["generate", PROMPT, "-o", str(folder)]) == 0
    return folder


def test_build_writes_exactly_what_generate_wrote(generated: Path, tmp_path: Path) -> None:
    assert main(["build", str(generated / "recipe.json"), "-o", str(tmp_path)]) == 0
    expected, built = _files(generated), _files(tmp_path)
    assert sorted(built) == sorted(expected)
    assert any(name.endswith(".glb") for name in built)  # the plant meshes, too
    assert built == expected


def test_build_compiles_a_hand_edited_recipe(generated: Path, tmp_path: Path) -> None:
    data = json.loads((generated / "recipe.json").read_text(encoding="utf-8"))
    data["fields"][1]["geometry"]["size_m"] = [10.0, 20.0]
    edited = tmp_path / "recipe.json"
    edited.write_text(json.dumps(data), encoding="utf-8")
    out = tmp_path / "out"
    assert main(["build", str(edited), "-o", str(out), "--backends", "annotations"]) == 0
    with (out / "plants.csv").open(encoding="utf-8") as handle:
        carrots = [r for r in csv.DictReader(handle) if r["field_id"] == "carrot_field_1"]
    assert carrots and all(float(r["y_m"]) <= 20.0 for r in carrots)


def test_build_refuses_an_invalid_recipe_and_writes_nothing(
    generated: Path, tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    data = json.loads((generated / "recipe.json").read_text(encoding="utf-8"))
    data["fields"][0]["crop"] = "Olive"
    bad = tmp_path / "bad.json"
    bad.write_text(json.dumps(data), encoding="utf-8")
    out = tmp_path / "out"
    assert main(["build", str(bad), "-o", str(out)]) == 2
    assert "Olive" in capsys.readouterr().err
    assert not out.exists()


def test_edit_prints_the_diff_and_writes_the_edited_scene(
    generated: Path, tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    code = main(
        [
            "edit",
            str(generated / "recipe.json"),
            "make the pears ill",
            "-o",
            str(tmp_path),
            "--backends",
            "annotations",
        ]
    )
    assert code == 0
    out = capsys.readouterr().out
    assert out.splitlines()[0] == "~ pear_orchard_1: health Healthy -> Ill"
    recipe = json.loads((tmp_path / "recipe.json").read_text(encoding="utf-8"))
    assert [f["health"] for f in recipe["fields"]] == ["Ill", "Healthy"]

    def carrot_rows(folder: Path) -> list[dict[str, str]]:
        with (folder / "plants.csv").open(encoding="utf-8") as handle:
            return [r for r in csv.DictReader(handle) if r["field_id"] == "carrot_field_1"]

    assert carrot_rows(tmp_path) == carrot_rows(generated)


def test_edit_dry_run_writes_nothing(
    generated: Path, tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    out = tmp_path / "out"
    args = ["edit", str(generated / "recipe.json"), "remove the carrots", "-o", str(out)]
    assert main([*args, "--dry-run"]) == 0
    assert capsys.readouterr().out.startswith("- carrot_field_1 (Nantes carrot field)")
    assert not out.exists()


def test_an_ambiguous_edit_is_an_error_listing_the_fields(
    generated: Path, tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    out = tmp_path / "out"
    assert main(["edit", str(generated / "recipe.json"), "make it ill", "-o", str(out)]) == 2
    err = capsys.readouterr().err
    assert "does not say which field" in err and "carrot_field_1" in err
    assert not out.exists()
