"""``agrirecipe validate FILE...``: exit 0 when valid; 1 with every problem and its path."""

from __future__ import annotations

import json
import shutil
import subprocess
import sys
from pathlib import Path
from typing import Any

import pytest

from agrirecipe.cli import main

EXAMPLES = Path(__file__).resolve().parents[2] / "examples" / "recipes"
ORCHARD = EXAMPLES / "pink-lady-orchard-summer.json"


def _write(path: Path, data: Any) -> Path:
    path.write_text(json.dumps(data, indent=2), encoding="utf-8")
    return path


def _orchard() -> dict[str, Any]:
    data: dict[str, Any] = json.loads(ORCHARD.read_text(encoding="utf-8"))
    return data


def test_valid_files(capsys: pytest.CaptureFixture[str]) -> None:
    files = sorted(EXAMPLES.glob("*.json"))
    assert main(["validate", *map(str, files)]) == 0
    out = capsys.readouterr().out.splitlines()
    assert len(out) == len(files)
    assert f"{ORCHARD}: ok (1 field(s), 1,335 planting positions)" in out


def test_every_problem_is_printed_with_its_path(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    data = _orchard()
    data["fields"][0]["agronomy"]["in_row_spacing_m"] = 0
    data["fields"][0]["variety"] = "Honeycrisp"
    data["environment"]["hemisphere"] = "south"
    bad = _write(tmp_path / "bad.json", data)
    assert main(["validate", str(bad)]) == 1
    captured = capsys.readouterr()
    assert captured.out == ""
    lines = captured.err.splitlines()
    assert [line.split(": ")[1] for line in lines] == [
        "environment.hemisphere",
        "fields[0].agronomy.in_row_spacing_m",
    ]
    assert all(line.startswith(f"{bad}: ") for line in lines)
    # The hierarchy is consulted only once the models accept the recipe.
    data["fields"][0]["agronomy"]["in_row_spacing_m"] = 1.0
    data["environment"]["hemisphere"] = "north"
    _write(bad, data)
    assert main(["validate", str(bad)]) == 1
    err = capsys.readouterr().err
    assert err.startswith(f"{bad}: fields[0].variety: 'Honeycrisp' is not a variety of Apple")


def test_the_json_schema_is_checked_too(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    data = _orchard()
    data["seed"] = "7"  # the models alone would accept and convert this
    bad = _write(tmp_path / "seed.json", data)
    assert main(["validate", str(bad)]) == 1
    assert capsys.readouterr().err == f"{bad}: seed: '7' is not of type 'integer'\n"


def test_good_and_bad_files_together(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    broken = tmp_path / "broken.json"
    broken.write_text('{"prompt": ', encoding="utf-8")
    missing = tmp_path / "missing.json"
    assert main(["validate", str(ORCHARD), str(broken), str(missing)]) == 1
    captured = capsys.readouterr()
    assert captured.out.startswith(f"{ORCHARD}: ok")
    assert f"{broken}: error: not valid JSON" in captured.err
    assert f"{missing}: error: no such file" in captured.err


def test_max_plants(capsys: pytest.CaptureFixture[str]) -> None:
    assert main(["validate", "--max-plants", "1000", str(ORCHARD)]) == 1
    err = capsys.readouterr().err
    assert "fields[0].geometry.size_m: the scene would hold 1,335 plants" in err
    assert "cap of 1,000" in err
    assert main(["validate", "--max-plants", "1335", str(ORCHARD)]) == 0


def test_custom_hierarchy(
    tmp_path: Path, capsys: pytest.CaptureFixture[str], repo_root: Path
) -> None:
    # A hierarchy whose apples live under another content root: the shipped
    # example's asset paths no longer match.
    source = (repo_root / "hierarchy.yaml").read_text(encoding="utf-8")
    custom = tmp_path / "hierarchy.yaml"
    custom.write_text(
        source.replace("content_root: /Game/Agriculture", "content_root: /Game/MyFarm"),
        encoding="utf-8",
    )
    assert main(["validate", "--hierarchy", str(custom), str(ORCHARD)]) == 1
    err = capsys.readouterr().err
    assert "fields[0].asset_path" in err
    assert "expected '/Game/MyFarm/Fruits/Apple/PinkLady/" in err
    data = _orchard()
    data["fields"][0]["asset_path"] = data["fields"][0]["asset_path"].replace(
        "/Game/Agriculture/", "/Game/MyFarm/"
    )
    moved = _write(tmp_path / "moved.json", data)
    assert main(["validate", "--hierarchy", str(custom), str(moved)]) == 0


def test_malformed_custom_hierarchy_exits_2(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    custom = tmp_path / "hierarchy.yaml"
    custom.write_text("stages: [Vegetative]\n", encoding="utf-8")
    assert main(["validate", "--hierarchy", str(custom), str(ORCHARD)]) == 2
    err = capsys.readouterr().err
    assert err.startswith("agrirecipe: error: ")
    assert "categories: Field required" in err


def test_exit_code_from_a_real_process(tmp_path: Path) -> None:
    bad = tmp_path / "bad.json"
    shutil.copy(ORCHARD, bad)
    data = json.loads(bad.read_text(encoding="utf-8"))
    data["fields"][0]["geometry"]["size_m"] = [1, 1]
    _write(bad, data)
    result = subprocess.run(
        [sys.executable, "-m", "agrirecipe", "validate", str(bad)],
        capture_output=True,
        text=True,
        check=False,
    )
    assert result.returncode == 1
    assert "fields[0].geometry.size_m: a 1 x 1 m field with a 6 m headland is too small" in (
        result.stderr
    )
