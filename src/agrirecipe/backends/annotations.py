"""Ground truth: ``plants.csv`` (one row per plant), ``fields.geojson`` and a ``preview.png`` map.

Above a million plants the plants table is written as ``plants.parquet`` instead
(the same columns, compressed and typed: about a tenth of the CSV's size); the
backend's ``ground_truth`` option asks for either or both at any size.

All three come from the same seeded layout the engine backends use, so a row
of ``plants.csv`` is exactly a plant in the Unreal, Blender and USD scenes
(within each engine's numeric precision). Coordinates are the recipe's: local
metres, right-handed, X east, Y north, Z up; ``yaw_deg`` is counter-clockwise
seen from above.

``plants.csv`` columns: ``field_id, crop, variety, stage, season, health, x_m,
y_m, z_m, yaw_deg, scale, height_m, variant``; ``variant`` is the shape variant
the engines draw the plant with (the mesh ``assets/.../SM_..._v<variant>.glb``,
:func:`agrirecipe.plants.plant_variant`); plants in recipe field order, each field
in kernel order (the order of its USD ``PointInstancer`` instances). Numbers
have fixed decimals (positions and heights 0.1 mm, yaw 0.001 degree, scale
1e-5), so the same recipe and seed give a byte-identical file.
"""

from __future__ import annotations

import csv
import functools
import io
import json
import math
from collections.abc import Sequence
from pathlib import Path
from typing import TYPE_CHECKING, Any, ClassVar, Literal

import numpy as np

from agrirecipe._errors import BackendError, ConfigurationError
from agrirecipe._files import atomic_path, write_atomic
from agrirecipe.backends._base import Backend
from agrirecipe.plants import SCENE_VARIANTS, plant_variants

if TYPE_CHECKING:
    from PIL import Image, ImageFont

    from agrirecipe._scene import Scene
    from agrirecipe.layout import FieldPlants, Layout

__all__ = [
    "CSV_COLUMNS",
    "AnnotationsBackend",
    "field_colours",
    "fields_geojson",
    "render_preview",
    "write_plants_csv",
    "write_plants_parquet",
]

#: Header of ``plants.csv``.
CSV_COLUMNS = (
    "field_id",
    "crop",
    "variety",
    "stage",
    "season",
    "health",
    "x_m",
    "y_m",
    "z_m",
    "yaw_deg",
    "scale",
    "height_m",
    "variant",
)
_ROW_NUMBERS = ",%.4f,%.4f,%.4f,%.3f,%.5f,%.4f,%d\n"
_CSV_CHUNK = 65_536
# Okabe-Ito and Tableau hues: distinguishable for colour-blind readers; fields
# beyond the palette reuse it darker.
_PALETTE = (
    (230, 159, 0),
    (86, 180, 233),
    (0, 158, 115),
    (240, 228, 66),
    (0, 114, 178),
    (213, 94, 0),
    (204, 121, 167),
    (148, 103, 189),
    (140, 86, 75),
    (127, 127, 127),
)
_BACKGROUND = (236, 232, 214)
_SOIL = (160, 134, 104)
_INK = (30, 30, 30)
# Above this many plants drawn as discs, plants are subsampled evenly (pixel
# plants are always all drawn: they cost one array assignment).
_MAX_DISCS = 60_000


def field_colours(count: int) -> list[tuple[int, int, int]]:
    """A distinct RGB colour for each of ``count`` fields, in field order."""
    colours = []
    for index in range(count):
        r, g, b = _PALETTE[index % len(_PALETTE)]
        shade = 0.75 ** (index // len(_PALETTE))
        colours.append((int(r * shade), int(g * shade), int(b * shade)))
    return colours


def _csv_prefix(plants: FieldPlants) -> str:
    """The quoted text columns of one field's rows (names may hold commas or quotes)."""
    spec = plants.spec
    buffer = io.StringIO()
    csv.writer(buffer, lineterminator="").writerow(
        [spec.id, spec.crop, spec.variety, spec.stage, spec.season, spec.health]
    )
    return buffer.getvalue()


def write_plants_csv(layout: Layout, path: str | Path) -> Path:
    """Write ``plants.csv`` atomically, streaming (a million plants never sit in one string)."""
    target = Path(path)
    with atomic_path(target) as temporary, temporary.open("w", encoding="utf-8", newline="") as out:
        out.write(",".join(CSV_COLUMNS) + "\n")
        for plants in layout.fields:
            variants = plant_variants(plants.plant_count, SCENE_VARIANTS)
            # '%' formatting is not applied to the prefix: a name with '%' stays literal.
            row_format = _csv_prefix(plants).replace("%", "%%") + _ROW_NUMBERS
            yaw_deg = np.degrees(plants.yaw_rad)
            for start in range(0, plants.plant_count, _CSV_CHUNK):
                stop = start + _CSV_CHUNK
                columns = (
                    plants.xyz[start:stop, 0].tolist(),
                    plants.xyz[start:stop, 1].tolist(),
                    plants.xyz[start:stop, 2].tolist(),
                    yaw_deg[start:stop].tolist(),
                    plants.scale[start:stop].tolist(),
                    plants.height_m[start:stop].tolist(),
                    variants[start:stop].tolist(),
                )
                out.write("".join(row_format % row for row in zip(*columns, strict=True)))
    return target


#: Plants above which ``ground_truth="auto"`` writes ``plants.parquet`` instead of CSV
#: (a million CSV rows are about 105 MB; the Parquet file is a fraction of that).
PARQUET_ABOVE = 1_000_000
GroundTruth = Literal["auto", "csv", "parquet", "both"]


def write_plants_parquet(layout: Layout, path: str | Path) -> Path:
    """Write the columns of ``plants.csv`` as Parquet (zstd), one row group per field.

    Text columns are dictionary-encoded; x and y are float64, z, yaw, scale and height
    float32 (finer than the CSV's decimals), ``variant`` is uint8. Needs ``pyarrow``
    (``pip install 'agrirecipe[parquet]'``).
    """
    try:
        import pyarrow as pa
        import pyarrow.parquet as pq
    except ImportError as exc:
        raise BackendError(
            f"plants.parquet needs pyarrow ({exc})",
            stage="compile",
            hint="pip install 'agrirecipe[parquet]', or write plants.csv (ground_truth='csv')",
        ) from exc
    target = Path(path)
    schema = pa.schema(
        [(name, pa.dictionary(pa.int32(), pa.string())) for name in CSV_COLUMNS[:6]]
        + [("x_m", pa.float64()), ("y_m", pa.float64())]
        + [(name, pa.float32()) for name in CSV_COLUMNS[8:12]]
        + [("variant", pa.uint8())]
    )
    with atomic_path(target, suffix=".parquet") as temporary:
        writer = pq.ParquetWriter(str(temporary), schema, compression="zstd")
        try:
            for plants in layout.fields:
                spec, count = plants.spec, plants.plant_count
                texts = (spec.id, spec.crop, spec.variety, spec.stage, spec.season, spec.health)
                columns = [
                    pa.DictionaryArray.from_arrays(
                        pa.array(np.zeros(count, dtype=np.int32)), pa.array([text])
                    )
                    for text in texts
                ]
                numbers = (
                    plants.xyz[:, 0],
                    plants.xyz[:, 1],
                    plants.xyz[:, 2],
                    np.degrees(plants.yaw_rad),
                    plants.scale,
                    plants.height_m,
                )
                columns += [
                    pa.array(np.asarray(n, dtype=np.float64 if k < 2 else np.float32))
                    for k, n in enumerate(numbers)
                ]
                variants = plant_variants(count, SCENE_VARIANTS).astype(np.uint8)
                columns.append(pa.array(variants))
                writer.write_table(pa.Table.from_arrays(columns, schema=schema))
        finally:
            writer.close()
    return target


def fields_geojson(layout: Layout) -> dict[str, Any]:
    """The field outlines as a GeoJSON FeatureCollection in the scene's local metres.

    RFC 7946 assumes WGS 84 longitude/latitude; these coordinates are local
    metres (x east, y north) instead, which the ``coordinate_system`` member
    says. Tools such as QGIS read them as a planar layer.
    """
    features = []
    for plants in layout.fields:
        spec = plants.spec
        ring = [[round(x, 6), round(y, 6)] for x, y in spec.geometry.corners_m()]
        ring.append(ring[0])  # GeoJSON rings are closed, counter-clockwise
        features.append(
            {
                "type": "Feature",
                "id": spec.id,
                "geometry": {"type": "Polygon", "coordinates": [ring]},
                "properties": plants.attributes(),
            }
        )
    return {
        "type": "FeatureCollection",
        "name": "agrirecipe fields",
        "coordinate_system": "local metres: x east, y north (not WGS 84)",
        "features": features,
    }


@functools.cache
def _font(size: int) -> ImageFont.FreeTypeFont | ImageFont.ImageFont:
    from PIL import ImageFont

    return ImageFont.load_default(size=size)


def render_preview(layout: Layout, *, map_size_px: int = 1200) -> Image.Image:
    """A top-down map: fields outlined, plants in a colour per field, a legend, a scale bar.

    ``map_size_px`` is the longer side of the map area; the legend panel is
    added to its right.
    """
    from PIL import Image, ImageDraw

    corners = [c for plants in layout.fields for c in plants.spec.geometry.corners_m()]
    x_min, x_max = min(x for x, _ in corners), max(x for x, _ in corners)
    y_min, y_max = min(y for _, y in corners), max(y for _, y in corners)
    span = max(x_max - x_min, y_max - y_min, 1e-6)
    pixels_per_m = (map_size_px - 1) / span
    margin, title_height, legend_width = 40, 48, 520
    map_width = math.ceil((x_max - x_min) * pixels_per_m) + 1
    map_height = math.ceil((y_max - y_min) * pixels_per_m) + 1
    entry_height = 50
    legend_height = 40 + entry_height * len(layout.fields)
    width = margin * 2 + map_width + legend_width
    height = max(title_height + margin * 2 + map_height, title_height + margin + legend_height)
    left, top = margin, title_height + margin

    def to_pixels(x: Any, y: Any) -> tuple[Any, Any]:
        return left + (x - x_min) * pixels_per_m, top + (y_max - y) * pixels_per_m

    image = Image.new("RGB", (width, height), _BACKGROUND)
    draw = ImageDraw.Draw(image)
    for plants in layout.fields:
        outline = [to_pixels(x, y) for x, y in plants.spec.geometry.corners_m()]
        draw.polygon(outline, fill=_SOIL)

    colours = field_colours(len(layout.fields))
    _draw_plants(image, layout.fields, colours, to_pixels, pixels_per_m)

    draw = ImageDraw.Draw(image)
    for plants in layout.fields:
        outline = [to_pixels(x, y) for x, y in plants.spec.geometry.corners_m()]
        draw.polygon(outline, outline=_INK, width=2)
        label_x, label_y = to_pixels(*plants.spec.geometry.corners_m()[3])
        draw.text((label_x + 4, label_y + 3), plants.field_id, fill=_INK, font=_font(14))

    recipe = layout.recipe
    thinned = any(plants.plants_per_instance > 1 for plants in layout.fields)
    title = (
        f"{len(layout.fields)} field(s), {layout.plant_count:,} plants"
        f"{' drawn' if thinned else ''}, {recipe.environment.season}, seed {recipe.seed}"
    )
    draw.text((margin, 14), title, fill=_INK, font=_font(20))
    _draw_scale_bar(draw, left, top + map_height + 12, span, pixels_per_m)
    # North arrow at the top right of the legend column: never on top of a field.
    _draw_north_arrow(draw, left + map_width + margin + legend_width - 80, top)
    _draw_legend(draw, layout.fields, colours, left + map_width + margin, top)
    return image


def _draw_plants(
    image: Image.Image,
    fields: Sequence[FieldPlants],
    colours: Sequence[tuple[int, int, int]],
    to_pixels: Any,
    pixels_per_m: float,
) -> None:
    """Plants smaller than a pixel are painted into the array; larger ones as discs."""
    from PIL import Image, ImageDraw

    pixels = np.asarray(image).copy()
    discs: list[tuple[FieldPlants, tuple[int, int, int], float]] = []
    for plants, colour in zip(fields, colours, strict=True):
        radius_px = plants.spec.agronomy.canopy_width_m / 2.0 * pixels_per_m
        if radius_px < 1.0:
            column, row = to_pixels(plants.xyz[:, 0], plants.xyz[:, 1])
            column = np.clip(np.rint(column).astype(np.int64), 0, pixels.shape[1] - 1)
            row = np.clip(np.rint(row).astype(np.int64), 0, pixels.shape[0] - 1)
            pixels[row, column] = colour
        else:
            discs.append((plants, colour, radius_px))
    image.paste(Image.fromarray(pixels))
    total = sum(plants.plant_count for plants, _, _ in discs)
    stride = max(1, math.ceil(total / _MAX_DISCS))
    draw = ImageDraw.Draw(image)
    for plants, colour, radius_px in discs:
        columns, rows = to_pixels(plants.xyz[::stride, 0], plants.xyz[::stride, 1])
        radii = radius_px * plants.scale[::stride]
        darker = tuple(int(c * 0.7) for c in colour)
        for column, row, radius in zip(
            columns.tolist(), rows.tolist(), radii.tolist(), strict=True
        ):
            box = (column - radius, row - radius, column + radius, row + radius)
            draw.ellipse(box, fill=colour, outline=darker if radius > 3 else None)


def _draw_scale_bar(draw: Any, x: float, y: float, span_m: float, pixels_per_m: float) -> None:
    # The largest 1-2-5 length up to a quarter of the map.
    target = span_m / 4.0
    exponent = math.floor(math.log10(target))
    length_m = max(
        step * 10.0**exponent for step in (1.0, 2.0, 5.0) if step * 10.0**exponent <= target
    )
    length_px = length_m * pixels_per_m
    draw.line([(x, y + 6), (x + length_px, y + 6)], fill=_INK, width=3)
    for end in (x, x + length_px):
        draw.line([(end, y), (end, y + 12)], fill=_INK, width=2)
    label = f"{length_m:g} m" if length_m < 1000 else f"{length_m / 1000:g} km"
    draw.text((x + length_px + 8, y - 2), label, fill=_INK, font=_font(14))


def _draw_north_arrow(draw: Any, x: float, y: float) -> None:
    draw.polygon([(x, y), (x - 7, y + 20), (x + 7, y + 20)], fill=_INK)
    draw.text((x - 5, y + 22), "N", fill=_INK, font=_font(14))


def _draw_legend(
    draw: Any,
    fields: Sequence[FieldPlants],
    colours: Sequence[tuple[int, int, int]],
    x: float,
    y: float,
) -> None:
    draw.text((x, y), "Legend", fill=_INK, font=_font(18))
    y += 34
    for plants, colour in zip(fields, colours, strict=True):
        spec = plants.spec
        draw.rectangle([x, y + 2, x + 24, y + 26], fill=colour, outline=_INK)
        draw.text(
            (x + 34, y), f"{spec.id}: {spec.crop} '{spec.variety}'", fill=_INK, font=_font(16)
        )
        draw.text(
            (x + 34, y + 21),
            f"{spec.stage}, {spec.season}, {spec.health}, {plants.plant_count:,} plants"
            + (
                f" drawn, each for {plants.plants_per_instance}"
                if plants.plants_per_instance > 1
                else ""
            ),
            fill=_INK,
            font=_font(14),
        )
        y += 50


class AnnotationsBackend(Backend):
    """Writes ``plants.csv``, ``fields.geojson`` and ``preview.png``."""

    name: ClassVar[str] = "annotations"
    outputs: ClassVar[tuple[str, ...]] = ("plants.csv", "fields.geojson", "preview.png")

    def __init__(self, *, map_size_px: int = 1200, ground_truth: GroundTruth = "auto") -> None:
        if ground_truth not in ("auto", "csv", "parquet", "both"):
            raise ConfigurationError(
                f"unknown ground truth format {ground_truth!r}",
                stage="compile",
                hint="auto (CSV up to a million plants, Parquet above), csv, parquet or both",
            )
        self.map_size_px = map_size_px
        self.ground_truth = ground_truth

    def write(self, scene: Scene, directory: Path) -> list[Path]:
        """Write the ground-truth files atomically into ``directory``: the plants table
        (``plants.csv`` and/or ``plants.parquet``), ``fields.geojson``, ``preview.png``."""
        folder = Path(directory)
        layout = scene.layout
        formats = {
            "csv": ("csv",),
            "parquet": ("parquet",),
            "both": ("csv", "parquet"),
            "auto": ("parquet",) if layout.plant_count > PARQUET_ABOVE else ("csv",),
        }[self.ground_truth]
        written = []
        for kind in ("csv", "parquet"):
            path = folder / f"plants.{kind}"
            if kind in formats:
                writer = write_plants_csv if kind == "csv" else write_plants_parquet
                written.append(writer(layout, path))
            else:
                path.unlink(missing_ok=True)  # a table of an earlier, other-sized scene
        geojson = json.dumps(fields_geojson(layout), indent=2, ensure_ascii=False) + "\n"
        written.append(write_atomic(folder / "fields.geojson", geojson))
        png = io.BytesIO()
        render_preview(layout, map_size_px=self.map_size_px).save(png, format="PNG", optimize=False)
        written.append(write_atomic(folder / "preview.png", png.getvalue()))
        return written
