"""What one variant shows, drawn from its seed: camera poses, weeds, light and weather.

Pure numpy; every draw comes from a generator seeded by (dataset seed, variant,
purpose), so a variant's plan does not depend on which worker renders it or on
the other variants.
"""

from __future__ import annotations

import hashlib
import math
from collections.abc import Sequence
from typing import Any

import numpy as np

from agrirecipe.dataset._config import CameraKind, CameraRigs, dataset_defaults
from agrirecipe.layout import field_parameters, plant_grid
from agrirecipe.recipe import FieldSpec, SceneRecipe

__all__ = [
    "WEED_COLUMNS",
    "plan_conditions",
    "plan_views",
    "plan_weeds",
    "stream",
    "sun_position",
    "variant_seed",
    "weeds_csv",
]

_RIG_KINDS = ("robot", "drone", "overview")


def variant_seed(seed: int, source: int, variant: int) -> int:
    """The layout seed of one variant (SHA-256 of its coordinates; below 2**63)."""
    digest = hashlib.sha256(f"agrirecipe/dataset/{seed}/{source}/{variant}".encode()).digest()
    return int.from_bytes(digest[:8], "big") >> 1


def stream(seed: int, purpose: str) -> np.random.Generator:
    """An independent generator for one purpose (``"views"``, ``"weeds"``...) of a variant."""
    digest = hashlib.sha256(f"{seed}/{purpose}".encode()).digest()
    return np.random.Generator(np.random.PCG64(int.from_bytes(digest[:16], "big")))


def _to_world(spec: FieldSpec, local_x: float, local_y: float) -> tuple[float, float]:
    turn = math.radians(spec.geometry.rotation_deg)
    origin = spec.geometry.origin_m
    return (
        origin[0] + local_x * math.cos(turn) - local_y * math.sin(turn),
        origin[1] + local_x * math.sin(turn) + local_y * math.cos(turn),
    )


def _lens_for(hfov_deg: float, sensor_width_mm: float) -> float:
    return sensor_width_mm / 2.0 / math.tan(math.radians(hfov_deg) / 2.0)


def _robot_view(recipe: SceneRecipe, rigs: CameraRigs, rng: np.random.Generator) -> dict[str, Any]:
    """Between two adjacent rows of a random field, somewhere along them, facing along them."""
    rig = rigs.robot
    index = int(rng.integers(len(recipe.fields)))
    spec = recipe.fields[index]
    params = field_parameters(recipe)[index]
    beds, rows_per_bed, per_row, x_start, y_start = plant_grid(params)
    rows = sorted(
        {
            round(
                x_start + bed * spec.agronomy.row_spacing_m + row * spec.agronomy.bed_row_spacing_m,
                9,
            )
            for bed in range(beds)
            for row in range(rows_per_bed)
        }
    )
    if len(rows) > 1:
        gap = int(rng.integers(len(rows) - 1))
        local_x = (rows[gap] + rows[gap + 1]) / 2.0
    else:
        local_x = rows[0] + 0.5 * max(spec.agronomy.row_spacing_m, 1.0)
    y_end = y_start + (per_row - 1) * spec.agronomy.in_row_spacing_m
    low, high = y_start + rig.row_margin_m, y_end - rig.row_margin_m
    local_y = float(rng.uniform(low, high)) if high > low else (y_start + y_end) / 2.0
    forward = bool(rng.integers(2))
    x, y = _to_world(spec, local_x, local_y)
    row_bearing = -spec.geometry.rotation_deg
    jitter = float(rng.uniform(-rig.heading_jitter_deg, rig.heading_jitter_deg))
    bearing = (row_bearing + (0.0 if forward else 180.0) + jitter) % 360.0
    return {
        "kind": "robot",
        "field_id": spec.id,
        "location_m": [round(x, 6), round(y, 6), rig.height_m],
        "bearing_deg": round(bearing, 6),
        "pitch_deg": rig.pitch_deg,
        "lens_mm": round(_lens_for(rig.hfov_deg, rigs.sensor_width_mm), 6),
    }


def _drone_view(
    recipe: SceneRecipe, rigs: CameraRigs, rng: np.random.Generator, width_px: int
) -> dict[str, Any]:
    """Above a random point of a random field's middle, nadir or oblique, any heading."""
    rig = rigs.drone
    spec = recipe.fields[int(rng.integers(len(recipe.fields)))]
    width, length = spec.geometry.size_m
    local_x = float(rng.uniform(0.2, 0.8)) * width
    local_y = float(rng.uniform(0.2, 0.8)) * length
    x, y = _to_world(spec, local_x, local_y)
    bearing = float(rng.uniform(0.0, 360.0))
    pitch = -90.0 if rig.view == "nadir" else rig.oblique_pitch_deg
    if rig.gsd_m is not None:
        lens = rig.altitude_m * rigs.sensor_width_mm / (width_px * rig.gsd_m)
    else:
        lens = _lens_for(rig.hfov_deg, rigs.sensor_width_mm)
    return {
        "kind": "drone",
        "field_id": spec.id,
        "location_m": [round(x, 6), round(y, 6), rig.altitude_m],
        "bearing_deg": round(bearing, 6),
        "pitch_deg": pitch,
        "lens_mm": round(lens, 6),
        "gsd_m": round(rig.altitude_m * rigs.sensor_width_mm / (width_px * lens), 9),
    }


def _overview_view(rigs: CameraRigs, rng: np.random.Generator) -> dict[str, Any]:
    """The whole scene from above at an angle; Blender fits the distance to every field."""
    rig = rigs.overview
    bearing = rig.bearing_deg + float(rng.uniform(-rig.bearing_jitter_deg, rig.bearing_jitter_deg))
    pitch = rig.pitch_deg + float(rng.uniform(-rig.pitch_jitter_deg, rig.pitch_jitter_deg))
    return {
        "kind": "overview",
        "field_id": None,
        "bearing_deg": round(bearing % 360.0, 6),
        "pitch_deg": round(max(-89.0, min(-5.0, pitch)), 6),
        "lens_mm": rig.lens_mm,
        "margin": rig.margin,
    }


def plan_views(
    recipe: SceneRecipe,
    *,
    count: int,
    camera: CameraKind,
    rigs: CameraRigs,
    resolution: tuple[int, int],
    rng: np.random.Generator,
) -> list[dict[str, Any]]:
    """``count`` views named ``c00``, ``c01``...; ``camera="random"`` draws a rig per view."""
    views = []
    for index in range(count):
        kind = _RIG_KINDS[int(rng.integers(3))] if camera == "random" else camera
        if kind == "robot":
            view = _robot_view(recipe, rigs, rng)
        elif kind == "drone":
            view = _drone_view(recipe, rigs, rng, resolution[0])
        else:
            view = _overview_view(rigs, rng)
        view.update(
            name=f"c{index:02d}",
            sensor_width_mm=rigs.sensor_width_mm,
            clip_start_m=rigs.clip_start_m,
            clip_end_m=rigs.clip_end_m,
        )
        views.append(view)
    return views


def sun_position(season: str, latitude_deg: float, hour: float) -> tuple[float, float]:
    """Sun ``(elevation_deg, azimuth_deg)`` at local solar ``hour`` in the middle of ``season``.

    The same spherical astronomy as the recipe's sun (which is this at 15:00):
    declination from the season (sign flipped south of the equator), hour angle
    15 degrees per hour from noon; azimuth clockwise from north.
    """
    declination = float(dataset_defaults()["conditions"]["declination_deg"][season])
    if latitude_deg < 0:
        declination = -declination
    lat, dec = math.radians(latitude_deg), math.radians(declination)
    hour_angle = math.radians(15.0 * (hour - 12.0))
    sin_elevation = math.sin(lat) * math.sin(dec) + math.cos(lat) * math.cos(dec) * math.cos(
        hour_angle
    )
    elevation = math.asin(max(-1.0, min(1.0, sin_elevation)))
    cos_azimuth = (math.sin(dec) - math.sin(elevation) * math.sin(lat)) / max(
        1e-9, math.cos(elevation) * math.cos(lat)
    )
    azimuth = math.degrees(math.acos(max(-1.0, min(1.0, cos_azimuth))))
    if hour_angle > 0:
        azimuth = 360.0 - azimuth
    return round(math.degrees(elevation), 3), round(azimuth % 360.0, 3)


def plan_conditions(recipe: SceneRecipe, *, vary: bool, rng: np.random.Generator) -> dict[str, Any]:
    """Light and weather of one variant: the recipe's sun and a clear sky, or drawn ones."""
    settings = dataset_defaults()["conditions"]
    environment = recipe.environment
    if not vary:
        hour, overcast, fog, wet = 15.0, False, None, False
        elevation, azimuth = environment.sun.elevation_deg, environment.sun.azimuth_deg
    else:
        ranges = settings["vary"]
        hour = round(float(rng.uniform(*ranges["hours"])), 3)
        overcast = bool(rng.random() < ranges["overcast_probability"])
        fog_drawn = rng.random() < ranges["fog_probability"]
        visibility = round(float(rng.uniform(*ranges["fog_visibility_m"])), 3)
        fog = visibility if fog_drawn else None
        wet = bool(rng.random() < ranges["wet_soil_probability"])
        elevation, azimuth = sun_position(environment.season, environment.latitude_deg, hour)
    sky = settings["overcast" if overcast else "clear"]
    return {
        "hour": hour,
        "season": environment.season,
        "latitude_deg": environment.latitude_deg,
        "sun_elevation_deg": elevation,
        "sun_azimuth_deg": azimuth,
        "overcast": overcast,
        "sun_factor": float(sky["sun_factor"]),
        "sky_rgb": [float(c) for c in sky["sky_rgb"]],
        "sky_factor": float(sky["sky_factor"]),
        "fog_visibility_m": fog,
        "fog_rgb": [float(c) for c in settings["fog_rgb"]],
        "wet_soil": wet,
    }


#: Columns of a variant's ``weeds.csv``.
WEED_COLUMNS = ("instance_id", "field_id", "x_m", "y_m", "z_m", "yaw_deg", "size_m", "variant")


def plan_weeds(
    recipe: SceneRecipe,
    *,
    density_per_m2: float,
    first_id: int,
    rng: np.random.Generator,
) -> dict[str, Any]:
    """Weeds scattered uniformly over every field (between and within rows).

    Each field gets a Poisson number of weeds with mean ``density * area``;
    instance ids continue after the crop plants (``first_id``, ``first_id + 1``...).
    """
    settings = dataset_defaults()["weeds"]
    low, high = (float(v) for v in settings["size_m"])
    shapes: Sequence[int] = settings["leaves"]
    columns: dict[str, list[Any]] = {
        name: [] for name in ("field_id", "x", "y", "z", "yaw", "size_m", "variant")
    }
    for spec in recipe.fields:
        if density_per_m2 <= 0.0:
            break
        width, length = spec.geometry.size_m
        count = min(
            int(rng.poisson(density_per_m2 * width * length)), int(settings["max_per_field"])
        )
        local = rng.random((count, 2)) * np.array([width, length])
        yaw = rng.uniform(0.0, 2 * math.pi, count)
        size = rng.uniform(low, high, count)
        variant = rng.integers(len(shapes), size=count)
        for k in range(count):
            x, y = _to_world(spec, float(local[k, 0]), float(local[k, 1]))
            columns["field_id"].append(spec.id)
            columns["x"].append(round(x, 4))
            columns["y"].append(round(y, 4))
            columns["z"].append(0.0)
            columns["yaw"].append(round(float(yaw[k]), 6))
            columns["size_m"].append(round(float(size[k]), 4))
            columns["variant"].append(int(variant[k]))
    count = len(columns["x"])
    return {
        **columns,
        "instance_id": list(range(first_id, first_id + count)),
        "leaves": [int(v) for v in shapes],
        "rgb": [float(c) for c in settings["rgb"]],
        "density_per_m2": density_per_m2,
    }


def weeds_csv(weeds: dict[str, Any]) -> str:
    """A variant's ``weeds.csv``: one row per weed, ids after the crop plants'."""
    lines = [",".join(WEED_COLUMNS)]
    for k, instance in enumerate(weeds["instance_id"]):
        lines.append(
            f"{instance},{weeds['field_id'][k]},{weeds['x'][k]:.4f},{weeds['y'][k]:.4f},"
            f"{weeds['z'][k]:.4f},{math.degrees(weeds['yaw'][k]):.3f},{weeds['size_m'][k]:.4f},"
            f"{weeds['variant'][k]}"
        )
    return "\n".join(lines) + "\n"
