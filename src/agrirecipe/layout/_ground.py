"""The soil surface of one field: ridges, raised beds, plastic mulch and headland tracks.

Like the placement kernel this module uses only the standard library, so the
Blender backend inlines it verbatim into ``blender_build.py`` and the USD backend
imports it: both engines build the same surface from the same numbers.

The crest of a ridge and the top of a bed are at z = 0, where ``plants.csv`` puts
the plants; furrows and the paths between beds go down to ``-depth_m``. The
profile runs across the rows (field-local x) and is extruded along them (local
y) between the headlands, where it ramps back to the flat headland at z = 0.
Returned coordinates are world metres (the field's origin and rotation applied,
as the kernel does).
"""

import math
from typing import Any

GROUND_VERSION = 1
GROUND_RELIEFS = ("flat", "ridges", "beds")


def ground_parts(params: dict[str, Any], ground: dict[str, Any]) -> list[dict[str, Any]]:
    """The surface parts of one field: ``[{"part", "points", "triangles"}]``.

    ``params`` are the field's kernel parameters; ``ground`` holds the field's
    planting grid (``"grid"``: the kernel's ``plant_grid(params)``) and says the
    relief (``"flat"``, ``"ridges"``, ``"beds"``), its
    ``depth_m`` and ``top_m`` (crest or bed-top width), whether beds carry plastic
    ``mulch`` and the width of the headland ``track_m`` (0: none). Parts are
    ``"soil"``, ``"mulch"`` and ``"track"``; points are flat ``[x, y, z, ...]``
    lists and triangles flat vertex-index lists, counter-clockwise seen from above.
    """
    width, length = float(params["size_m"][0]), float(params["size_m"][1])
    headland = float(params["headland_m"])
    relief = str(ground["relief"])
    if relief not in GROUND_RELIEFS:
        raise ValueError(f"unknown ground relief {relief!r}")
    xs = [(0.0, 0.0), (width, 0.0)]  # (x, z) across the field
    tops: list[tuple[float, float]] = []
    if relief != "flat":
        xs, tops = _ground_profile(params, ground, width)
    ys = [0.0, length] if relief == "flat" else _ground_along(headland, length)
    soil = _ground_sheet(xs, ys, headland, length - headland)
    if relief != "flat":
        # a bank of soil around the field, down below its furrows: the ground around the
        # fields lies that low (GROUND_BASE_M) so that it never covers a furrow
        skirt = _ground_skirt(width, length, ground_base_depth(ground))
        offset = len(soil[0]) // 3
        soil = (soil[0] + skirt[0], soil[1] + [i + offset for i in skirt[1]])
    parts = [{"part": "soil", "points": soil[0], "triangles": soil[1]}]
    if ground.get("mulch") and not tops:
        tops = _ground_row_strips(params, ground, width)  # mulch laid flat under each row
    if ground.get("mulch") and tops:
        parts.append(_ground_strips("mulch", tops, headland, length - headland, 0.004))
    track = min(float(ground.get("track_m", 0.0)), headland)
    if track > 0.0:
        ends = [(0.0, width)]
        near = _ground_strips(
            "track", ends, (headland - track) / 2.0, (headland + track) / 2.0, 0.003
        )
        far_start = length - (headland + track) / 2.0
        far = _ground_strips("track", ends, far_start, far_start + track, 0.003)
        offset = len(near["points"]) // 3
        near["points"] += far["points"]
        near["triangles"] += [i + offset for i in far["triangles"]]
        parts.append(near)
    return [_ground_placed(part, params) for part in parts]


def ground_base_depth(ground: dict[str, Any]) -> float:
    """How far below z = 0 the ground around a field must lie not to cover its furrows."""
    return float(ground.get("depth_m", 0.0)) + 0.03 if ground["relief"] != "flat" else 0.0


def _ground_skirt(width: float, length: float, depth: float) -> tuple[list[float], list[int]]:
    """Four walls from the field's edge at z = 0 down to ``-depth``."""
    corners = [(0.0, 0.0), (width, 0.0), (width, length), (0.0, length)]
    points: list[float] = []
    triangles: list[int] = []
    for index, (x0, y0) in enumerate(corners):
        x1, y1 = corners[(index + 1) % 4]
        base = len(points) // 3
        points += [x0, y0, 0.0, x1, y1, 0.0, x1, y1, -depth, x0, y0, -depth]
        triangles += [base, base + 1, base + 2, base, base + 2, base + 3]
    return points, triangles


def _ground_profile(
    params: dict[str, Any], ground: dict[str, Any], width: float
) -> tuple[list[tuple[float, float]], list[tuple[float, float]]]:
    """(x, z) points across the field and the (x0, x1) extent of every crest or bed top."""
    beds, rows_per_bed, x_start = (
        int(ground["grid"][0]),
        int(ground["grid"][1]),
        float(ground["grid"][3]),
    )
    spacing = float(params["row_spacing_m"])
    bed_span = float(params["bed_row_spacing_m"]) * (rows_per_bed - 1)
    depth = float(ground["depth_m"])
    top = max(float(ground["top_m"]), bed_span + 0.1)
    top = min(top, 0.85 * spacing) if beds > 1 else top
    slope = max(0.0, min((spacing - top) / 2.0 * 0.7, 2.0 * depth)) if beds > 1 else 2.0 * depth
    points = [(0.0, 0.0)]
    tops = []
    for bed in range(beds):
        centre = x_start + bed * spacing + bed_span / 2.0
        left, right = centre - top / 2.0, centre + top / 2.0
        points += [(left - slope, -depth), (left, 0.0), (right, 0.0), (right + slope, -depth)]
        tops.append((left, right))
    points.append((width, 0.0))
    # clip to the field and keep x increasing
    cleaned: list[tuple[float, float]] = []
    for x, z in points:
        x = min(max(x, 0.0), width)
        if cleaned and x <= cleaned[-1][0] + 1e-6:
            continue
        cleaned.append((x, z))
    return cleaned, tops


def _ground_row_strips(
    params: dict[str, Any], ground: dict[str, Any], width: float
) -> list[tuple[float, float]]:
    """The (x0, x1) of a mulch strip under each row (or bed) of flat ground."""
    beds, rows_per_bed, x_start = (
        int(ground["grid"][0]),
        int(ground["grid"][1]),
        float(ground["grid"][3]),
    )
    spacing = float(params["row_spacing_m"])
    span = float(params["bed_row_spacing_m"]) * (rows_per_bed - 1)
    strip = span + min(0.8, 0.6 * spacing)
    out = []
    for bed in range(beds):
        centre = x_start + bed * spacing + span / 2.0
        out.append((max(centre - strip / 2.0, 0.0), min(centre + strip / 2.0, width)))
    return out


def _ground_along(headland: float, length: float) -> list[float]:
    """Rows of the surface along the field: flat edge, relief from the headland on."""
    ramp = min(0.5, headland / 2.0)
    inner0, inner1 = headland - ramp, length - headland + ramp
    ys = [0.0, max(inner0, 0.0), headland, length - headland, min(inner1, length), length]
    out: list[float] = []
    for y in ys:
        if not out or y > out[-1] + 1e-6:
            out.append(y)
    return out


def _ground_sheet(
    xs: list[tuple[float, float]], ys: list[float], low: float, high: float
) -> tuple[list[float], list[int]]:
    """A grid surface: the profile at every y from ``low`` to ``high``, flat elsewhere."""
    points: list[float] = []
    for y in ys:
        relief = low - 1e-9 <= y <= high + 1e-9
        for x, z in xs:
            points += [x, y, z if relief else 0.0]
    triangles: list[int] = []
    count = len(xs)
    for row in range(len(ys) - 1):
        for column in range(count - 1):
            a = row * count + column
            b, c, d = a + 1, a + count + 1, a + count
            triangles += [a, b, c, a, c, d]
    return points, triangles


def _ground_strips(
    part: str, spans: list[tuple[float, float]], y0: float, y1: float, lift: float
) -> dict[str, Any]:
    """Flat rectangles over the x ``spans`` from ``y0`` to ``y1``, ``lift`` above z = 0."""
    points: list[float] = []
    triangles: list[int] = []
    for x0, x1 in spans:
        base = len(points) // 3
        points += [x0, y0, lift, x1, y0, lift, x1, y1, lift, x0, y1, lift]
        triangles += [base, base + 1, base + 2, base, base + 2, base + 3]
    return {"part": part, "points": points, "triangles": triangles}


def _ground_placed(part: dict[str, Any], params: dict[str, Any]) -> dict[str, Any]:
    """Field-local metres to world metres (the kernel's origin and rotation)."""
    turn = math.radians(float(params["rotation_deg"]))
    cos_r, sin_r = math.cos(turn), math.sin(turn)
    ox, oy = float(params["origin_m"][0]), float(params["origin_m"][1])
    local = part["points"]
    world: list[float] = []
    for index in range(0, len(local), 3):
        x, y, z = local[index], local[index + 1], local[index + 2]
        world += [ox + (x * cos_r - y * sin_r), oy + (x * sin_r + y * cos_r), z]
    return {"part": part["part"], "points": world, "triangles": part["triangles"]}
