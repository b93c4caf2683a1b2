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
