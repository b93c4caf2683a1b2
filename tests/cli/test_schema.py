"""``agrirecipe schema`` prints the checked-in JSON Schema."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import pytest

from agrirecipe.cli import main
from agrirecipe.recipe import schema_text


def test_schema_prints_the_schema(capsys: pytest.CaptureFixture[str]) -> None:
    assert main(["schema"]) == 0
    captured = capsys.readouterr()
    assert captured.out == schema_text()
    assert captured.err == ""


def test_python_dash_m_prints_the_checked_in_file(repo_root: Path) -> None:
    result = subprocess.run(
        [sys.executable, "-m", "agrirecipe", "schema"],
        capture_output=True,
        text=True,
        encoding="utf-8",
        check=False,
    )
    assert result.returncode == 0, result.stderr
    checked_in = (repo_root / "schemas" / "scene-recipe.schema.json").read_text(encoding="utf-8")
    assert result.stdout == checked_in


def test_schema_help(capsys: pytest.CaptureFixture[str]) -> None:
    with pytest.raises(SystemExit) as exited:
        main(["schema", "--help"])
    assert exited.value.code == 0
    assert "JSON Schema" in capsys.readouterr().out
