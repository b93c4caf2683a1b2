"""Members listed after the plural mention that announced them (resolve/_listed_members.py)."""

from __future__ import annotations

import pytest

from agrirecipe import PromptError, generate
from agrirecipe.resolve._listed_members import fits
from agrirecipe.resolve._mentions import Mention


def _fields(prompt: str) -> list[tuple[str | None, str]]:
    return [(f.crop, f.health) for f in generate(prompt, resolver="hybrid").recipe.fields]


def test_more_members_than_announced_is_refused_with_the_counts() -> None:
    with pytest.raises(PromptError, match="announces 2 field"):
        generate("two fields: sweetcorn, durum wheat and romaine lettuce")


def test_a_share_of_them_is_that_many_members() -> None:
    fields = _fields("four potato fields, two of them blighted")
    assert [health for _, health in fields] == ["Ill", "Ill", "Healthy", "Healthy"]


def test_the_member_at_a_place_holds_the_ones_before_it_open() -> None:
    fields = _fields("Three potato fields in a line. The middle one has blight")
    assert [health for _, health in fields] == ["Healthy", "Ill", "Healthy"]


def test_a_vague_number_of_fields_is_as_many_as_listed() -> None:
    fields = _fields("some veg fields, three of them, all young")
    assert len(fields) == 3


def test_a_member_of_another_category_does_not_fit() -> None:
    crop_categories = {"Apple": "Fruits", "Wheat": "Cereals", "Maize": "Cereals"}
    parent = Mention(category="Cereals")
    assert fits(Mention(category="Cereals"), parent, crop_categories)
    assert not fits(Mention(category="Fruits"), parent, crop_categories)
    # a mention naming no crop describes any member
    assert fits(Mention(), parent, crop_categories)
