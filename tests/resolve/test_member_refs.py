"""Members of a counted plural said by their place (resolve/_member_refs.py)."""

from __future__ import annotations

import pytest

from agrirecipe.resolve._decompose import Mention
from agrirecipe.resolve._lexicon import Item, Token
from agrirecipe.resolve._member_refs import place_said


def _reference(words: str) -> Item:
    tokens = tuple(Token(w, w, i, i + 1) for i, w in enumerate(words.split()))
    return Item(tokens=tokens, senses=(), role="reference")


@pytest.mark.parametrize(
    ("words", "count", "expected"),
    [
        ("the middle one", 3, 1),
        ("the middle one", 5, 2),
        ("the middle one", 4, None),  # (no middle of an even count)
        ("the second one", 3, 1),
        ("the last one", 4, 3),
        ("the fourth one", 3, None),  # (past the count)
    ],
)
def test_a_member_said_by_its_place(words: str, count: int, expected: int | None) -> None:
    assert place_said(_reference(words), Mention(count=count)) == expected


def test_a_place_already_said_is_not_said_again() -> None:
    parent = Mention(count=3, refinements=[Mention(), Mention()])
    assert place_said(_reference("the second one"), parent) is None
    parent.refinements[1].unsaid = True
    assert place_said(_reference("the second one"), parent) == 1
