"""Plural and singular word forms (resolve._lexicon)."""

from __future__ import annotations

import pytest

from agrirecipe.resolve._lexicon import plurals, singular


@pytest.mark.parametrize(
    ("word", "plural"),
    [
        ("potato", "potatoes"),
        ("strawberry", "strawberries"),
        ("tunnel", "tunnels"),
        ("glasshouse", "glasshouses"),
        ("peach", "peaches"),
        ("lettuce", "lettuces"),
    ],
)
def test_singular_undoes_plurals(word: str, plural: str) -> None:
    assert plural in plurals(word)
    assert singular(plural) == word


@pytest.mark.parametrize("word", ["grass", "maize", "wheat", "is", "gas"])
def test_a_word_that_is_no_plural_stays(word: str) -> None:
    assert singular(word) == word
