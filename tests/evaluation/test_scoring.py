"""Scoring a prompt's outcome: field matching, counts, relations, sizes, invalid prompts."""

from __future__ import annotations

import itertools
from dataclasses import replace

import pytest
from evaluation_helpers import field, make_prompt, scene
from hypothesis import given, settings
from hypothesis import strategies as st

from agrirecipe import AgrirecipeError, PromptError, UnknownCropError
from agrirecipe.evaluation import PredictedRelation, optimal_assignment, score_prompt

GALA = {"crop": "Apple", "variety": "Gala", "stage": "Reproductive", "season": "Spring"}


def test_exact_single_field_is_correct() -> None:
    item = make_prompt(type="single_detailed", fields=[GALA])
    result = score_prompt(item, scene(field("Apple", "Gala", "Reproductive", "Spring")))
    assert result.correct
    assert result.reasons == ()
    assert (result.true_positives, result.predicted_fields, result.truth_fields) == (1, 1, 1)


@pytest.mark.parametrize(
    ("predicted", "kind"),
    [
        (field("Apple", "Fuji", "Reproductive", "Spring"), "variety"),
        (field("Pear", "Conference", "Reproductive", "Spring"), "crop"),
        (field("Apple", "Gala", "Maturation", "Spring"), "stage"),
        (field("Apple", "Gala", "Reproductive", "Fall"), "season"),
        (field("Apple", "Gala", "Reproductive", "Spring", "Ill"), "health"),
    ],
)
def test_every_stated_attribute_is_checked(predicted: object, kind: str) -> None:
    item = make_prompt(type="single_detailed", fields=[GALA])
    result = score_prompt(item, scene(predicted))  # type: ignore[arg-type]
    assert not result.correct
    assert kind in result.kinds
    assert any(kind in reason for reason in result.reasons)
    assert result.true_positives == 0


def test_unstated_health_defaults_to_healthy_and_unstated_stage_is_open() -> None:
    item = make_prompt(type="single_generic", fields=[{"crop": "Apple"}])
    assert item.fields[0].health == ("Healthy",)
    assert item.fields[0].inferred == ("health",)
    assert score_prompt(item, scene(field("Apple", "Fuji", "Maturation", "Winter"))).correct
    assert not score_prompt(item, scene(field("Apple", "Fuji", health="Ill"))).correct


def test_any_of_values_and_category_from_the_crop() -> None:
    item = make_prompt(type="single_generic", fields=[{"crop": ["Apple", "Pear", "Cherry"]}])
    assert item.fields[0].category == ("Fruits",)
    assert score_prompt(item, scene(field("Cherry", "Bing"))).correct
    assert not score_prompt(item, scene(field("Grape", "Riesling"))).correct


def test_matching_is_order_insensitive_and_optimal_not_greedy() -> None:
    # Greedy would give the open apple field the Gala apple first and leave the
    # Gala truth unmatched; the optimal assignment pairs both.
    item = make_prompt(
        type="multi_generic", fields=[{"crop": "Apple"}, {"crop": "Apple", "variety": "Gala"}]
    )
    outcome = scene(field("Apple", "Gala"), field("Apple", "Fuji"))
    result = score_prompt(item, outcome)
    assert result.correct, result.reasons
    assert result.true_positives == 2


def test_an_extra_field_costs_precision_and_a_missing_one_recall() -> None:
    item = make_prompt(
        type="multi_detailed",
        fields=[{"crop": "Apple", "variety": "Gala"}, {"crop": "Pear", "variety": "Conference"}],
    )
    extra = score_prompt(
        item, scene(field("Apple", "Gala"), field("Pear", "Conference"), field("Cherry", "Bing"))
    )
    assert not extra.correct
    assert "count" in extra.kinds
    assert (extra.true_positives, extra.predicted_fields, extra.truth_fields) == (2, 3, 2)
    missing = score_prompt(item, scene(field("Apple", "Gala")))
    assert not missing.correct
    assert (missing.true_positives, missing.predicted_fields, missing.truth_fields) == (1, 1, 2)
    assert any("missing" in reason for reason in missing.reasons)


def test_open_count_accepts_extra_fields_that_fit() -> None:
    item = make_prompt(
        type="multi_generic",
        fields=[{"category": "Fruits"}, {"category": "Vegetables"}],
        field_count={"min": 2, "max": 4},
        extra_field={"category": ["Fruits", "Vegetables"]},
    )
    three = scene(field("Apple", "Gala"), field("Carrot", "Nantes"), field("Pear", "Conference"))
    result = score_prompt(item, three)
    assert result.correct, result.reasons
    assert result.true_positives == 3
    with_cereal = scene(field("Apple", "Gala"), field("Carrot", "Nantes"), field("Wheat", "Spelt"))
    assert not score_prompt(item, with_cereal).correct
    too_many = scene(
        *(field("Apple", v) for v in ("Gala", "Fuji", "Jonagold")),
        field("Carrot", "Nantes"),
        field("Potato", "Agria"),
    )
    assert not score_prompt(item, too_many).correct


def test_distinct_crops() -> None:
    item = make_prompt(
        type="multi_generic", distinct_crops=True, fields=[{"category": "Vegetables"}] * 2
    )
    assert score_prompt(item, scene(field("Carrot", "Nantes"), field("Onion", "Sturon"))).correct
    same = score_prompt(item, scene(field("Carrot", "Nantes"), field("Carrot", "Danvers")))
    assert not same.correct
    assert same.kinds == ("distinct",)


def _two_fields_with(relation: dict[str, object]) -> object:
    return make_prompt(
        type="multi_detailed",
        fields=[
            {"ref": "orchard", "crop": "Apple", "variety": "Gala"},
            {"ref": "potatoes", "crop": "Potato", "variety": "Bintje"},
        ],
        relations=[relation],
    )


@pytest.mark.parametrize(
    ("truth", "predicted", "ok"),
    [
        ("north_of", PredictedRelation("north_of", "orchard_1", ("potatoes_1",)), True),
        ("north_of", PredictedRelation("south_of", "potatoes_1", ("orchard_1",)), True),
        ("north_of", PredictedRelation("south_of", "orchard_1", ("potatoes_1",)), False),
        ("north_of", PredictedRelation("next_to", "orchard_1", ("potatoes_1",)), False),
        ("next_to", PredictedRelation("next_to", "potatoes_1", ("orchard_1",)), True),
        ("east_of", PredictedRelation("west_of", "potatoes_1", ("orchard_1",)), True),
        ("west_of", PredictedRelation("west_of", "potatoes_1", ("orchard_1",)), False),
    ],
)
def test_relations_compare_up_to_symmetry(
    truth: str, predicted: PredictedRelation, ok: bool
) -> None:
    item = _two_fields_with({"kind": truth, "subject": "orchard", "objects": ["potatoes"]})
    outcome = scene(
        field("Potato", "Bintje", field_id="potatoes_1"),
        field("Apple", "Gala", field_id="orchard_1"),
        relations=(predicted,),
    )
    result = score_prompt(item, outcome)  # type: ignore[arg-type]
    assert result.correct is ok, result.reasons
    if not ok:
        assert result.kinds == ("relation",)


def test_between_objects_in_any_order_and_a_missing_relation_fails() -> None:
    item = make_prompt(
        type="multi_detailed",
        fields=[
            {"ref": "mid", "crop": "Strawberry", "variety": "Elsanta"},
            {"ref": "a", "crop": "Lettuce", "variety": "Iceberg"},
            {"ref": "b", "crop": "Carrot", "variety": "Nantes"},
        ],
        relations=[{"kind": "between", "subject": "mid", "objects": ["a", "b"]}],
    )
    fields = (
        field("Carrot", "Nantes", field_id="c"),
        field("Lettuce", "Iceberg", field_id="l"),
        field("Strawberry", "Elsanta", field_id="s"),
    )
    between = PredictedRelation("between", "s", ("c", "l"))
    assert score_prompt(item, scene(*fields, relations=(between,))).correct
    assert not score_prompt(item, scene(*fields)).correct


def test_interchangeable_fields_are_told_apart_by_the_relations() -> None:
    # "two veg plots, each 20 rows at 50 cm, one directly north of the other": either
    # recipe field matches either truth field, and the relation says which is which
    item = make_prompt(
        type="multi_generic",
        fields=[{"ref": "north", "crop": "Potato"}, {"ref": "south", "crop": "Potato"}],
        relations=[{"kind": "north_of", "subject": "north", "objects": ["south"]}],
    )
    fields = (field("Potato", "Agria", field_id="p1"), field("Potato", "Agria", field_id="p2"))
    for subject, other in (("p1", "p2"), ("p2", "p1")):
        placed = PredictedRelation("north_of", subject, (other,))
        assert score_prompt(item, scene(*fields, relations=(placed,))).correct
    # ... but a relation still has to be there, and fields that differ are not swapped
    assert not score_prompt(item, scene(*fields)).correct
    told = make_prompt(
        type="multi_detailed",
        fields=[
            {"ref": "north", "crop": "Potato", "variety": "Agria"},
            {"ref": "south", "crop": "Potato", "variety": "Bintje"},
        ],
        relations=[{"kind": "north_of", "subject": "north", "objects": ["south"]}],
    )
    apart = (field("Potato", "Agria", field_id="a"), field("Potato", "Bintje", field_id="b"))
    reversed_ = PredictedRelation("north_of", "b", ("a",))
    assert not score_prompt(told, scene(*apart, relations=(reversed_,))).correct


def test_sizes_are_unordered_within_one_percent_and_areas_are_checked() -> None:
    item = make_prompt(type="single_generic", fields=[{"crop": "Potato", "size_m": [50, 100]}])
    assert score_prompt(item, scene(field("Potato", "Agria", size_m=(100.0, 50.0)))).correct
    assert score_prompt(item, scene(field("Potato", "Agria", size_m=(50.4, 99.6)))).correct
    wrong = score_prompt(item, scene(field("Potato", "Agria", size_m=(60.0, 100.0))))
    assert wrong.kinds == ("size",)
    area = make_prompt(type="single_generic", fields=[{"crop": "Apple", "area_m2": 20000}])
    assert score_prompt(area, scene(field("Apple", "Gala", size_m=(141.42, 141.42)))).correct
    assert not score_prompt(area, scene(field("Apple", "Gala", size_m=(100.0, 100.0)))).correct


def test_hemisphere_and_expected_warning() -> None:
    south = make_prompt(type="single_detailed", hemisphere="south", fields=[GALA])
    gala = field("Apple", "Gala", "Reproductive", "Spring")
    assert score_prompt(south, scene(gala, hemisphere="south")).correct
    assert score_prompt(south, scene(gala)).kinds == ("hemisphere",)
    warned = make_prompt(type="single_detailed", expect_warning=True, fields=[GALA])
    assert score_prompt(warned, scene(gala, warnings=("unusual",))).correct
    assert score_prompt(warned, scene(gala)).kinds == ("warning",)


def test_a_valid_prompt_that_raises_is_a_failure_with_the_error_recorded() -> None:
    item = make_prompt(type="single_detailed", fields=[GALA])
    rejected = score_prompt(item, PromptError("no crop found"))
    assert not rejected.correct
    assert rejected.kinds == ("rejected",)
    assert "no crop found" in rejected.got
    crashed = score_prompt(item, KeyError("crop"))
    assert crashed.kinds == ("foreign_error",)
    assert (crashed.true_positives, crashed.predicted_fields, crashed.truth_fields) == (0, 0, 1)


def test_invalid_prompts_must_raise_an_agrirecipe_error() -> None:
    item = make_prompt(type="invalid", prompt="a mango plantation", error="UnknownCropError")
    exact = score_prompt(item, UnknownCropError("mango is unknown", requested="mango"))
    assert exact.correct and exact.error_class_ok
    broader = score_prompt(item, PromptError("not a farm"))
    assert broader.correct and broader.error_class_ok is False
    root = make_prompt(type="invalid", prompt="a 0 m field", error="AgrirecipeError")
    assert score_prompt(root, PromptError("too small")).error_class_ok
    foreign = score_prompt(item, ValueError("mango"))
    assert not foreign.correct
    assert foreign.kinds == ("foreign_error",)
    assert "ValueError" in foreign.got
    accepted = score_prompt(item, scene(field("Orange", "Navel")))
    assert not accepted.correct
    assert accepted.kinds == ("accepted",)
    assert "Orange/Navel" in accepted.got
    assert issubclass(UnknownCropError, AgrirecipeError)


def test_inference_marking_counts_fields_that_call_unstated_attributes_inferred() -> None:
    item = make_prompt(type="single_generic", fields=[{"crop": "Apple", "season": "Summer"}])
    honest = field(
        "Apple", "Jonagold", stated=("crop", "season"), inferred=("variety", "stage", "health")
    )
    result = score_prompt(item, scene(honest))
    assert (result.inferred_checked, result.inferred_ok) == (1, 1)
    overclaiming = field("Apple", "Jonagold")  # says everything was stated
    result = score_prompt(item, scene(overclaiming))
    assert result.correct  # marking is reported separately, not part of correctness
    assert (result.inferred_checked, result.inferred_ok) == (1, 0)


def _brute_force(weights: list[list[float]]) -> float:
    rows, cols = len(weights), len(weights[0])
    if rows <= cols:
        return max(
            sum(weights[r][c] for r, c in enumerate(perm))
            for perm in itertools.permutations(range(cols), rows)
        )
    return max(
        sum(weights[r][c] for c, r in enumerate(perm))
        for perm in itertools.permutations(range(rows), cols)
    )


@settings(max_examples=150, deadline=None)
@given(
    st.integers(1, 5).flatmap(
        lambda rows: st.integers(1, 5).flatmap(
            lambda cols: st.lists(
                st.lists(st.integers(0, 120), min_size=cols, max_size=cols),
                min_size=rows,
                max_size=rows,
            )
        )
    )
)
def test_optimal_assignment_matches_brute_force(weights: list[list[int]]) -> None:
    matrix = [[float(w) for w in row] for row in weights]
    assignment = optimal_assignment(matrix)
    assert len(assignment) == len(matrix)
    chosen = [c for c in assignment if c is not None]
    assert len(chosen) == len(set(chosen)) == min(len(matrix), len(matrix[0]))
    total = sum(matrix[r][c] for r, c in enumerate(assignment) if c is not None)
    assert total == pytest.approx(_brute_force(matrix))


def test_optimal_assignment_of_nothing() -> None:
    assert optimal_assignment([]) == []
    assert optimal_assignment([[], []]) == [None, None]


# --- stated geometry (rows, spacings, density, direction) ---


@pytest.fixture(scope="module")
def roma() -> object:
    """The recipe of a real prompt, and its one field's spec."""
    import agrirecipe

    recipe = agrirecipe.generate("a 30 by 60 m Roma tomato field", seed=0).recipe
    assert len(recipe.fields) == 1
    return recipe


def _own_geometry(spec: object) -> dict[str, object]:
    """Every geometry key of the truth, computed from the field's own recipe values."""
    agronomy = spec.agronomy  # type: ignore[attr-defined]
    truth: dict[str, object] = {
        "rows": spec.row_count,  # type: ignore[attr-defined]
        "beds": spec.bed_count,  # type: ignore[attr-defined]
        "rows_per_bed": agronomy.rows_per_bed,
        "row_length_m": spec.row_length_m,  # type: ignore[attr-defined]
        "bed_width_m": agronomy.row_spacing_m,
        "in_row_spacing_m": agronomy.in_row_spacing_m,
        "plants_per_ha": spec.plants_per_ha,  # type: ignore[attr-defined]
        "plant_count": spec.nominal_plant_count,  # type: ignore[attr-defined]
        "headland_m": spec.geometry.headland_m,  # type: ignore[attr-defined]
        "row_bearing_deg": spec.row_bearing_deg,  # type: ignore[attr-defined]
    }
    truth["row_spacing_m"] = (
        agronomy.row_spacing_m if agronomy.rows_per_bed == 1 else agronomy.bed_row_spacing_m
    )
    return truth


def _roma_prompt(**geometry: object) -> object:
    return make_prompt(
        type="single_generic",
        fields=[{"crop": "Tomato", "variety": "Roma", "size_m": [30, 60], **geometry}],
    )


def test_a_recipe_whose_geometry_matches_every_stated_key_is_correct(roma: object) -> None:
    from agrirecipe.evaluation import GEOMETRY_KEYS, PredictedScene

    predicted = PredictedScene.from_recipe(roma)  # type: ignore[arg-type]
    spec = roma.fields[0]  # type: ignore[attr-defined]
    got = predicted.fields[0]
    assert got.row_count == spec.row_count and got.nominal_plant_count == spec.nominal_plant_count
    assert got.row_spacing_m == spec.agronomy.row_spacing_m
    truth = _own_geometry(spec)
    assert set(truth) == set(GEOMETRY_KEYS)
    item = _roma_prompt(**truth)
    result = score_prompt(item, predicted)  # type: ignore[arg-type]
    assert result.correct, result.reasons
    assert result.true_positives == 1 and result.phantom_fields == 0
    # Within 1 % for lengths, spacings and densities.
    near = {k: v * 1.009 for k, v in truth.items() if k.endswith("_m") or k == "plants_per_ha"}
    near.pop("headland_m")  # may be 0, and 0 is only matched by 0
    assert score_prompt(_roma_prompt(**near), predicted).correct  # type: ignore[arg-type]


@pytest.mark.parametrize(
    ("key", "change", "words"),
    [
        ("rows", lambda v: v + 1, "rows"),
        ("beds", lambda v: v + 2, "beds"),
        ("rows_per_bed", lambda v: v + 1, "rows per bed"),
        ("plant_count", lambda v: v + 1, "plants"),  # within 1 %, but counts are exact
        ("row_length_m", lambda v: v * 1.05, "row length"),
        ("row_spacing_m", lambda v: v * 0.9, "row spacing"),
        ("bed_width_m", lambda v: v * 1.1, "bed width"),
        ("in_row_spacing_m", lambda v: v * 1.02, "in-row spacing"),
        ("plants_per_ha", lambda v: v * 0.95, "density"),
        ("headland_m", lambda v: v + 1.0, "headland"),
        ("row_bearing_deg", lambda v: (v + 90) % 180, "row bearing"),
    ],
)
def test_a_wrong_geometry_key_makes_the_field_not_match(
    roma: object, key: str, change: object, words: str
) -> None:
    from agrirecipe.evaluation import PredictedScene

    predicted = PredictedScene.from_recipe(roma)  # type: ignore[arg-type]
    value = _own_geometry(roma.fields[0])[key]  # type: ignore[attr-defined]
    item = _roma_prompt(**{key: change(value)})  # type: ignore[operator]
    result = score_prompt(item, predicted)  # type: ignore[arg-type]
    assert not result.correct
    assert result.kinds == ("geometry",)
    assert result.true_positives == 0
    assert any(f"geometry: {words} " in reason for reason in result.reasons), result.reasons
    assert result.phantom_fields == 0  # a wrong field is not a phantom one


def test_geometry_note_names_value_and_expectation() -> None:
    item = make_prompt(type="single_generic", fields=[{"crop": "Maize", "row_spacing_m": 0.76}])
    got = replace(field("Maize", "Ambition"), rows_per_bed=1, row_spacing_m=0.75)
    result = score_prompt(item, scene(got))
    assert result.reasons == ("field 1: geometry: row spacing 0.75 m (expected 0.76)",)
    # A field that carries no geometry at all does not match a stated one either.
    bare = score_prompt(item, scene(field("Maize", "Ambition")))
    assert bare.kinds == ("geometry",)
    assert "row spacing none" in bare.reasons[0]


def test_row_spacing_is_the_rows_on_a_bed_and_bed_width_the_beds() -> None:
    beds = replace(
        field("Strawberry", "Elsanta"), rows_per_bed=2, row_spacing_m=1.5, bed_row_spacing_m=0.4
    )

    def scored(**geometry: object) -> bool:
        item = make_prompt(type="single_generic", fields=[{"crop": "Strawberry", **geometry}])
        return score_prompt(item, scene(beds)).correct

    assert scored(row_spacing_m=0.4, bed_width_m=1.5, rows_per_bed=2)
    assert not scored(row_spacing_m=1.5)
    assert not scored(bed_width_m=0.4)
    single = replace(beds, rows_per_bed=1, bed_row_spacing_m=0.0)
    item = make_prompt(type="single_generic", fields=[{"crop": "Strawberry", "row_spacing_m": 1.5}])
    assert score_prompt(item, scene(single)).correct


@pytest.mark.parametrize(
    ("truth", "got", "ok"),
    [
        (0.0, 179.5, True),
        (179.6, 0.5, True),
        (0.0, 0.9, True),
        (90.0, 90.8, True),
        (45.0, 45.0, True),
        (0.0, 2.0, False),
        (0.0, 178.5, False),
        (90.0, 88.5, False),
        (45.0, 135.0, False),
    ],
)
def test_row_bearing_is_compared_within_a_degree_modulo_180(
    truth: float, got: float, ok: bool
) -> None:
    item = make_prompt(type="single_generic", fields=[{"crop": "Maize", "row_bearing_deg": truth}])
    predicted = replace(field("Maize", "Ambition"), row_bearing_deg=got)
    result = score_prompt(item, scene(predicted))
    assert result.correct is ok, result.reasons
    if not ok:
        assert result.kinds == ("geometry",)


# --- phantom fields ---


def test_phantom_fields_are_recipe_fields_nobody_asked_for() -> None:
    item = make_prompt(type="single_detailed", fields=[GALA])
    gala = field("Apple", "Gala", "Reproductive", "Spring")
    assert score_prompt(item, scene(gala)).phantom_fields == 0
    two_more = score_prompt(item, scene(field("Wheat", "Spelt"), gala, field("Maize", "Ambition")))
    assert not two_more.correct
    assert two_more.phantom_fields == 2
    assert two_more.true_positives == 1
    # The right number of fields but a wrong one: a wrong field, not a phantom.
    assert score_prompt(item, scene(field("Pear", "Conference"))).phantom_fields == 0
    # Accepted extras of an open count are asked for; beyond the count they are phantoms.
    open_count = make_prompt(
        type="multi_generic",
        fields=[{"category": "Fruits"}, {"category": "Vegetables"}],
        field_count={"min": 2, "max": 3},
        extra_field={"category": ["Fruits", "Vegetables"]},
    )
    fits = scene(field("Apple", "Gala"), field("Carrot", "Nantes"), field("Pear", "Conference"))
    assert score_prompt(open_count, fits).phantom_fields == 0
    beyond = scene(*fits.fields, field("Cherry", "Bing"), field("Wheat", "Spelt"))
    assert score_prompt(open_count, beyond).phantom_fields == 2
    # Prompts that raised, and invalid prompts, have no phantom fields to count.
    assert score_prompt(item, PromptError("no crop")).phantom_fields == 0
    invalid = make_prompt(type="invalid", prompt="a barn", error="PromptError")
    assert score_prompt(invalid, scene(gala)).phantom_fields == 0
