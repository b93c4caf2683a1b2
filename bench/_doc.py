"""The shared part of every benchmark: its section of docs/PERFORMANCE.md."""

from __future__ import annotations

from pathlib import Path

REPO = Path(__file__).resolve().parent.parent
DOC = REPO / "docs" / "PERFORMANCE.md"
HEADER = (
    "# Performance\n\n"
    "Measured numbers, written by the benchmark scripts in `bench/`. Re-run a script to\n"
    "refresh its section; each script only replaces the text between its own markers.\n\n"
)


def update_doc(section: str, start: str, end: str, doc: Path = DOC) -> None:
    """Replace the text between ``start`` and ``end`` in ``doc`` with ``section``
    (which carries both markers); append it the first time."""
    text = doc.read_text(encoding="utf-8") if doc.exists() else HEADER
    if start in text and end in text:
        before, rest = text.split(start, 1)
        after = rest.split(end, 1)[1].lstrip("\n")
        text = before + section + ("\n" + after if after else "")
    else:
        text = text.rstrip("\n") + "\n\n" + section
    doc.parent.mkdir(parents=True, exist_ok=True)
    doc.write_text(text, encoding="utf-8")
