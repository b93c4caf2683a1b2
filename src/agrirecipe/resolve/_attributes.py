"""A field's stated attributes from its words: one value each, or a contradiction.

Months become seasons for the hemisphere; an "Ill" word right after a negation
("no blight", "free of scab") is "Healthy"; two different values for one field
("young ripe carrots", "in summer and winter") are a :class:`~agrirecipe.PromptError`.
"""

from __future__ import annotations

from collections.abc import Sequence

from agrirecipe._errors import PromptError
from agrirecipe.recipe import HealthState, Season
from agrirecipe.resolve._intent import Hemisphere, SizeIntent
from agrirecipe.resolve._lexicon import Item, vocabulary

__all__ = ["health_of", "month_season", "single_size", "single_value", "values_of"]


def month_season(month: int, hemisphere: Hemisphere | None) -> Season:
    table = vocabulary()["month_seasons_north"]
    season: Season = next(s for s, months in table.items() if month in months)
    if hemisphere == "south":
        season = {"Spring": "Fall", "Summer": "Winter", "Fall": "Spring", "Winter": "Summer"}[
            season
        ]  # type: ignore[assignment]
    return season


def values_of(
    items: Sequence[Item], roles: tuple[str, ...], hemisphere: Hemisphere | None
) -> list[str]:
    values: list[str] = []
    for item in items:
        if item.role not in roles or item.data.get("negated"):
            continue  # "no flowers yet", "not in ear yet": not that stage
        if item.role == "month":
            values.append(month_season(int(item.data["value"]), hemisphere))
        else:
            values.append(str(item.data["value"]))
    return values


def single_value(
    items: Sequence[Item],
    roles: tuple[str, ...],
    attribute: str,
    text: str,
    hemisphere: Hemisphere | None,
) -> str | None:
    values = values_of(items, roles, hemisphere)
    distinct = sorted(set(values))
    if attribute == "stage" and distinct == ["Maturation", "Reproductive"]:
        distinct = _fruit_that_ripens(items, roles) or distinct
    if len(distinct) > 1:
        words = [i.raw for i in items if i.role in roles]
        raise PromptError(
            f"{text!r} is said to be both " + " and ".join(distinct) + f" ({', '.join(words)})",
            stage="resolve",
            hint=f"a field has one {attribute}; describe different fields separately",
        )
    return distinct[0] if distinct else None


def _fruit_that_ripens(items: Sequence[Item], roles: tuple[str, ...]) -> list[str]:
    """``["Maturation"]`` when every Reproductive word only says fruit is on the plant
    ("all fruiting and starting to ripen": the fruit ripens), else nothing."""
    bearing = {" ".join(w.split()) for w in vocabulary()["fruit_bearing_words"]}
    reproductive = [
        i
        for i in items
        if i.role in roles and not i.data.get("negated") and i.data.get("value") == "Reproductive"
    ]
    if all(" ".join(i.raw.lower().split()) in bearing for i in reproductive):
        return ["Maturation"]
    return []


def health_of(items: Sequence[Item], text: str) -> HealthState | None:
    ordered = sorted(items, key=lambda item: item.start)
    values: list[HealthState] = []
    vigour = {str(w) for w in vocabulary()["vigour_words"]}
    only_vigour = True  # every Healthy word only says the plants grow well ("lush")
    for index, item in enumerate(ordered):
        if item.role != "health":
            continue
        value: HealthState = item.data["value"]
        negated = index > 0 and ordered[index - 1].role == "negation"
        if negated:
            value = "Healthy"
        if value == "Healthy" and (negated or item.norm not in vigour):
            only_vigour = False
        values.append(value)
    distinct: list[HealthState] = sorted(set(values))
    if len(distinct) > 1 and only_vigour:
        return "Ill"  # "Lush and dark green, with a bit of yellow rust on the lower leaves"
    if len(distinct) > 1:
        words = [i.raw for i in ordered if i.role == "health"]
        raise PromptError(
            f"{text!r} is said to be both healthy and ill ({', '.join(words)})",
            stage="resolve",
            hint="a field is either healthy or ill; describe different fields separately",
        )
    return distinct[0] if distinct else None


def single_size(sizes: Sequence[SizeIntent], text: str) -> SizeIntent | None:
    unique = {(s.width_m, s.length_m, s.area_m2): s for s in sizes}
    if len(unique) > 1:
        raise PromptError(
            f"{text!r} is given two sizes: " + " and ".join(s.text for s in unique.values()),
            stage="resolve",
            hint="give one size per field",
        )
    return next(iter(unique.values()), None)
