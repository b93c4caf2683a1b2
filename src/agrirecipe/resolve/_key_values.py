"""Requests written as settings (issue 8): "crop=lettuce var=Iceberg rows=30
row_spacing=0.35m in_row=0.30m | crop=lettuce var=Lollo Rosso ...".

Engineers paste a field's parameters as ``key=value`` pairs. :func:`read_key_values`
writes each known key (``key_values`` in ``data/casual.yaml``: the key and the words its
value is said in) as the plain words the reader takes ("lettuce Iceberg 30 rows, rows
0.35 m apart, plants 0.30 m apart"), and a bar between two fields as a semicolon. A key
it does not know is left as written (its words are listed as not used).
"""

from __future__ import annotations

import functools
import re
from typing import Any

from agrirecipe.resolve._lexicon import load_data

__all__ = ["read_key_values"]

#: One ``key=value`` pair; the value runs to the next pair, a bar, a semicolon or a comma.
_PAIR = re.compile(
    r"(?<![\w=])(?P<key>[A-Za-z][A-Za-z_-]*)(?P<eq>\s*=\s*)(?P<value>[^|;,=\n]+?)"
    r"(?=\s+[A-Za-z][A-Za-z_-]*\s*=|\s*[|;,\n]|\s*$)"
)
#: A bar between the settings of two fields.
_BAR = re.compile(r"\s*\|\s*")


@functools.cache
def _templates() -> dict[str, str]:
    data: dict[str, Any] = load_data("casual.yaml")
    return {
        _key(str(key)): str(words) for words, keys in data["key_values"].items() for key in keys
    }


def _key(word: str) -> str:
    return re.sub(r"[\s_-]+", "_", word.strip().lower())


def read_key_values(text: str) -> str:
    """``text`` with its known ``key=value`` settings written as words (see the module)."""
    templates = _templates()
    said = 0

    def words(match: re.Match[str]) -> str:
        nonlocal said
        template = templates.get(_key(match.group("key")))
        if template is None or (
            # (a count's noun before a spaced "=" is a sum: "12 rows x 30 trees = 360 trees")
            match.group("eq").strip() != match.group("eq")
            and re.search(r"\d\s+$", match.string[: match.start()])
        ):
            return match.group(0)
        said += 1
        return template.replace("{}", match.group("value").strip()) + ","

    written = _PAIR.sub(words, text)
    # (settings come several together; one "x = y" alone is left to the reader, and a
    # bar parts the fields the settings describe)
    return _BAR.sub("; ", written) if said >= 2 else text
