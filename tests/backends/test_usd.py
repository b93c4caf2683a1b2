"""The OpenUSD backend: the stage reopened with pxr matches plants.csv, in metres, Z up."""

from __future__ import annotations

import csv
import math
import sys
from pathlib import Path

import numpy as np
import pytest

from agrirecipe import BackendError, ConfigurationError, Scene
from agrirecipe.backends import get_backend
from agrirecipe.backends.usd import proxy_mesh, yaw_quaternions

pxr = pytest.importorskip("pxr")
from pxr import Gf, Usd, UsdGeom  # noqa: E402

EXAMPLES = sorted(
    Path(__file__).resolve().parents[2].joinpath("examples", "recipes").glob("*.json")
)


def read_plants_csv_column(path: Path, column: str) -> dict[str, list[int]]:
    """Per field: one integer column of plants.csv."""
    values: dict[str, list[int]] = {}
    with path.open(encoding="utf-8", newline="") as stream:
        for row in csv.DictReader(stream):
            values.setdefault(row["field_id"], []).append(int(row[column]))
    return values


def read_plants_csv(path: Path) -> dict[str, np.ndarray]:
    """Per field: an (n, 5) array of x, y, z, yaw_deg, scale."""
    rows: dict[str, list[list[float]]] = {}
    with path.open(encoding="utf-8", newline="") as stream:
        for row in csv.DictReader(stream):
            rows.setdefault(row["field_id"], []).append(
                [float(row[k]) for k in ("x_m", "y_m", "z_m", "yaw_deg", "scale")]
            )
    return {field: np.array(values) for field, values in rows.items()}


@pytest.fixture(scope="module", params=EXAMPLES, ids=lambda p: p.stem)
def written(
    request: pytest.FixtureRequest, tmp_path_factory: pytest.TempPathFactory
) -> tuple[Scene, Path]:
    scene = Scene.from_file(request.param)
    folder = tmp_path_factory.mktemp(request.param.stem)
    scene.write(folder, backends=["usd", "annotations"])
    return scene, folder


def test_examples_exist() -> None:
    assert len(EXAMPLES) >= 3
    assert any(
        f.geometry.rotation_deg != 0 for p in EXAMPLES for f in Scene.from_file(p).recipe.fields
    ), "one example has a rotated field"


def test_stage_is_in_metres_with_z_up(written: tuple[Scene, Path]) -> None:
    _, folder = written
    stage = Usd.Stage.Open(str(folder / "scene.usda"))
    assert UsdGeom.GetStageMetersPerUnit(stage) == 1.0
    assert UsdGeom.GetStageUpAxis(stage) == UsdGeom.Tokens.z
    assert stage.HasAuthoredMetadata("metersPerUnit") and stage.HasAuthoredMetadata("upAxis")
    assert stage.GetDefaultPrim().GetPath() == "/World"


def test_instance_transforms_match_plants_csv(written: tuple[Scene, Path]) -> None:
    scene, folder = written
    stage = Usd.Stage.Open(str(folder / "scene.usda"))
    truth = read_plants_csv(folder / "plants.csv")
    time = Usd.TimeCode.Default()
    instancers = [p for p in stage.Traverse() if p.IsA(UsdGeom.PointInstancer)]
    assert len(instancers) == len(scene.recipe.fields)
    for spec in scene.recipe.fields:
        instancer = UsdGeom.PointInstancer(stage.GetPrimAtPath(f"/World/Fields/{spec.id}/Plants"))
        assert instancer, spec.id
        matrices = instancer.ComputeInstanceTransformsAtTime(time, time)
        expected = truth[spec.id]
        assert len(matrices) == len(expected) == scene.layout.field(spec.id).plant_count
        m = np.array([np.array(matrix) for matrix in matrices])  # (n, 4, 4), row vectors
        translation = m[:, 3, :3]
        assert np.allclose(translation, expected[:, :3], atol=2e-3), spec.id
        # Row 0 is the image of +X: scale * (cos yaw, sin yaw, 0).
        scale = np.linalg.norm(m[:, 0, :3], axis=1)
        assert np.allclose(scale, expected[:, 4], rtol=2e-3), spec.id
        assert np.allclose(np.linalg.norm(m[:, 2, :3], axis=1), expected[:, 4], rtol=2e-3)
        assert np.allclose(m[:, 0, 2], 0.0, atol=1e-6) and np.allclose(m[:, 2, :2], 0.0, atol=1e-6)
        yaw = np.arctan2(m[:, 0, 1], m[:, 0, 0])
        difference = np.angle(np.exp(1j * (yaw - np.radians(expected[:, 3]))))
        assert np.abs(difference).max() < math.radians(0.25), spec.id  # half-precision quaternions


def test_prototypes_reference_the_plant_meshes_and_name_the_asset(
    written: tuple[Scene, Path],
) -> None:
    scene, folder = written
    stage = Usd.Stage.Open(str(folder / "scene.usda"))
    variants = {
        field: np.array(values)
        for field, values in read_plants_csv_column(folder / "plants.csv", "variant").items()
    }
    for spec in scene.recipe.fields:
        instancer = UsdGeom.PointInstancer(stage.GetPrimAtPath(f"/World/Fields/{spec.id}/Plants"))
        targets = instancer.GetPrototypesRel().GetTargets()
        assert len(targets) == 3
        stem = spec.asset_path.rsplit(".", 1)[1]
        for variant, target in enumerate(targets):
            prototype = stage.GetPrimAtPath(target)
            assert target.name == f"{stem}_v{variant}"
            assert str(target).startswith(str(instancer.GetPath()))  # not drawn on its own
            assert prototype.GetAttribute("agrirecipe:asset_path").Get() == spec.asset_path
            assert prototype.GetAttribute("agrirecipe:crop").Get() == spec.crop
            assert prototype.GetAttribute("agrirecipe:variety").Get() == spec.variety
            assert prototype.GetAttribute("agrirecipe:variant").Get() == variant
            assert prototype.GetAssetInfo()["name"] == stem
            # The payload resolves: the mesh file is beside the stage and composes in.
            (payload,) = prototype.GetMetadata("payload").GetAddedOrExplicitItems()
            assert (folder / payload.assetPath).is_file()
            meshes = [p for p in Usd.PrimRange(prototype) if p.IsA(UsdGeom.Mesh)]
            assert meshes, f"{target} holds no mesh"
            bound = UsdGeom.Imageable(prototype).ComputeLocalBound(
                Usd.TimeCode.Default(), UsdGeom.Tokens.default_
            )
            box = bound.ComputeAlignedRange()
            low, high = np.array(box.GetMin()), np.array(box.GetMax())
            agronomy = spec.agronomy
            height, width = agronomy.plant_height_m, agronomy.canopy_width_m
            assert 0.0 <= low[2] <= max(0.02 * height, 0.01)  # standing on the ground
            assert high[2] == pytest.approx(height, rel=0.05)
            # Across the row the canopy; along it a trellis may span the in-row spacing.
            assert high[0] - low[0] <= 1.05 * width
            assert high[1] - low[1] <= 1.05 * max(width, agronomy.in_row_spacing_m)
        # Instance i shows the variant plants.csv names for it.
        indices = np.array(instancer.GetProtoIndicesAttr().Get())
        assert np.array_equal(indices, variants[spec.id])


def test_a_field_without_a_plant_mesh_gets_a_proxy(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    import agrirecipe.plants as plants

    scene = Scene.from_file(EXAMPLES[0])
    monkeypatch.setattr(
        plants, "field_assets", lambda recipe, **_: {spec.id: None for spec in recipe.fields}
    )
    stage = get_backend("usd").stage(scene)  # type: ignore[attr-defined]
    for spec in scene.recipe.fields:
        instancer = UsdGeom.PointInstancer(stage.GetPrimAtPath(f"/World/Fields/{spec.id}/Plants"))
        (target,) = instancer.GetPrototypesRel().GetTargets()
        mesh = UsdGeom.Mesh(stage.GetPrimAtPath(target.AppendChild("Proxy")))
        low, high = (np.array(v) for v in mesh.GetExtentAttr().Get())
        assert high[2] == pytest.approx(spec.agronomy.plant_height_m, rel=1e-5)
        assert low[2] == 0.0
        assert high[0] - low[0] == pytest.approx(spec.agronomy.canopy_width_m, rel=1e-5)
        assert set(instancer.GetProtoIndicesAttr().Get()) == {0}


def test_every_field_has_its_soil_under_its_plants(written: tuple[Scene, Path]) -> None:
    scene, folder = written
    stage = Usd.Stage.Open(str(folder / "scene.usda"))
    for spec in scene.recipe.fields:
        ground = UsdGeom.Mesh(stage.GetPrimAtPath(f"/World/Fields/{spec.id}/Ground"))
        points = np.array(ground.GetPointsAttr().Get())
        # it covers the field rectangle exactly (in the field's own frame)
        turn = math.radians(spec.geometry.rotation_deg)
        dx = points[:, 0] - spec.geometry.origin_m[0]
        dy = points[:, 1] - spec.geometry.origin_m[1]
        across = dx * math.cos(turn) + dy * math.sin(turn)
        along = -dx * math.sin(turn) + dy * math.cos(turn)
        width, length = spec.geometry.size_m
        assert across.min() == pytest.approx(0.0, abs=1e-3)
        assert across.max() == pytest.approx(width, abs=1e-3)
        assert along.min() == pytest.approx(0.0, abs=1e-3)
        assert along.max() == pytest.approx(length, abs=1e-3)
        # nothing rises above the plants' feet: crests and bed tops at z = 0, furrows below
        assert points[:, 2].max() == pytest.approx(0.0, abs=1e-6)
        pattern = spec.agronomy.planting_pattern
        if pattern in ("ridges", "double_rows_on_beds"):
            assert points[:, 2].min() < -0.1, spec.id
        else:
            assert np.allclose(points[:, 2], 0.0)
        field = stage.GetPrimAtPath(f"/World/Fields/{spec.id}")
        assert field.GetAttribute("agrirecipe:health").Get() == spec.health


def test_stage_is_byte_identical_when_written_again(
    written: tuple[Scene, Path], tmp_path: Path
) -> None:
    scene, folder = written
    again = get_backend("usd").write(Scene(scene.recipe), tmp_path)
    names = sorted(p.name for p in again)
    assert names[0] == "scene.usda"
    for path in again:
        assert path.read_bytes() == (folder / path.name).read_bytes()
    assert sorted(p.name for p in tmp_path.iterdir()) == ["assets", *names]
    meshes = sorted(p.relative_to(tmp_path) for p in (tmp_path / "assets").rglob("*.usdc"))
    assert len(meshes) == 3 * len({spec.asset_path for spec in scene.recipe.fields})
    for relative in meshes:  # the meshes too are byte-identical
        assert (tmp_path / relative).read_bytes() == (folder / relative).read_bytes()
    assert not [p for p in tmp_path.rglob(".*")]  # no temporary left


def test_sun_light_points_at_the_sun(written: tuple[Scene, Path]) -> None:
    scene, folder = written
    stage = Usd.Stage.Open(str(folder / "scene.usda"))
    light = UsdGeom.Xformable(stage.GetPrimAtPath("/World/Sun"))
    matrix = light.ComputeLocalToWorldTransform(Usd.TimeCode.Default())
    z_axis = matrix.TransformDir(Gf.Vec3d(0, 0, 1))
    sun = scene.recipe.environment.sun
    assert math.degrees(math.asin(z_axis[2])) == pytest.approx(sun.elevation_deg, abs=0.01)
    azimuth = math.degrees(math.atan2(z_axis[0], z_axis[1])) % 360  # clockwise from north
    assert azimuth == pytest.approx(sun.azimuth_deg, abs=0.01)


def test_yaw_quaternions_use_numpy_column_order() -> None:
    quaternions = yaw_quaternions(np.array([0.0, math.pi / 2]))
    assert quaternions.dtype == np.float16
    assert quaternions[0].tolist() == [0.0, 0.0, 0.0, 1.0]  # x, y, z, w
    rotation = Gf.Rotation(pxr.Vt.QuathArray.FromNumpy(quaternions)[1])
    assert rotation.TransformDir(Gf.Vec3d(1, 0, 0))[1] == pytest.approx(1.0, abs=1e-3)


def test_proxy_meshes_are_closed_for_every_growth_form() -> None:
    for form in ("tree", "vine", "bush", "row_crop", "leafy_head", "cereal"):
        points, counts, indices, colours = proxy_mesh(form, 2.0, 1.0, (0.1, 0.5, 0.1))  # type: ignore[arg-type]
        assert sum(counts) == len(indices) and len(colours) == len(points)
        assert set(indices) == set(range(len(points)))
        # Closed surface: every edge is shared by exactly two faces, in opposite directions.
        edges: dict[tuple[int, int], int] = {}
        start = 0
        for count in counts:
            face = indices[start : start + count]
            start += count
            for a, b in zip(face, face[1:] + face[:1], strict=True):
                edges[(a, b)] = edges.get((a, b), 0) + 1
        assert all(edges.get((b, a)) == 1 for (a, b) in edges), form
        assert max(p[2] for p in points) == 2.0 and min(p[2] for p in points) == 0.0


def test_missing_pxr_is_a_backend_error(
    written: tuple[Scene, Path], monkeypatch: pytest.MonkeyPatch, tmp_path: Path
) -> None:
    scene, _ = written
    monkeypatch.setitem(sys.modules, "pxr", None)
    with pytest.raises(BackendError, match="usd-core"):
        get_backend("usd").write(scene, tmp_path)


def test_unwritable_destination_is_a_backend_error(
    written: tuple[Scene, Path], tmp_path: Path
) -> None:
    scene, _ = written
    blocker = tmp_path / "a_file"
    blocker.write_text("not a folder")
    with pytest.raises(BackendError, match=r"scene\.usda"):
        get_backend("usd").write(scene, blocker / "out")


def test_in_memory_stage_can_be_extended_before_saving(written: tuple[Scene, Path]) -> None:
    scene, _ = written
    stage = get_backend("usd").stage(scene)  # type: ignore[attr-defined]
    instancers = [p for p in stage.Traverse() if p.IsA(UsdGeom.PointInstancer)]
    assert len(instancers) == len(scene.recipe.fields)
    UsdGeom.Camera.Define(stage, "/World/Camera")  # a user's addition
    assert stage.GetPrimAtPath("/World/Camera").IsA(UsdGeom.Camera)
    assert 'def Camera "Camera"' in stage.GetRootLayer().ExportToString()


def test_large_scenes_keep_their_plants_in_a_binary_sublayer(
    written: tuple[Scene, Path], tmp_path: Path
) -> None:
    from agrirecipe.backends.usd import PLANTS_LAYER_NAME, UsdBackend

    scene, _ = written
    text = tmp_path / "text"
    UsdBackend(binary_above=None).write(scene, text)
    small = tmp_path / "small"
    UsdBackend(binary_above=0).write(scene, small)
    assert not (text / PLANTS_LAYER_NAME).exists()
    assert (small / PLANTS_LAYER_NAME).is_file()
    assert (small / "scene.usda").stat().st_size < (text / "scene.usda").stat().st_size
    root = (small / "scene.usda").read_text(encoding="utf-8")
    assert f"@./{PLANTS_LAYER_NAME}@" in root and "anon:" not in root
    # both compose to the same instances
    time = Usd.TimeCode.Default()
    for path in (text, small):
        stage = Usd.Stage.Open(str(path / "scene.usda"))
        for spec in scene.recipe.fields:
            instancer = UsdGeom.PointInstancer(
                stage.GetPrimAtPath(f"/World/Fields/{spec.id}/Plants")
            )
            count = len(instancer.ComputeInstanceTransformsAtTime(time, time))
            assert count == scene.layout.field(spec.id).plant_count
    # writing a small scene over a large one leaves no stale binary layer behind
    UsdBackend(binary_above=None).write(scene, small)
    assert not (small / PLANTS_LAYER_NAME).exists()
    with pytest.raises(ConfigurationError):
        UsdBackend(binary_above=-1)
