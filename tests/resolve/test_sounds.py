"""The sound-alike key of words spelt by ear (resolve/_sounds.py)."""

from __future__ import annotations

import pytest

from agrirecipe.resolve._sounds import sound_key


@pytest.mark.parametrize(
    ("said", "known"),
    [("lettus", "lettuce"), ("tomatos", "tomatoes"), ("fillips", "philips"), ("kabage", "cabbage")],
)
def test_words_spelt_by_ear_sound_alike(said: str, known: str) -> None:
    assert sound_key(said) == sound_key(known)


@pytest.mark.parametrize(("one", "other"), [("canes", "cayenne"), ("carrot", "cherry")])
def test_other_words_do_not(one: str, other: str) -> None:
    assert sound_key(one) != sound_key(other)
