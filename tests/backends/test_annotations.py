"""Ground truth: plants.csv row per plant, field outlines, and a preview map that is not blank."""

from __future__ import annotations

import csv
import json
from pathlib import Path

import numpy as np
import pytest
from PIL import Image

from agrirecipe import BackendError, ConfigurationError, Scene
from agrirecipe.backends import get_backend
from agrirecipe.backends.annotations import (
    CSV_COLUMNS,
    field_colours,
    render_preview,
    write_plants_csv,
)
from agrirecipe.layout import layout_scene

EXAMPLES = Path(__file__).resolve().parents[2] / "examples" / "recipes"


@pytest.fixture(scope="module")
def scene() -> Scene:
    """Two fields of very different plant sizes (trees as discs, carrots as pixels)."""
    return Scene.from_file(EXAMPLES / "orchard-next-to-carrots.json")


@pytest.fixture(scope="module")
def written(scene: Scene, tmp_path_factory: pytest.TempPathFactory) -> Path:
    folder = tmp_path_factory.mktemp("annotations")
    paths = get_backend("annotations").write(scene, folder)
    assert [p.name for p in paths] == ["plants.csv", "fields.geojson", "preview.png"]
    return folder


def test_csv_has_one_row_per_plant_with_the_layout_values(scene: Scene, written: Path) -> None:
    with (written / "plants.csv").open(encoding="utf-8", newline="") as stream:
        rows = list(csv.reader(stream))
    assert tuple(rows[0]) == CSV_COLUMNS
    body = rows[1:]
    assert len(body) == scene.layout.plant_count > 70_000
    start = 0
    for plants in scene.layout.fields:
        spec = plants.spec
        block = body[start : start + plants.plant_count]
        start += plants.plant_count
        assert {tuple(r[:6]) for r in block} == {
            (spec.id, spec.crop, spec.variety, spec.stage, spec.season, spec.health)
        }
        numbers = np.array([[float(v) for v in r[6:]] for r in block])
        assert np.allclose(numbers[:, :3], plants.xyz, atol=5e-5)
        assert np.allclose(numbers[:, 3], np.degrees(plants.yaw_rad), atol=5e-4)
        assert np.allclose(numbers[:, 4], plants.scale, atol=5e-6)
        assert np.allclose(numbers[:, 5], plants.height_m, atol=5e-5)
    assert start == len(body)


def test_csv_is_byte_stable(scene: Scene, written: Path, tmp_path: Path) -> None:
    again = write_plants_csv(layout_scene(scene.recipe), tmp_path / "plants.csv")
    assert again.read_bytes() == (written / "plants.csv").read_bytes()
    first_row = again.read_text(encoding="utf-8").splitlines()[1]
    numbers = first_row.split(",")[6:]
    assert first_row.count(".") == 6 and all(len(v.split(".")[1]) in (3, 4, 5) for v in numbers[:6])
    assert numbers[6].isdigit()  # the shape variant


def test_csv_quotes_names_with_commas_and_quotes(scene: Scene, tmp_path: Path) -> None:
    odd = 'Cox\'s "Orange", 100% Pippin'
    spec = scene.recipe.fields[0].model_copy(update={"variety": odd})
    recipe = scene.recipe.model_copy(update={"fields": (spec, *scene.recipe.fields[1:])})
    path = write_plants_csv(layout_scene(recipe), tmp_path / "plants.csv")
    with path.open(encoding="utf-8", newline="") as stream:
        rows = list(csv.DictReader(stream))
    assert rows[0]["variety"] == odd and float(rows[0]["x_m"]) > 0
    assert all(len(row) == len(CSV_COLUMNS) for row in rows)


def test_geojson_outlines_the_fields(scene: Scene, written: Path) -> None:
    data = json.loads((written / "fields.geojson").read_text(encoding="utf-8"))
    assert data["type"] == "FeatureCollection"
    assert [f["id"] for f in data["features"]] == [f.id for f in scene.recipe.fields]
    for feature, plants in zip(data["features"], scene.layout.fields, strict=True):
        ring = feature["geometry"]["coordinates"][0]
        assert feature["geometry"]["type"] == "Polygon" and ring[0] == ring[-1] and len(ring) == 5
        assert np.allclose(ring[:4], plants.spec.geometry.corners_m())
        properties = feature["properties"]
        assert properties["crop"] == plants.spec.crop
        assert properties["asset_path"] == plants.spec.asset_path
        assert properties["plant_count"] == plants.plant_count
        assert properties["nominal_plant_count"] == plants.spec.nominal_plant_count


def test_preview_is_a_map_with_every_field_drawn(scene: Scene, written: Path) -> None:
    image = Image.open(written / "preview.png")
    assert image.format == "PNG" and image.mode == "RGB"
    expected = render_preview(scene.layout)
    assert image.size == expected.size
    width, height = image.size
    assert 1200 <= width <= 2400 and 1000 <= height <= 2400
    pixels = np.asarray(image)
    assert len(np.unique(pixels.reshape(-1, 3), axis=0)) > 20, "not blank"
    for colour in field_colours(len(scene.recipe.fields)):
        share = np.all(pixels == colour, axis=2).mean()
        assert share > 0.001, f"no plants drawn in {colour}"


def test_preview_of_a_rotated_field_and_many_fields(tmp_path: Path) -> None:
    scene = Scene.from_file(EXAMPLES / "pinot-noir-vineyard-harvest.json")
    image = render_preview(scene.layout, map_size_px=400)
    pixels = np.asarray(image)
    (colour,) = field_colours(1)
    assert np.all(pixels == colour, axis=2).sum() > 100
    assert len(set(field_colours(64))) == 64


def test_parquet_holds_the_csv_columns(scene: Scene, tmp_path: Path) -> None:
    pq = pytest.importorskip("pyarrow.parquet")
    from agrirecipe.backends.annotations import AnnotationsBackend

    written = AnnotationsBackend(ground_truth="both").write(scene, tmp_path)
    assert [p.name for p in written[:2]] == ["plants.csv", "plants.parquet"]
    table = pq.read_table(tmp_path / "plants.parquet")
    assert table.column_names == list(CSV_COLUMNS)
    with (tmp_path / "plants.csv").open(newline="", encoding="utf-8") as stream:
        rows = list(csv.DictReader(stream))
    assert table.num_rows == len(rows) == scene.layout.plant_count
    columns = table.to_pydict()
    for name in ("field_id", "crop", "variety", "stage", "season", "health"):
        assert columns[name] == [row[name] for row in rows]
    for name, tolerance in (("x_m", 5.1e-5), ("y_m", 5.1e-5), ("yaw_deg", 6e-4), ("scale", 6e-6)):
        expected = np.array([float(row[name]) for row in rows])
        np.testing.assert_allclose(columns[name], expected, atol=tolerance)
    assert columns["variant"] == [int(row["variant"]) for row in rows]
    # Parquet is the smaller file; asking for CSV alone removes a stale Parquet table
    assert (tmp_path / "plants.parquet").stat().st_size < (tmp_path / "plants.csv").stat().st_size
    AnnotationsBackend(ground_truth="csv").write(scene, tmp_path)
    assert not (tmp_path / "plants.parquet").exists()


def test_auto_ground_truth_switches_to_parquet_above_a_million_plants(
    scene: Scene, tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    pytest.importorskip("pyarrow")
    import agrirecipe.backends.annotations as annotations

    names = [p.name for p in annotations.AnnotationsBackend().write(scene, tmp_path)]
    assert "plants.csv" in names and "plants.parquet" not in names  # a small scene
    monkeypatch.setattr(annotations, "PARQUET_ABOVE", scene.layout.plant_count - 1)
    names = [p.name for p in annotations.AnnotationsBackend().write(scene, tmp_path)]
    assert "plants.parquet" in names and not (tmp_path / "plants.csv").exists()
    with pytest.raises(ConfigurationError, match="ground truth"):
        annotations.AnnotationsBackend(ground_truth="xml")  # type: ignore[arg-type]


def test_parquet_without_pyarrow_says_how_to_install(
    scene: Scene, tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    import builtins

    from agrirecipe.backends.annotations import write_plants_parquet

    real = builtins.__import__

    def refuse(name: str, *args: object, **kwargs: object) -> object:
        if name.startswith("pyarrow"):
            raise ImportError("No module named 'pyarrow'")
        return real(name, *args, **kwargs)  # type: ignore[arg-type]

    monkeypatch.setattr(builtins, "__import__", refuse)
    with pytest.raises(BackendError, match="pyarrow"):
        write_plants_parquet(scene.layout, tmp_path / "plants.parquet")
    assert not list(tmp_path.iterdir())
