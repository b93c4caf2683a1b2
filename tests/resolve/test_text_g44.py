"""Text of blind set g44 (issue 8), the misses fixed so far: plots "arranged 2 by 2", and
bulk boxes and a grader as scenery."""

from __future__ import annotations

import pytest

from agrirecipe import generate


def test_plots_arranged_two_by_two() -> None:
    recipe = generate(
        "Four 25 x 25 m plots for drone altitude calibration, arranged 2 by 2: wheat in the NW "
        "corner, maize NE, potatoes SW, carrots SE."
    ).recipe
    assert [f.crop for f in recipe.fields] == ["Wheat", "Maize", "Potato", "Carrot"]
    assert all(f.geometry.size_m == pytest.approx((25.0, 25.0)) for f in recipe.fields)
    relations = {(r.kind, r.subject, r.objects) for r in recipe.relations}
    assert ("north_of", "wheat_plot_1", ("potato_plot_1",)) in relations
    assert ("west_of", "wheat_plot_1", ("maize_plot_1",)) in relations


def test_boxes_and_a_grader_are_scenery_not_unknown_crops() -> None:
    # (refused as the unknown crop "boxes" before; the phantom field "at the top of the
    # shot" still adds is left for the next round)
    recipe = generate(
        "the onion field, tops flattened and drying off, ready for lifting; the grader and "
        "big boxes stand at the top of the shot."
    ).recipe
    assert recipe.fields[0].crop == "Onion"
    assert recipe.fields[0].stage == "Maturation"
