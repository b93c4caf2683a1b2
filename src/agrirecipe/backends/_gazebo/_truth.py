"""Ground truth for the Gazebo world: row lines, each plant's row, the robot's spawn pose.

Everything here is in the world frame, which is the frame of ``plants.csv``:
metres, X east, Y north, Z up. A field's rows run along its local +Y (the
kernel's convention); the field's local frame is its origin turned by its
``rotation_deg`` about Z, exactly as :func:`agrirecipe.layout.place_field` does.
"""

from __future__ import annotations

import csv
import io
import math
from dataclasses import dataclass
from pathlib import Path
from typing import TYPE_CHECKING, Any

import numpy as np
from numpy.typing import NDArray

from agrirecipe._files import atomic_path
from agrirecipe.backends._gazebo._meshes import plant_rows
from agrirecipe.layout import placement_terms, plant_grid

if TYPE_CHECKING:
    from agrirecipe.layout import FieldPlants

__all__ = [
    "MARKER_COLUMNS",
    "FieldRows",
    "SpawnPose",
    "field_rows",
    "spawn_pose",
    "write_markers_csv",
]

#: Header of ``markers.csv``.
MARKER_COLUMNS = (
    "kind",
    "field_id",
    "id",
    "row",
    "x_m",
    "y_m",
    "z_m",
    "end_x_m",
    "end_y_m",
    "end_z_m",
)
_CHUNK = 65_536


@dataclass(frozen=True, slots=True)
class FieldRows:
    """A field's nominal row lines and its plants in the field's local frame.

    ``row_x`` is each row's local x (bed by bed, row by row within a bed: the
    kernel's order); every row runs from local y ``y_start`` to ``y_end``.
    ``local_xy`` are the plants' local positions, ``plant_row`` their row.
    """

    origin: tuple[float, float]
    rotation_rad: float
    row_x: NDArray[np.float64]
    y_start: float
    y_end: float
    local_xy: NDArray[np.float64]
    plant_row: NDArray[np.int64]

    def to_world(
        self, x: NDArray[np.float64], y: NDArray[np.float64]
    ) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
        """Field-local metres to world metres (the kernel's formula and grouping)."""
        cos_r, sin_r = math.cos(self.rotation_rad), math.sin(self.rotation_rad)
        return (
            self.origin[0] + (x * cos_r - y * sin_r),
            self.origin[1] + (x * sin_r + y * cos_r),
        )


def field_rows(plants: FieldPlants, params: dict[str, Any]) -> FieldRows:
    """The rows of one field, and which row each of its plants stands in."""
    beds, rows_per_bed, per_row, x_start, y_start = plant_grid(params)
    terms = placement_terms(params)
    bed = np.arange(beds, dtype=np.float64)[:, None]
    row = np.arange(rows_per_bed, dtype=np.float64)[None, :]
    row_x = ((x_start + bed * terms.row_spacing) + row * terms.bed_row_spacing).ravel()
    dx = plants.xyz[:, 0] - terms.origin_x
    dy = plants.xyz[:, 1] - terms.origin_y
    local = np.empty((plants.plant_count, 2), dtype=np.float64)
    local[:, 0] = dx * terms.cos_r + dy * terms.sin_r
    local[:, 1] = -dx * terms.sin_r + dy * terms.cos_r
    return FieldRows(
        origin=(terms.origin_x, terms.origin_y),
        rotation_rad=terms.rotation_rad,
        row_x=row_x,
        y_start=y_start,
        y_end=y_start + (per_row - 1) * terms.in_row,
        local_xy=local,
        plant_row=plant_rows(local[:, 0], row_x),
    )


@dataclass(frozen=True, slots=True)
class SpawnPose:
    """Where a robot starts: world metres and yaw (radians, counter-clockwise from +X)."""

    field_id: str
    x_m: float
    y_m: float
    z_m: float
    yaw_rad: float

    def yaml(self, world_name: str) -> str:
        """``spawn.yaml``: the pose, with the arguments ``ros_gz_sim create`` takes."""
        return (
            "# Robot spawn pose in the world frame (= the plants.csv frame): metres, radians.\n"
            "# At the start of the first row of the first field, in the lane beside it,\n"
            "# facing along the rows. ros2 run ros_gz_sim create -x X -y Y -z Z -Y YAW\n"
            f"world: {world_name}\n"
            "frame: world\n"
            f"field_id: {self.field_id}\n"
            f"x: {self.x_m:.4f}\n"
            f"y: {self.y_m:.4f}\n"
            f"z: {self.z_m:.4f}\n"
            "roll: 0.0\n"
            "pitch: 0.0\n"
            f"yaw: {self.yaw_rad:.6f}\n"
        )


def spawn_pose(field_id: str, rows: FieldRows, clearance_m: float) -> SpawnPose:
    """The start of the field's first row: in the lane between its first two rows (on the
    row when there is only one), ``clearance_m`` before the first planting position,
    facing along the rows into the field."""
    ordered = np.sort(rows.row_x)
    lane_x = float(ordered[0] + ordered[1]) / 2.0 if len(ordered) > 1 else float(ordered[0])
    local_y = rows.y_start - clearance_m
    x, y = rows.to_world(np.array([lane_x]), np.array([local_y]))
    yaw = math.atan2(
        math.sin(rows.rotation_rad + math.pi / 2), math.cos(rows.rotation_rad + math.pi / 2)
    )
    return SpawnPose(field_id, float(x[0]), float(y[0]), 0.0, yaw)


def _prefix(*texts: str) -> str:
    buffer = io.StringIO()
    csv.writer(buffer, lineterminator="").writerow(texts)
    return buffer.getvalue().replace("%", "%%")


def write_markers_csv(path: Path, fields: list[tuple[FieldPlants, FieldRows]]) -> Path:
    """``markers.csv``: every plant (``kind`` plant, ``id`` its index in the field, as in
    ``plants.csv``) and every row line (``kind`` row, start and end), in the world frame.

    Plant coordinates are written with ``plants.csv``'s decimals, so the two files
    agree character for character.
    """
    with (
        atomic_path(path, suffix=".csv") as temporary,
        temporary.open("w", encoding="utf-8", newline="") as out,
    ):
        out.write(",".join(MARKER_COLUMNS) + "\n")
        for plants, rows in fields:
            start_x, start_y = rows.to_world(rows.row_x, np.full(len(rows.row_x), rows.y_start))
            end_x, end_y = rows.to_world(rows.row_x, np.full(len(rows.row_x), rows.y_end))
            row_format = (
                _prefix("row", plants.field_id) + ",%d,%d,%.4f,%.4f,0.0000,%.4f,%.4f,0.0000\n"
            )
            lines = zip(
                range(len(rows.row_x)),
                range(len(rows.row_x)),
                start_x.tolist(),
                start_y.tolist(),
                end_x.tolist(),
                end_y.tolist(),
                strict=True,
            )
            out.write("".join(row_format % line for line in lines))
            plant_format = _prefix("plant", plants.field_id) + ",%d,%d,%.4f,%.4f,%.4f,,,\n"
            for start in range(0, plants.plant_count, _CHUNK):
                stop = min(start + _CHUNK, plants.plant_count)
                columns = zip(
                    range(start, stop),
                    rows.plant_row[start:stop].tolist(),
                    plants.xyz[start:stop, 0].tolist(),
                    plants.xyz[start:stop, 1].tolist(),
                    plants.xyz[start:stop, 2].tolist(),
                    strict=True,
                )
                out.write("".join(plant_format % column for column in columns))
    return path
