"""A variety named again by its first word (issue 8).

"pinot nero & cabernet, 1ha each, pinot north", "Cripps Pink and Gala, the cripps
flowering": after a variety of two or more words is named, its first word alone, when
that word names nothing by itself, is the same variety said short.
:func:`name_short_forms` writes it out in full before the prompt is read.
"""

from __future__ import annotations

import re
from collections.abc import Callable, Iterable, Sequence

from agrirecipe.resolve._lexicon import Item

__all__ = ["name_short_forms"]


def name_short_forms(text: str, names: Iterable[str], tag: Callable[[str], Sequence[Item]]) -> str:
    """``text`` with the first word of a variety of several words (``names``: the
    hierarchy's variety names and aliases), said alone after the full name, written as
    the full name; only where that word alone is unknown to the reader."""
    for name in sorted({n for n in names if len(n.split()) >= 2}, key=len, reverse=True):
        said = re.search(rf"(?<![\w-]){re.escape(name)}(?![\w-])", text, re.IGNORECASE)
        if said is None:
            continue
        first, second = name.split()[:2]
        if any(item.senses for item in tag(first)):
            continue  # ("Red Baron ..., red onions": a word of its own)
        alone = re.compile(
            rf"(?<![\w-]){re.escape(first)}(?![\w-])(?!\s+{re.escape(second)}(?![\w-]))",
            re.IGNORECASE,
        )
        head, rest = text[: said.end()], text[said.end() :]
        text = head + alone.sub(name, rest)
    return text
