"""``agrirecipe finetune``: arguments and errors (training itself runs in test_train)."""

from __future__ import annotations

from pathlib import Path

import pytest

from agrirecipe.cli import main


def test_help_describes_the_command(capsys: pytest.CaptureFixture[str]) -> None:
    with pytest.raises(SystemExit) as exit_info:
        main(["finetune", "--help"])
    assert exit_info.value.code == 0
    text = " ".join(capsys.readouterr().out.split())
    for option in ("--output", "--epochs", "--max-steps", "--resume"):
        assert option in text
    assert "llama.cpp LoRA GGUF" in text


@pytest.mark.parametrize("option", ["--max-steps", "--epochs"])
def test_non_positive_counts_are_refused(
    option: str, tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    assert main(["finetune", "-o", str(tmp_path), option, "0"]) == 2
    assert f"{option} must be at least 1" in capsys.readouterr().err


def test_a_bad_settings_file_names_the_key(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    settings = tmp_path / "settings.yaml"
    settings.write_text("version: 1\nlora: {rank: 0}\n", encoding="utf-8")
    assert main(["finetune", "-o", str(tmp_path), "--settings", str(settings)]) == 2
    assert "lora.rank" in capsys.readouterr().err
