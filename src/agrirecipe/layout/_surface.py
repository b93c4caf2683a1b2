"""What a field's soil surface is made of (:mod:`agrirecipe.layout._ground` builds it).

``ground_spec`` turns a field of the recipe into the plain data the surface builder
reads (relief, depths, mulch, track and the kernel's planting grid), from
``layout/data/ground.yaml``; ``field_ground`` returns the built parts.
"""

from __future__ import annotations

import functools
from pathlib import Path
from typing import Any

import yaml

from agrirecipe.layout._ground import ground_parts
from agrirecipe.layout._kernel import plant_grid
from agrirecipe.recipe import FieldSpec

__all__ = ["field_ground", "ground_colours", "ground_source", "ground_spec"]

_DATA = Path(__file__).with_name("data") / "ground.yaml"


@functools.cache
def _data() -> dict[str, Any]:
    loaded: dict[str, Any] = yaml.safe_load(_DATA.read_text("utf-8"))
    return loaded


def ground_colours() -> dict[str, tuple[float, float, float]]:
    """sRGB colour of each surface part (soil, mulch, track)."""
    return {k: (float(v[0]), float(v[1]), float(v[2])) for k, v in _data()["colours"].items()}


def ground_spec(spec: FieldSpec, params: dict[str, Any]) -> dict[str, Any]:
    """The JSON-able description of one field's surface, for :func:`ground_parts`."""
    data = _data()
    pattern = data["patterns"].get(spec.agronomy.planting_pattern, {"relief": "flat"})
    headland = spec.geometry.headland_m
    track = float(data["track_m"]) if headland >= float(data["min_track_headland_m"]) else 0.0
    return {
        "relief": pattern["relief"],
        "depth_m": float(pattern.get("depth_m", 0.0)),
        "top_m": float(pattern.get("top_m", 0.0)),
        "mulch": spec.crop in data["mulch"],
        "track_m": track,
        "grid": list(plant_grid(params)),
    }


def field_ground(spec: FieldSpec, params: dict[str, Any]) -> list[dict[str, Any]]:
    """The surface parts of one field, in world metres (see :func:`ground_parts`)."""
    return ground_parts(params, ground_spec(spec, params))


def ground_source() -> str:
    """The surface builder's source, to inline into engine scripts like the kernel."""
    return Path(__file__).with_name("_ground.py").read_text(encoding="utf-8")
