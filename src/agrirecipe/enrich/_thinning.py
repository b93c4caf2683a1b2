"""Dense fields thinned to fit the plant cap: every N-th plant drawn, each standing for N.

A whole drilled cereal field is millions of plants (winter wheat at 12.5 cm x 5 cm is
1.6 million per hectare): 20 ha of it is 31 million, more than a scene may hold
(``max_plants``, 10 million by default). Rather than refuse it, the densest fields -
those of more than :data:`DENSE_PLANTS_PER_HA` plants per hectare (cereals, carrots,
onions; never orchards, vineyards or plantations) - draw every N-th planting position
along each row, the same smallest N for all of them (at most
:data:`~agrirecipe.recipe.MAX_PLANTS_PER_INSTANCE`), and record it as
``placement.plants_per_instance``. The field keeps its stated agronomy (spacings,
density, rows) and its area; every engine, plants.csv and the annotations draw and
count the thinned positions, and the recipe carries a warning saying so and how to
draw every plant (raise ``max_plants``). A scene that does not fit even so is refused
with the cap, saying how much of the field fits drawn that sparsely.
"""

from __future__ import annotations

from collections.abc import Sequence

from agrirecipe.recipe import MAX_PLANTS_PER_INSTANCE, FieldSpec

__all__ = ["DENSE_PLANTS_PER_HA", "thin_to_fit"]

#: Fields denser than this (plants per hectare) may be thinned; sparser ones never are.
DENSE_PLANTS_PER_HA = 250_000


def thin_to_fit(fields: Sequence[FieldSpec], cap: int) -> tuple[list[FieldSpec], list[str]]:
    """``fields`` with their densest ones thinned so the scene draws at most ``cap``
    plants, and a warning per thinned field; unchanged when they fit."""
    if sum(f.drawn_plant_count() for f in fields) <= cap:
        return list(fields), []
    dense = {index for index, spec in enumerate(fields) if _dense(spec)}
    if not dense:
        return list(fields), []
    for stride in range(2, MAX_PLANTS_PER_INSTANCE + 1):
        drawn = sum(
            spec.drawn_plant_count(stride if index in dense else 1)
            for index, spec in enumerate(fields)
        )
        if drawn <= cap:
            break
    # (still too many at the sparsest drawing: the recipe's own check refuses it, saying
    # how much of the field fits drawn so)
    thinned: list[FieldSpec] = []
    warnings: list[str] = []
    for index, spec in enumerate(fields):
        if index not in dense:
            thinned.append(spec)
            continue
        placement = spec.placement.model_copy(update={"plants_per_instance": stride})
        thinned.append(spec.model_copy(update={"placement": placement}))
        warnings.append(
            f"{spec.id}: {spec.nominal_plant_count:,} plants are more than the scene may draw "
            f"(max_plants {cap:,}), so every {_ordinal(stride)} plant along each row is drawn, "
            f"each standing for {stride} ({thinned[-1].drawn_plant_count():,} drawn); the "
            "stated spacings and density are kept in the recipe. Raise max_plants "
            "(generate(..., max_plants=N), --max-plants N) to draw every plant"
        )
    return thinned, warnings


def _dense(spec: FieldSpec) -> bool:
    if spec.geometry.plant_count is not None:
        return False  # a stated count of plants is drawn whole
    width, length = spec.geometry.size_m
    return spec.nominal_plant_count / max(width * length / 10_000.0, 1e-9) > DENSE_PLANTS_PER_HA


def _ordinal(number: int) -> str:
    return {2: "second", 3: "third", 4: "fourth", 5: "fifth", 6: "sixth", 7: "seventh"}.get(
        number, f"{number}th"
    )
