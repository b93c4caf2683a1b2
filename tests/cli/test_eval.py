"""``agrirecipe eval`` on a handful of prompts with the rules strategy (no model needed)."""

from __future__ import annotations

import re
from pathlib import Path

import pytest

from agrirecipe.cli import main
from agrirecipe.evaluation import BEGIN_MARKER


def test_eval_prints_the_tables_and_writes_the_report(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    report = tmp_path / "EVALUATION.md"
    code = main(
        [
            "eval",
            "--resolver",
            "rules",
            "--limit",
            "6",
            "--no-retrieval",
            "--no-progress",
            "--write",
            str(report),
        ]
    )
    out, err = capsys.readouterr()
    assert code == 0, err
    assert "### Table I" in out and "### Table III" in out and "### Table II" in out
    assert "| Prompt type (n) | Paper: Few-shot / Finetuning / RAG / Hybrid | rules |" in out
    assert "Single-field detailed (2), accuracy" in out  # --limit 6 spreads over the types
    assert "100/100/97/98 %" in out
    assert "6 prompts (--limit 6)" in out
    assert "<details>" not in out  # failure lists only with --failures
    # The latency row of rules: first call timed in a new process, then in this one.
    assert re.search(r"\| rules \| \d+\.\d\d \| \d+\.\d\d \| ", out)
    text = report.read_text(encoding="utf-8")
    assert text.startswith("# Evaluation")
    assert BEGIN_MARKER in text and "### Table I" in text and "<details>" in text
    assert f"wrote {report}" in err


def test_eval_selects_by_category_and_lists_failures(
    capsys: pytest.CaptureFixture[str],
) -> None:
    code = main(
        [
            "eval",
            "--resolver",
            "rules",
            "--category",
            "invalid,typo",
            "--limit",
            "5",
            "--no-retrieval",
            "--no-progress",
            "--failures",
            "--no-fresh-process",
        ]
    )
    out, _ = capsys.readouterr()
    assert code == 0
    assert "categories invalid, typo" in out
    assert "Invalid prompts rejected with an `AgrirecipeError` (1)" in out
    assert "typos (4)" in out
    assert "<details><summary><b>rules</b>" in out


@pytest.mark.parametrize(
    ("arguments", "message"),
    [
        (["--resolver", "magic"], "unknown resolver strategy magic"),
        (["--category", "fruity"], "unknown prompt category fruity"),
        (["--limit", "0"], "--limit must be at least 1"),
        (["--benchmark", "/nonexistent/prompts.yaml"], "does not exist"),
    ],
)
def test_eval_rejects_bad_arguments_with_exit_code_2(
    arguments: list[str], message: str, capsys: pytest.CaptureFixture[str]
) -> None:
    code = main(["eval", "--no-retrieval", "--no-progress", "--no-fresh-process", *arguments])
    _, err = capsys.readouterr()
    assert code == 2
    assert message in err


def test_eval_selects_the_new_genre_and_geometry_tags(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    prompts = tmp_path / "genres.yaml"
    prompts.write_text(
        "version: 1\nsplit: heldout\ndefaults: {health: Healthy}\nprompts:\n"
        "- id: t-engineering-01\n  type: single_generic\n  tags: [engineering, geometry]\n"
        "  prompt: a 30 by 60 m Roma tomato field\n"
        "  fields: [{crop: Tomato, variety: Roma, size_m: [30, 60], rows: 999}]\n"
        "- id: t-photo-01\n  type: single_generic\n  tags: [photo, scenery]\n"
        "  prompt: a 30 by 60 m field of Roma tomatoes\n"
        "  fields: [{crop: Tomato}]\n"
        "- id: t-casual-01\n  type: single_generic\n  tags: [casual]\n"
        "  prompt: some apples\n  fields: [{crop: Apple}]\n",
        encoding="utf-8",
    )
    code = main(
        [
            "eval",
            "--resolver",
            "rules",
            "--benchmark",
            str(prompts),
            "--category",
            "engineering,photo",
            "--no-retrieval",
            "--no-progress",
            "--failures",
            "--no-fresh-process",
        ]
    )
    out, err = capsys.readouterr()
    assert code == 0, err
    assert "2 prompts (categories engineering, photo)" in out
    assert "`genres.yaml`" in out
    assert "| engineering requests (1) |" in out and "| stated geometry (1) |" in out
    assert "| photo descriptions (1) |" in out and "| casual text (" not in out
    assert "| phantom fields (recipe fields nobody asked for) |" in out
    assert "### Phantom fields per genre" in out
    # 999 rows cannot be what a 30 m wide field lays out: a geometry failure.
    assert "| wrong geometry (rows, spacing, density, direction) | 1 |" in out
    assert "geometry: rows " in out and "(expected 999)" in out


def test_eval_help_lists_the_new_tags(capsys: pytest.CaptureFixture[str]) -> None:
    with pytest.raises(SystemExit):
        main(["eval", "--help"])
    out, _ = capsys.readouterr()
    for tag in ("photo", "engineering", "casual", "farm", "geometry", "scenery", "cue"):
        assert tag in out
    assert "heldout/*.yaml" in out
