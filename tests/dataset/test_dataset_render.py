"""A tiny dataset rendered in real Blender (2 variants x 2 views at 96 x 72), checked
against the layout: ids, boxes, masks, COCO, YOLO, cameras; then resumed, and rendered
again through Ray with the same bytes."""

from __future__ import annotations

import csv
import filecmp
import json
import shutil
from pathlib import Path
from typing import Any

import numpy as np
import pytest
from PIL import Image

from agrirecipe import ConfigurationError
from agrirecipe.dataset import MARKER, SEMANTIC_BASE, DatasetReport, dataset

pytest.importorskip("bpy")
pytestmark = pytest.mark.slow

PROMPT = "a 10 by 12 m apple orchard in summer next to a 6 by 8 m field of carrots"
SETTINGS: dict[str, Any] = {
    "variants": 2,
    "views": 2,
    "resolution": (96, 72),
    "camera": "random",
    "weeds": "some",
    "vary_conditions": True,
    "samples": 4,
    "seed": 0,  # draws an overview, a robot and a drone view
    "resolver": "rules",
}


@pytest.fixture(scope="module")
def local(tmp_path_factory: pytest.TempPathFactory) -> DatasetReport:
    folder = tmp_path_factory.mktemp("dataset") / "local"
    return dataset([PROMPT], folder, executor="local", workers=2, **SETTINGS)


@pytest.fixture(scope="module")
def manifest(local: DatasetReport) -> dict[str, Any]:
    loaded: dict[str, Any] = json.loads(local.manifest.read_text("utf-8"))
    return loaded


def _images(manifest: dict[str, Any]) -> list[tuple[dict[str, Any], dict[str, Any]]]:
    return [(variant, image) for variant in manifest["variants"] for image in variant["images"]]


def _plants(root: Path, variant: dict[str, Any]) -> list[dict[str, str]]:
    with (root / variant["files"]["plants"]).open(encoding="utf-8") as stream:
        return list(csv.DictReader(stream))


def _weeds(root: Path, variant: dict[str, Any]) -> dict[int, dict[str, str]]:
    with (root / variant["files"]["weeds"]).open(encoding="utf-8") as stream:
        return {int(row["instance_id"]): row for row in csv.DictReader(stream)}


def _project(image: dict[str, Any], point: np.ndarray) -> tuple[float, float, float]:
    camera = np.asarray(image["camera"]["world_to_camera"]) @ np.append(point, 1.0)
    pixel = np.asarray(image["camera"]["K"]) @ camera[:3]
    return float(pixel[0] / pixel[2]), float(pixel[1] / pixel[2]), float(camera[2])


def test_every_file_of_every_image_is_written(local: DatasetReport, manifest: dict) -> None:
    assert local.images == 4 and local.rendered == ("v0000", "v0001") and local.skipped == ()
    kinds = {image["camera"]["kind"] for _, image in _images(manifest)}
    assert kinds == {"overview", "robot", "drone"}
    for _, image in _images(manifest):
        files = image["files"]
        rgb = np.asarray(Image.open(local.output / files["image"]))
        assert rgb.shape == (72, 96, 3) and rgb.std() > 5  # a picture, not a blank
        semantic = np.asarray(Image.open(local.output / files["semantic"]))
        assert semantic.shape == (72, 96) and semantic.dtype == np.uint8
        instance = np.load(local.output / files["instance"])
        assert instance.shape == (72, 96) and instance.dtype == np.uint32
        depth = np.load(local.output / files["depth"])
        assert depth.dtype == np.float32 and depth.shape == (72, 96)
        # Depth exactly where something was hit; every plant pixel has a depth.
        assert np.all((depth > 0) == (semantic != SEMANTIC_BASE["sky"]))
        assert np.all(depth[instance > 0] > 0)
        assert (local.output / files["yolo"]).is_file()
        assert image["conditions"]["season"] == "Summer"
    assert all(v["render_device"] == "CPU" for v in manifest["variants"])


def test_visible_plant_ids_are_rows_of_plants_csv(local: DatasetReport, manifest: dict) -> None:
    seen_plants = seen_weeds = 0
    for variant, image in _images(manifest):
        plants = _plants(local.output, variant)
        weeds = _weeds(local.output, variant)
        assert len(plants) == variant["plant_count"]
        instance = np.load(local.output / image["files"]["instance"])
        semantic = np.asarray(Image.open(local.output / image["files"]["semantic"]))
        classes = manifest["semantic_classes"]
        for value in np.unique(instance[instance > 0]).tolist():
            pixels = semantic[instance == value]
            if value <= len(plants):
                seen_plants += 1
                assert np.all(pixels == classes[plants[value - 1]["crop"]])
            else:
                seen_weeds += 1
                assert value in weeds
                assert np.all(pixels == SEMANTIC_BASE["weed"])
        # Every crop or weed pixel has an instance, and only those.
        assert np.array_equal(instance > 0, semantic >= SEMANTIC_BASE["weed"])
    assert seen_plants > 50 and seen_weeds > 0


def test_boxes_hold_the_projected_plants(local: DatasetReport, manifest: dict) -> None:
    """A box lies inside the projection of its plant's bounding cylinder (so the id is
    the right plant), and contains the plant's projected centre where the view is clear."""
    for variant, image in _images(manifest):
        recipe = json.loads((local.output / variant["files"]["recipe"]).read_text("utf-8"))
        canopy = {f["id"]: f["agronomy"]["canopy_width_m"] for f in recipe["fields"]}
        plants, weeds = _plants(local.output, variant), _weeds(local.output, variant)
        width, height = image["width"], image["height"]
        clear = centred = 0
        for annotation in image["annotations"]:
            identifier = annotation["instance_id"]
            if identifier <= len(plants):
                row = plants[identifier - 1]
                tall = float(row["height_m"])
                radius = 0.6 * max(canopy[row["field_id"]] * float(row["scale"]), tall)
            else:
                row = weeds[identifier]
                tall = radius = 0.5 * float(row["size_m"])
            base = np.array([float(row["x_m"]), float(row["y_m"]), float(row["z_m"])])
            rim = [
                _project(image, base + np.array([radius * np.cos(a), radius * np.sin(a), z]))
                for a in np.linspace(0, 2 * np.pi, 24, endpoint=False)
                for z in (-0.3, 1.15 * tall)
            ]
            us = [u for u, _, depth in rim if depth > 0]
            vs = [v for _, v, depth in rim if depth > 0]
            x, y, w, h = annotation["bbox"]
            assert min(us) - 1 <= x and x + w <= max(us) + 1, annotation
            assert min(vs) - 1 <= y and y + h <= max(vs) + 1, annotation
            if x > 0 and y > 0 and x + w < width and y + h < height:
                clear += 1
                u, v, _ = _project(image, base + np.array([0.0, 0.0, tall / 2]))
                centred += x - 1 <= u <= x + w + 1 and y - 1 <= v <= y + h + 1
        if image["camera"]["kind"] != "robot":  # from above, nothing hides a plant's centre
            assert centred == clear
        else:  # low along the rows, neighbours hide some
            assert centred >= 0.5 * clear


def test_coco_is_read_by_pycocotools_and_matches_the_masks(
    local: DatasetReport, manifest: dict
) -> None:
    coco_api = pytest.importorskip("pycocotools.coco")
    coco = coco_api.COCO(str(local.output / "coco.json"))
    assert sorted(coco.getImgIds()) == [1, 2, 3, 4]
    names = {c["id"]: c["name"] for c in coco.loadCats(coco.getCatIds())}
    assert names == {3: "weed", 4: "Apple", 5: "Carrot"}
    for image_id, (_, image) in enumerate(_images(manifest), start=1):
        instance = np.load(local.output / image["files"]["instance"])
        annotations = coco.loadAnns(coco.getAnnIds(imgIds=[image_id]))
        assert {a["instance_id"] for a in annotations} == set(np.unique(instance[instance > 0]))
        for annotation in annotations:
            mask = coco.annToMask(annotation).astype(bool)
            assert np.array_equal(mask, instance == annotation["instance_id"])
            assert annotation["area"] == int(mask.sum())
            ys, xs = np.nonzero(mask)
            x, y, w, h = annotation["bbox"]
            assert (x, y, x + w - 1, y + h - 1) == (xs.min(), ys.min(), xs.max(), ys.max())


def test_yolo_labels_are_the_coco_boxes(local: DatasetReport, manifest: dict) -> None:
    names = (local.output / "dataset.yaml").read_text("utf-8")
    assert '0: "weed"' in names and '1: "Apple"' in names
    for _, image in _images(manifest):
        lines = (local.output / image["files"]["yolo"]).read_text("utf-8").splitlines()
        assert len(lines) == len(image["annotations"])
        for line, annotation in zip(lines, image["annotations"], strict=True):
            label, cx, cy, w, h = line.split()
            x, y, bw, bh = annotation["bbox"]
            assert int(label) == annotation["category_id"] - 3
            assert float(cx) == pytest.approx((x + bw / 2) / 96, abs=1e-6)
            assert float(cy) == pytest.approx((y + bh / 2) / 72, abs=1e-6)
            assert float(w) == pytest.approx(bw / 96, abs=1e-6)
            assert float(h) == pytest.approx(bh / 72, abs=1e-6)


def test_cameras_record_intrinsics_and_a_rigid_extrinsic(manifest: dict) -> None:
    for _, image in _images(manifest):
        camera = image["camera"]
        k = np.asarray(camera["K"])
        assert k[0, 0] > 0 and k[0, 0] == k[1, 1] and k[2].tolist() == [0, 0, 1]
        extrinsic = np.asarray(camera["world_to_camera"])
        rotation = extrinsic[:3, :3]
        assert np.allclose(rotation @ rotation.T, np.eye(3), atol=1e-5)
        assert np.linalg.det(rotation) == pytest.approx(1.0, abs=1e-5)
        centre = -rotation.T @ extrinsic[:3, 3]
        assert np.allclose(centre, camera["location_m"], atol=1e-4)
        forward = rotation[2]  # the optical axis (camera z) in world coordinates
        if camera["kind"] == "robot":  # the rig's height and pitch (dataset.yaml defaults)
            assert centre[2] == pytest.approx(1.0, abs=1e-5)
            assert forward[2] == pytest.approx(np.sin(np.radians(-25.0)), abs=1e-5)
        elif camera["kind"] == "drone":  # nadir at 10 m
            assert centre[2] == pytest.approx(10.0, abs=1e-4)
            assert forward == pytest.approx([0.0, 0.0, -1.0], abs=1e-5)
        else:  # the overview looks down at the scene
            assert forward[2] < -0.1


def test_a_rerun_resumes_and_changes_nothing(local: DatasetReport, tmp_path: Path) -> None:
    copy = tmp_path / "copy"
    shutil.copytree(local.output, copy)
    again = dataset([PROMPT], copy, workers=2, **SETTINGS)
    assert again.rendered == () and again.skipped == ("v0000", "v0001")
    # An interrupted variant (no marker written yet) is rendered again, and only it.
    (copy / "variants" / "v0001" / MARKER).unlink()
    (copy / "images" / "v0001_c00.png").unlink()
    # ... and a half-written file a killed process (no such pid) left behind is removed.
    (copy / "images" / ".v0001_c00.png.4194999.abcd1234.tmp").write_bytes(b"half")
    resumed = dataset([PROMPT], copy, workers=2, **SETTINGS)
    assert resumed.rendered == ("v0001",) and resumed.skipped == ("v0000",)
    comparison = filecmp.dircmp(local.output, copy)
    assert _differences(comparison) == []


def _differences(comparison: filecmp.dircmp[str]) -> list[str]:
    _, mismatch, errors = filecmp.cmpfiles(
        comparison.left, comparison.right, comparison.common_files, shallow=False
    )
    found = [*mismatch, *errors, *comparison.left_only, *comparison.right_only]
    for sub in comparison.subdirs.values():
        found += _differences(sub)
    return found


def test_one_worker_renders_the_same_bytes(local: DatasetReport, tmp_path: Path) -> None:
    """One worker in this process, Blender on every core (two workers had one core each)."""
    report = dataset([PROMPT], tmp_path / "one", workers=1, **SETTINGS)
    assert report.images == 4
    assert _differences(filecmp.dircmp(local.output, report.output)) == []


def test_ray_renders_the_same_bytes(local: DatasetReport, tmp_path: Path) -> None:
    pytest.importorskip("ray")
    report = dataset([PROMPT], tmp_path / "ray", executor="ray", **SETTINGS)
    assert report.images == 4
    assert _differences(filecmp.dircmp(local.output, report.output)) == []


@pytest.mark.parametrize(
    ("change", "message"),
    [
        ({"camera": "satellite"}, "unknown camera"),
        ({"resolution": (4, 4)}, "resolution"),
        ({"weeds": "loads"}, "weed density"),
        ({"views": 0}, "views"),
        ({"executor": "dask"}, "unknown executor"),
        ({"device": "tpu"}, "unknown render device"),
    ],
)
def test_bad_settings_fail_before_rendering(
    tmp_path: Path, change: dict[str, Any], message: str
) -> None:
    with pytest.raises(ConfigurationError, match=message):
        dataset([PROMPT], tmp_path / "bad", **{**SETTINGS, **change})
    assert not (tmp_path / "bad").exists()
