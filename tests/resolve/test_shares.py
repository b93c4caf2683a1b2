"""Parts of a whole said in words, written plainly (resolve/_shares.py)."""

from __future__ import annotations

import pytest

from agrirecipe.resolve._shares import read_shares


@pytest.mark.parametrize(
    ("said", "plain"),
    [
        (
            "two maize plots, 9 plants/m2 in one and 7 plants/m2 in the other",
            "two maize plots, one with 9 plants/m2 and the other with 7 plants/m2",
        ),
        (
            "two potato fields, blight in one and none in the other",
            "two potato fields, one with blight and the other with none",
        ),
        (
            "two plots: 2.5 m rows in one plot, 3 m rows in the other plot",
            "two plots: one with 2.5 m rows and the other with 3 m rows",
        ),
    ],
)
def test_what_each_of_two_has(said: str, plain: str) -> None:
    assert read_shares(said) == plain


def test_one_alone_is_left_as_said() -> None:
    assert read_shares("blight in one field") == "blight in one field"


@pytest.mark.parametrize(
    ("said", "plain"),
    [
        (
            "hamlin & valencia oranges, 2 groves, one has greening... the hamlin one",
            "hamlin & valencia oranges, 2 groves, the hamlin one has greening",
        ),
        (
            "two fields, one has blight - its the bintje one",
            "two fields, the bintje one has blight",
        ),
        # the other one, and "one" inside "the near one", are left as said
        (
            "two fields - one has late blight, the other one is clean",
            "two fields - one has late blight, the other one is clean",
        ),
        (
            "the near one has downy mildew, the far one is fine",
            "the near one has downy mildew, the far one is fine",
        ),
    ],
)
def test_a_look_said_of_one_then_which(said: str, plain: str) -> None:
    assert read_shares(said) == plain
