"""The model's answers read back: field intents, sizes and relations."""

from __future__ import annotations

import re
from collections.abc import Mapping, Sequence
from typing import TYPE_CHECKING, Any

from agrirecipe._errors import PromptError
from agrirecipe.resolve._grammar import ANY_PREFIX, NONE, OTHER
from agrirecipe.resolve._intent import FieldIntent, RelationIntent, SizeIntent
from agrirecipe.resolve.llm._checks import _check_contradiction, _unknown
from agrirecipe.resolve.llm._evidence import _Evidence
from agrirecipe.resolve.llm._examples import _STATE_KEYS
from agrirecipe.resolve.llm._parts import _Part

if TYPE_CHECKING:
    from agrirecipe.hierarchy import Hierarchy


def _field_intents(
    values: Mapping[str, str], part: _Part, evidence: _Evidence, hierarchy: Hierarchy
) -> list[FieldIntent]:
    """Validate a part's record and turn it into one FieldIntent per counted field."""
    crop = values["crop"]
    if crop == OTHER:
        name = values.get("name") or part.text
        nearest = evidence.other.get(name) or next(iter(evidence.other.values()), ())
        raise _unknown(name, nearest, hierarchy)
    count = int(values.get("count", "1"))
    states: dict[str, Any] = {
        key: None if values.get(key, NONE) == NONE else values[key] for key in _STATE_KEYS
    }
    per_field = [
        {
            key: values[f"{key} per field"].split("|")[index]
            for key in _STATE_KEYS
            if f"{key} per field" in values
        }
        for index in range(count)
    ]
    size = _parse_size(values.get("size", NONE), evidence)
    if crop.startswith(ANY_PREFIX):
        category = crop[len(ANY_PREFIX) :]
        options = tuple(c for c in evidence.plot_options if hierarchy.crops[c].category == category)
        distinct = values.get("different") == "yes" and count > 1
        return [
            FieldIntent(
                text=part.raw,
                mention=evidence.categories.get(category),
                noun=evidence.noun,
                category=category,
                generic=True,
                crop_options=options,
                distinct_group=0 if distinct else None,
                size=size,
                **{**states, **per_field[index]},
            )
            for index in range(count)
        ]
    variety = values.get("variety", NONE)
    _check_contradiction(crop, variety, evidence, part)
    distinct = evidence.distinct and count > 1
    if distinct and evidence.categories and variety == NONE:
        # "three different fruit crops, all of them apples"
        raise PromptError(
            f"{part.raw!r} asks for {count} different crops, but names only {crop}",
            stage="resolve",
            hint="name a different crop for each field, or drop 'different' to have "
            f"several {crop.lower()} fields",
        )
    mention = evidence.varieties.get((crop, variety)) or evidence.crops.get(crop)
    return [
        FieldIntent(
            text=part.raw,
            mention=mention,
            noun=evidence.noun,
            crop=crop,
            variety=None if variety == NONE else variety,
            size=size,
            # "two different apple orchards": different varieties of the crop
            distinct_group=0 if distinct else None,
            **{**states, **per_field[index]},
        )
        for index in range(count)
    ]


def _parse_size(answer: str, evidence: _Evidence) -> SizeIntent | None:
    """``"50 x 100 m"`` or ``"2 ha"`` (numbers and units are the part's own words)."""
    if not answer or answer == NONE:
        return None
    *numbers_text, unit = answer.split(" ")
    kind, factor = evidence.units.get(unit, ("length_unit", 1.0))
    try:
        numbers = [float(t) for t in numbers_text if t != "x"]
    except ValueError:
        return None  # not a size the words state; the grammar only offers those
    if any(n <= 0 for n in numbers):
        raise PromptError(
            f"a field cannot measure {answer}", stage="resolve", hint="sizes must be positive"
        )
    if len(numbers) == 2 and kind == "length_unit":
        return SizeIntent(width_m=numbers[0] * factor, length_m=numbers[1] * factor, text=answer)
    if len(numbers) == 1 and kind == "area_unit":
        return SizeIntent(area_m2=numbers[0] * factor, text=answer)
    return None


def _parse_relations(
    answer: str, first_field: Sequence[int], kinds: Sequence[str]
) -> list[RelationIntent]:
    """``"1 next to 2, 3 between 1 and 2"`` -> relations between the parts' first fields."""
    relations: list[RelationIntent] = []
    for piece in answer.strip().split(", "):
        between = re.fullmatch(r"(\d) between (\d) and (\d)", piece)
        if between:
            subject, *objects = (first_field[int(g) - 1] for g in between.groups())
            if len({subject, *objects}) == 3:
                relations.append(
                    RelationIntent(
                        kind="between", subject=subject, objects=tuple(objects), text=piece
                    )
                )
            continue
        match = re.fullmatch(r"(\d) ([a-z ]+) (\d)", piece)
        if match is None:
            continue
        kind = match.group(2).replace(" ", "_")
        subject, target = (first_field[int(match.group(i)) - 1] for i in (1, 3))
        if kind in kinds and subject != target:
            relations.append(
                RelationIntent.model_validate(
                    {"kind": kind, "subject": subject, "objects": (target,), "text": piece}
                )
            )
    return relations


def _between_counted(
    scene: _Evidence,
    relations: Sequence[RelationIntent],
    first_field: Sequence[int],
    field_count: int,
) -> list[RelationIntent]:
    """ "A between two fields of B": one part counted twice holds both sides."""
    if "between" not in scene.relations or any(r.kind == "between" for r in relations):
        return []
    if len(first_field) != 2:
        return []
    ends = [*first_field[1:], field_count]
    sizes = [end - start for start, end in zip(first_field, ends, strict=True)]
    if sorted(sizes) != [1, 2]:
        return []
    single = first_field[sizes.index(1)]
    pair = first_field[sizes.index(2)]
    return [RelationIntent(kind="between", subject=single, objects=(pair, pair + 1))]
