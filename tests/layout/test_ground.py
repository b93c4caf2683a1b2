"""The soil surface of a field: ridges and beds under the plants, mulch, headland tracks."""

from __future__ import annotations

import math

import numpy as np
import pytest

from agrirecipe import generate
from agrirecipe.layout import field_ground, field_parameters, ground_source, ground_spec
from agrirecipe.layout._ground import ground_parts


def _field(prompt: str) -> tuple[object, dict[str, object]]:
    recipe = generate(prompt, resolver="hybrid").recipe
    return recipe.fields[0], field_parameters(recipe)[0]


def _parts(prompt: str) -> dict[str, np.ndarray]:
    spec, params = _field(prompt)
    return {
        p["part"]: np.asarray(p["points"]).reshape(-1, 3)
        for p in field_ground(spec, params)  # type: ignore[arg-type]
    }


def test_ridges_put_every_plant_on_a_crest() -> None:
    scene = generate("a potato field, 20 ridges at 75 cm, 50 m long", resolver="hybrid")
    spec, params = scene.recipe.fields[0], field_parameters(scene.recipe)[0]
    (soil,) = [p for p in field_ground(spec, params) if p["part"] == "soil"]
    points = np.asarray(soil["points"]).reshape(-1, 3)
    inside = points[(points[:, 1] > 1.0) & (points[:, 1] < spec.geometry.size_m[1] - 1.0)]
    assert inside[:, 2].min() == pytest.approx(-0.18)  # furrows
    assert points[:, 2].max() == 0.0  # crests at the plants' feet
    assert points[:, 2].min() == pytest.approx(-0.21)  # the bank down to the ground around
    # every plant's x (across the rows) lies on a crest: the crest points span it
    crest_x = np.sort(points[np.isclose(points[:, 2], 0.0) & (points[:, 1] > 10), 0])
    plants = scene.layout.fields[0]
    for x in plants.xyz[::97, 0]:
        nearest = crest_x[np.searchsorted(crest_x, x).clip(1, len(crest_x) - 1) - 1 :][:2]
        assert nearest[0] - 0.05 <= x <= nearest[-1] + 0.05


def test_strawberry_beds_carry_plastic_mulch_and_tracks_at_the_headlands() -> None:
    parts = _parts("Elsanta strawberries, 8 beds, 50 m long, 4 m headland")
    assert set(parts) == {"soil", "mulch", "track"}
    assert parts["soil"][:, 2].min() == pytest.approx(-0.23)  # beds 0.2 m high, bank below
    assert np.all(parts["mulch"][:, 2] > 0.0)  # just above the bed tops
    assert len(parts["mulch"]) == 8 * 4  # one strip per bed
    assert np.allclose(parts["track"][:, 2], 0.003)


def test_drilled_and_tree_rows_are_flat() -> None:
    for prompt in ("a wheat field", "an apple orchard"):
        parts = _parts(prompt)
        assert np.allclose(parts["soil"][:, 2], 0.0)
        assert "mulch" not in parts


def test_the_surface_follows_the_field_rotation() -> None:
    spec, params = _field("a potato field, 10 ridges at 75 cm, 30 m long")
    turned = dict(params, rotation_deg=30.0)
    ground = ground_spec(spec, turned)  # type: ignore[arg-type]
    flat = ground_parts(params, ground)[0]["points"]  # type: ignore[arg-type]
    rotated = ground_parts(turned, ground)[0]["points"]
    a = np.asarray(flat).reshape(-1, 3)
    b = np.asarray(rotated).reshape(-1, 3)
    origin = np.asarray(params["origin_m"])  # type: ignore[call-overload]
    r = math.radians(30.0)
    local = a[:, :2] - origin
    expected = origin + local @ np.array([[math.cos(r), math.sin(r)], [-math.sin(r), math.cos(r)]])
    np.testing.assert_allclose(b[:, :2], expected, atol=1e-9)
    np.testing.assert_allclose(b[:, 2], a[:, 2])


def test_the_builder_is_standard_library_only() -> None:
    source = ground_source()
    imports = [line for line in source.splitlines() if line.startswith(("import ", "from "))]
    assert imports == ["import math", "from typing import Any"]
    with pytest.raises(ValueError, match="relief"):
        ground_parts(
            {"size_m": [1, 1], "headland_m": 0, "rotation_deg": 0, "origin_m": [0, 0]},
            {"relief": "terraces"},
        )
