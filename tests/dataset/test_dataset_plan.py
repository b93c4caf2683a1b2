"""Variant plans: camera poses, weeds and conditions drawn from the variant's seed."""

from __future__ import annotations

import itertools
import math

import numpy as np
import pytest

from agrirecipe import SceneRecipe, generate
from agrirecipe.dataset import (
    CameraRigs,
    plan_conditions,
    plan_views,
    plan_weeds,
    stream,
    sun_position,
    variant_seed,
    weeds_csv,
)
from agrirecipe.layout import field_parameters, plant_grid


@pytest.fixture(scope="module")
def recipe() -> SceneRecipe:
    return generate(
        "a 10 by 12 m apple orchard in summer next to a 6 by 8 m field of carrots",
        seed=0,
        resolver="rules",
    ).recipe


def _local(recipe: SceneRecipe, field_id: str, x: float, y: float) -> tuple[float, float]:
    spec = recipe.field(field_id)
    turn = math.radians(spec.geometry.rotation_deg)
    dx, dy = x - spec.geometry.origin_m[0], y - spec.geometry.origin_m[1]
    return dx * math.cos(turn) + dy * math.sin(turn), -dx * math.sin(turn) + dy * math.cos(turn)


def test_variant_seeds_are_stable_and_distinct() -> None:
    seeds = {variant_seed(0, source, variant) for source in range(3) for variant in range(50)}
    assert len(seeds) == 150
    assert variant_seed(0, 1, 2) == variant_seed(0, 1, 2)
    assert all(0 <= seed < 2**63 for seed in seeds)
    assert stream(5, "views").random() == stream(5, "views").random()
    assert stream(5, "views").random() != stream(5, "weeds").random()


def test_robot_cameras_stand_between_two_rows_inside_the_field(recipe: SceneRecipe) -> None:
    rigs = CameraRigs.defaults().with_overrides(robot_height_m=0.7, robot_pitch_deg=-30.0)
    views = plan_views(
        recipe, count=20, camera="robot", rigs=rigs, resolution=(640, 480), rng=stream(1, "v")
    )
    params = {p["id"]: p for p in field_parameters(recipe)}
    for view in views:
        assert view["kind"] == "robot"
        assert view["location_m"][2] == 0.7
        assert view["pitch_deg"] == -30.0
        spec = recipe.field(view["field_id"])
        local_x, local_y = _local(recipe, spec.id, *view["location_m"][:2])
        beds, rows_per_bed, _, x_start, _ = plant_grid(params[spec.id])
        rows = sorted(
            x_start + b * spec.agronomy.row_spacing_m + r * spec.agronomy.bed_row_spacing_m
            for b in range(beds)
            for r in range(rows_per_bed)
        )
        gaps = [(a + b) / 2 for a, b in itertools.pairwise(rows)]
        assert min(abs(local_x - gap) for gap in gaps) < 1e-6
        assert 0.0 < local_y < spec.geometry.size_m[1]
        # Facing along the rows (either way), within the heading jitter.
        along = (view["bearing_deg"] + spec.geometry.rotation_deg) % 180.0
        assert min(along, 180.0 - along) <= rigs.robot.heading_jitter_deg + 1e-9


def test_drone_focal_length_follows_the_ground_sampling_distance(recipe: SceneRecipe) -> None:
    rigs = CameraRigs.defaults().with_overrides(drone_altitude_m=20.0, drone_gsd_m=0.005)
    (view,) = plan_views(
        recipe, count=1, camera="drone", rigs=rigs, resolution=(800, 600), rng=stream(2, "v")
    )
    assert view["pitch_deg"] == -90.0
    assert view["location_m"][2] == 20.0
    # GSD = altitude * sensor width / (image width * focal length)
    assert 20.0 * 36.0 / (800 * view["lens_mm"]) == pytest.approx(0.005)
    assert view["gsd_m"] == pytest.approx(0.005)


def test_random_cameras_mix_rigs_reproducibly(recipe: SceneRecipe) -> None:
    def kinds(seed: int) -> list[str]:
        views = plan_views(
            recipe,
            count=30,
            camera="random",
            rigs=CameraRigs.defaults(),
            resolution=(64, 48),
            rng=stream(seed, "views"),
        )
        return [view["kind"] for view in views]

    assert set(kinds(3)) == {"robot", "drone", "overview"}
    assert kinds(3) == kinds(3)
    assert [f"c{i:02d}" for i in range(3)] == [
        v["name"]
        for v in plan_views(
            recipe,
            count=3,
            camera="overview",
            rigs=CameraRigs.defaults(),
            resolution=(64, 48),
            rng=stream(0, "v"),
        )
    ]


def test_sun_at_three_pm_matches_the_recipes_sun(recipe: SceneRecipe) -> None:
    environment = recipe.environment
    elevation, azimuth = sun_position(environment.season, environment.latitude_deg, 15.0)
    assert elevation == pytest.approx(environment.sun.elevation_deg, abs=1e-3)
    assert azimuth == pytest.approx(environment.sun.azimuth_deg, abs=1e-3)
    morning = sun_position("Summer", 50.0, 9.0)
    noon = sun_position("Summer", 50.0, 12.0)
    assert 0 < morning[1] < 180 and noon[0] > morning[0]  # east in the morning, higher at noon


def test_conditions_are_the_recipes_unless_varied(recipe: SceneRecipe) -> None:
    fixed = plan_conditions(recipe, vary=False, rng=stream(0, "c"))
    assert fixed["hour"] == 15.0 and not fixed["overcast"] and fixed["fog_visibility_m"] is None
    drawn = [plan_conditions(recipe, vary=True, rng=stream(s, "c")) for s in range(60)]
    assert {d["overcast"] for d in drawn} == {True, False}
    assert {d["wet_soil"] for d in drawn} == {True, False}
    assert any(d["fog_visibility_m"] for d in drawn) and any(
        d["fog_visibility_m"] is None for d in drawn
    )
    assert all(8.0 <= d["hour"] <= 17.0 for d in drawn)


def test_weeds_follow_the_density_and_take_ids_after_the_plants(recipe: SceneRecipe) -> None:
    weeds = plan_weeds(recipe, density_per_m2=2.0, first_id=5000, rng=stream(0, "w"))
    area = sum(f.geometry.size_m[0] * f.geometry.size_m[1] for f in recipe.fields)
    count = len(weeds["x"])
    assert abs(count - 2.0 * area) < 5 * math.sqrt(2.0 * area)  # Poisson, 5 sigma
    assert weeds["instance_id"] == list(range(5000, 5000 + count))
    for field_id, x, y in zip(weeds["field_id"], weeds["x"], weeds["y"], strict=True):
        local_x, local_y = _local(recipe, field_id, x, y)
        width, length = recipe.field(field_id).geometry.size_m
        assert -1e-3 <= local_x <= width + 1e-3 and -1e-3 <= local_y <= length + 1e-3
    lines = weeds_csv(weeds).splitlines()
    assert lines[0].startswith("instance_id,field_id") and len(lines) == count + 1
    none = plan_weeds(recipe, density_per_m2=0.0, first_id=1, rng=stream(0, "w"))
    assert none["x"] == [] and np.array_equal(none["instance_id"], [])


def test_varied_attributes_are_drawn_only_where_the_prompt_left_them_open() -> None:
    from agrirecipe import ConfigurationError
    from agrirecipe.dataset import vary_recipe
    from agrirecipe.layout import layout_scene

    stated = generate(
        "a 10 by 12 m healthy apple orchard in summer next to a 6 by 8 m field of carrots",
        seed=0,
        resolver="rules",
    ).recipe
    drawn_values = set()
    for seed in range(12):
        varied, drawn = vary_recipe(stated, ["stage", "season", "health"], stream(seed, "a"))
        assert "season" not in drawn  # stated: every field stays in summer
        assert varied.environment == stated.environment
        for before, after in zip(stated.fields, varied.fields, strict=True):
            for attribute in ("stage", "season", "health"):
                if attribute not in before.inferred:
                    assert getattr(after, attribute) == getattr(before, attribute)
            assert after.geometry == before.geometry
            assert after.agronomy.row_spacing_m == before.agronomy.row_spacing_m
            drawn_values.add(after.stage)
        plants_before, plants_after = layout_scene(stated), layout_scene(varied)
        for a, b in zip(plants_before.fields, plants_after.fields, strict=True):
            assert np.array_equal(a.xyz, b.xyz)  # the same plants, another stage
    assert len(drawn_values) == 3
    assert vary_recipe(stated, [], stream(0, "a")) == (stated, {"fields": {}})
    with pytest.raises(ConfigurationError, match="cannot vary"):
        vary_recipe(stated, ["variety"], stream(0, "a"))
