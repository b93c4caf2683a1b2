"""Pictures of crops in casual text ("fuji apples 🍎 rows 3.5m apart", "🍓 sonata + iceberg
🥬 lettuce"): read before the prompt is split into words (issue 8).

A picture drawn beside a word repeats it and is read as a space, so the words on each
side stay one phrase; beside a variety name that is also an everyday word ("sonata") it
names that name's crop. An emoji inside a word ("a straw🍓berry field") is no part of it.
The pictures and their crops are data (``data/casual.yaml``).
"""

from __future__ import annotations

import functools
import re
from typing import Any

from agrirecipe.resolve._lexicon import load_data, vocabulary

__all__ = ["read_pictures"]


def read_pictures(text: str) -> str:
    """``text`` with its emoji inside words dropped and its crop pictures read."""
    # "a straw🍓berry field": an emoji inside a word is not part of it
    text = _EMOJI_IN_WORD.sub("", text)
    # the text with every picture blanked out, once, at the same places
    plain = _crop_pictures().sub(lambda m: " " * len(m.group(0)), text)
    return _crop_pictures().sub(lambda m: _pictured_crop(plain, m), text)


_EMOJI_IN_WORD = re.compile(
    "(?<=[A-Za-z])[\U0001f000-\U0001faff\u2600-\u27bf\ufe0f\u200d]+(?=[A-Za-z])"
)


@functools.cache
def _crop_pictures() -> re.Pattern[str]:
    data: dict[str, Any] = load_data("casual.yaml")
    # (with the variation selector that asks for the colour form: "🌶️")
    return re.compile(f"[{re.escape(str(data['crop_pictures']))}]\ufe0f?")


@functools.cache
def _picture_crops() -> dict[str, str]:
    data: dict[str, Any] = load_data("casual.yaml")
    return {str(k): str(v) for k, v in data["picture_crops"].items()}


def _pictured_crop(plain: str, match: re.Match[str]) -> str:
    """What a crop picture reads as: its crop's word beside a variety name that is also an
    everyday word ("🍓 sonata"), when no word beside it names a crop; else a space.
    ``plain`` is the text with its pictures blanked out."""
    crop = _picture_crops().get(match.group(0)[0])
    if crop is None:
        return " "
    before = _WORDS_BEFORE.search(plain, 0, match.start())
    after = _WORDS_AFTER.match(plain, match.end())
    beside = [m.group("word").lower() for m in (before, after) if m is not None]
    weak = _weak_names()
    stem = crop[:-1] if crop.endswith("y") else crop
    if any(word in weak for word in beside) and not any(
        word.startswith(stem) or word in _CROP_WORDS for word in beside
    ):
        return f" {crop} "
    return " "


@functools.cache
def _weak_names() -> frozenset[str]:
    """Variety names that are also everyday words ("sonata", "cherry")."""
    return frozenset(str(w) for w in vocabulary()["weak_variety_words"])


#: The word right before / after a place in the text.
_WORDS_BEFORE = re.compile(r"(?P<word>[A-Za-z]+)\s*$")
_WORDS_AFTER = re.compile(r"\s*(?P<word>[A-Za-z]+)")
#: Words for crops beside a picture that its crop's word would repeat ("strawbs 🍓").
_CROP_WORDS = frozenset({"strawbs", "strawberries", "berries", "toms", "spuds", "corn", "chillies"})
