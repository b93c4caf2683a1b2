"""The Gazebo backend: world.sdf valid against the SDFormat XSDs, meshes resolve, poses and
plant counts match plants.csv, markers and spawn pose agree with the layout."""

from __future__ import annotations

import csv
import math
import re
import shutil
import xml.etree.ElementTree as ET
from pathlib import Path
from typing import Any

import numpy as np
import pytest

from agrirecipe import BackendError, ConfigurationError, Scene
from agrirecipe.backends import available_backends, get_backend
from agrirecipe.backends._gazebo._meshes import STL_RECORD, chunk_bounds
from agrirecipe.backends.gazebo import GazeboBackend, field_variants
from agrirecipe.plants import field_assets

EXAMPLES = Path(__file__).resolve().parents[2] / "examples" / "recipes"
# a rotated maize field beside strawberries on mulched beds; a vineyard turned 45 degrees
RECIPES = ["maize-test-rows-east-west", "pinot-noir-vineyard-harvest"]
# Debian's sdformat-sdf (scripts/install.sh): /usr/share/sdformat<N>/1.7/*.xsd
SDF_SCHEMAS = next(iter(sorted(Path("/usr/share").glob("sdformat*/1.7"))), Path("/nonexistent"))


def _stub(name: str) -> str:
    return (
        "<?xml version='1.0'?><xsd:schema xmlns:xsd='http://www.w3.org/2001/XMLSchema'>"
        f"<xsd:element name='{name}'><xsd:complexType><xsd:sequence>"
        "<xsd:any minOccurs='0' maxOccurs='unbounded' processContents='skip'/>"
        "</xsd:sequence><xsd:anyAttribute processContents='skip'/></xsd:complexType>"
        "</xsd:element></xsd:schema>"
    )


def _types_xsd() -> str:
    """The SDFormat value types (vector3, pose, color...), as the spec defines them."""
    number = r"[-+]?(\d+(\.\d*)?|\.\d+)([eE][-+]?\d+)?"

    def numbers(count: int) -> str:
        return rf"\s*{number}(\s+{number}){{{count - 1}}}\s*"

    patterns = {
        "vector3": numbers(3),
        "vector2d": numbers(2),
        "vector2i": r"\s*[-+]?\d+\s+[-+]?\d+\s*",
        "quaternion": numbers(4),
        "pose": numbers(6),
        "color": numbers(4),
        "time": r"\s*\d+\s+\d+\s*",
    }
    types = "".join(
        f'<xsd:simpleType name="{name}"><xsd:restriction base="xsd:string">'
        f'<xsd:pattern value="{pattern}"/></xsd:restriction></xsd:simpleType>'
        for name, pattern in patterns.items()
    )
    return f"<?xml version='1.0'?><xsd:schema xmlns:xsd='http://www.w3.org/2001/XMLSchema'>{types}</xsd:schema>"


@pytest.fixture(scope="session")
def sdf_schema(tmp_path_factory: pytest.TempPathFactory) -> Any:
    """The SDFormat 1.7 XSDs of Debian's ``sdformat-sdf``, made loadable offline.

    Three repairs, each to a known defect of the generated XSDs, none loosening what
    we emit: includes point at http://sdformat.org/schemas/ (made local);
    ``types.xsd`` and ``navsat.xsd`` are not shipped (types written from the spec,
    navsat stubbed: we write no sensors); ``state.xsd`` redeclares ``<model>``
    (stubbed: we write no state); and ``<pose>`` is declared empty although it
    holds six numbers (given its ``pose`` type).
    """
    etree = pytest.importorskip("lxml.etree", reason="lxml (the test extra) validates the SDF")
    if not (SDF_SCHEMAS / "root.xsd").is_file():
        pytest.skip("the SDFormat XSDs are missing: apt-get install sdformat-sdf")
    folder = tmp_path_factory.mktemp("sdformat-1.7")
    for source in SDF_SCHEMAS.glob("*.xsd"):
        text = source.read_text("utf-8").replace("http://sdformat.org/schemas/", "")
        (folder / source.name).write_text(text, "utf-8")
    (folder / "types.xsd").write_text(_types_xsd(), "utf-8")
    (folder / "state.xsd").write_text(_stub("state"), "utf-8")
    for schema in list(folder.glob("*.xsd")):
        for location in re.findall(r"schemaLocation='([^']*)'", schema.read_text("utf-8")):
            if not (folder / location).exists():
                (folder / location).write_text(_stub(location.removesuffix(".xsd")), "utf-8")
    pose = folder / "pose.xsd"
    text = pose.read_text("utf-8")
    opening = "<xsd:element name='pose'>\n    <xsd:complexType>"
    closing = "    </xsd:complexType>\n  </xsd:element>\n</xsd:schema>"
    assert opening in text and closing in text, "pose.xsd changed: revisit the repair"
    text = text.replace(
        opening, opening + "<xsd:simpleContent><xsd:extension base='pose'>", 1
    ).replace(closing, "</xsd:extension></xsd:simpleContent>" + closing, 1)
    pose.write_text(text, "utf-8")
    return etree.XMLSchema(etree.parse(str(folder / "root.xsd")))


@pytest.fixture(scope="module", params=RECIPES)
def written(
    request: pytest.FixtureRequest, tmp_path_factory: pytest.TempPathFactory
) -> tuple[Scene, Path]:
    scene = Scene.from_file(EXAMPLES / f"{request.param}.json")
    folder = tmp_path_factory.mktemp(request.param)
    scene.write(folder, backends=["annotations", "gazebo"])
    return scene, folder


def read_csv(path: Path) -> list[dict[str, str]]:
    with path.open(encoding="utf-8", newline="") as stream:
        return list(csv.DictReader(stream))


def read_stl(path: Path) -> np.ndarray:
    data = path.read_bytes()
    (count,) = np.frombuffer(data, dtype="<u4", count=1, offset=80)
    assert len(data) == 84 + 50 * int(count), f"{path.name}: size and facet count disagree"
    return np.frombuffer(data, dtype=STL_RECORD, count=int(count), offset=84)


def numbers(text: str | None) -> list[float]:
    assert text is not None
    return [float(v) for v in text.split()]


def world(folder: Path) -> ET.Element:
    return ET.parse(folder / "gazebo" / "world.sdf").getroot()


def field_models(folder: Path) -> dict[str, ET.Element]:
    return {
        m.get("name", ""): m
        for m in world(folder).iter("model")
        if m.get("name") != "agrirecipe_ground"
    }


def mesh_path(folder: Path, uri: str) -> Path:
    assert uri.startswith("model://"), uri
    return folder / "gazebo" / "models" / uri.removeprefix("model://")


def test_registered() -> None:
    assert "gazebo" in available_backends()
    backend = get_backend("gazebo")
    assert isinstance(backend, GazeboBackend)
    assert "gazebo/world.sdf" in backend.outputs


def test_world_and_models_validate_against_the_sdformat_schema(
    written: tuple[Scene, Path], sdf_schema: Any
) -> None:
    from lxml import etree

    _, folder = written
    documents = [folder / "gazebo" / "world.sdf"]
    documents += sorted((folder / "gazebo" / "models").glob("*/model.sdf"))
    assert len(documents) >= 2
    for document in documents:
        tree = etree.parse(str(document))
        assert tree.getroot().get("version") == "1.7"
        assert sdf_schema.validate(tree), f"{document.name}: {sdf_schema.error_log}"


def test_schema_rejects_a_broken_world(sdf_schema: Any, tmp_path: Path) -> None:
    """The validator is not a rubber stamp: a wrong pose and an unknown element fail."""
    from lxml import etree

    bad = etree.fromstring(
        b"<sdf version='1.7'><world name='w'><gravity>0 0 -9.8</gravity>"
        b"<magnetic_field>0 0 0</magnetic_field><atmosphere type='adiabatic'/>"
        b"<physics type='ode'/><scene/><frame name='f'><pose>1 2</pose></frame>"
        b"<tractor/></world></sdf>"
    )
    assert not sdf_schema.validate(bad)
    messages = str(sdf_schema.error_log)
    assert "pose" in messages or "tractor" in messages


def test_every_mesh_uri_resolves_to_a_binary_stl(written: tuple[Scene, Path]) -> None:
    _, folder = written
    uris = [uri.text or "" for uri in world(folder).iter("uri")]
    assert uris
    for uri in uris:
        path = mesh_path(folder, uri)
        assert path.is_file(), uri
        assert len(read_stl(path)) > 0
    config = ET.parse(next((folder / "gazebo" / "models").glob("*/model.config"))).getroot()
    assert config.find("sdf") is not None and config.find("sdf").text == "model.sdf"  # type: ignore[union-attr]


def test_model_poses_are_the_field_frames(written: tuple[Scene, Path]) -> None:
    scene, folder = written
    models = field_models(folder)
    assert set(models) == {spec.id for spec in scene.recipe.fields}
    for spec in scene.recipe.fields:
        model = models[spec.id]
        assert model.findtext("static") == "true"
        x, y, z, roll, pitch, yaw = numbers(model.findtext("pose"))
        assert (x, y, z, roll, pitch) == pytest.approx((*spec.geometry.origin_m, 0, 0, 0), abs=1e-6)
        assert yaw == pytest.approx(math.radians(spec.geometry.rotation_deg), abs=1e-6)


def _to_world(pose: list[float], points: np.ndarray) -> np.ndarray:
    x, y, z, _, _, yaw = pose
    c, s = math.cos(yaw), math.sin(yaw)
    out = np.empty_like(points, dtype=np.float64)
    out[..., 0] = x + c * points[..., 0] - s * points[..., 1]
    out[..., 1] = y + s * points[..., 0] + c * points[..., 1]
    out[..., 2] = z + points[..., 2]
    return out


def test_merged_plants_match_plants_csv(written: tuple[Scene, Path]) -> None:
    """Instance count: each material's merged triangles are the sum of its plants' triangles
    by their plants.csv variant; position: the first triangle is plant 0's, placed by its
    plants.csv pose."""
    scene, folder = written
    plants_csv = read_csv(folder / "plants.csv")
    backend = GazeboBackend()
    for spec in scene.recipe.fields:
        rows = [r for r in plants_csv if r["field_id"] == spec.id]
        asset = field_assets(scene.recipe)[spec.id]
        variants = field_variants(spec, asset, scene.knowledge)
        model = field_models(folder)[spec.id]
        pose = numbers(model.findtext("pose"))
        link = next(link for link in model.iter("link") if link.get("name") == "plants")
        per_material: dict[str, int] = {}
        files: dict[str, list[Path]] = {}
        for visual in link.iter("visual"):
            name = visual.get("name", "")
            _, material = re.fullmatch(r"(plants_c\d{3})_(\w+)", name).groups()  # type: ignore[union-attr]
            path = mesh_path(folder, visual.findtext("geometry/mesh/uri") or "")
            per_material[material] = per_material.get(material, 0) + len(read_stl(path))
            files.setdefault(material, []).append(path)
        counts = np.bincount([int(r["variant"]) for r in rows], minlength=len(variants))
        for material, total in per_material.items():
            expected = sum(
                int(counts[v]) * len(variants[v][material].corners)
                for v in range(len(variants))
                if material in variants[v]
            )
            assert total == expected, f"{spec.id} {material}: not one instance per plant"
        first_material = next(iter(variants[0]))
        first = read_stl(sorted(files[first_material])[0])["corners"][0].astype(np.float64)
        plant = rows[0]
        assert plant["variant"] == "0"
        yaw = math.radians(float(plant["yaw_deg"])) - math.radians(spec.geometry.rotation_deg)
        template = variants[0][first_material].corners[0] * float(plant["scale"])
        c, s = math.cos(yaw), math.sin(yaw)
        local = np.stack(
            [c * template[:, 0] - s * template[:, 1], s * template[:, 0] + c * template[:, 1]], 1
        )
        got = _to_world(pose, first)[:, :2]
        origin = _to_world(pose, np.zeros((1, 3)))[0, :2]
        rotated = _to_world([0, 0, 0, 0, 0, pose[5]], np.c_[local, np.zeros(3)])[:, :2]
        assert np.allclose(
            got, rotated + np.array([float(plant["x_m"]), float(plant["y_m"])]), atol=2e-3
        )
        assert np.allclose(origin, spec.geometry.origin_m)
        assert backend.max_chunk_triangles >= max(
            len(read_stl(p)) for f in files.values() for p in f
        )


def test_markers_agree_with_plants_csv(written: tuple[Scene, Path]) -> None:
    scene, folder = written
    plants = read_csv(folder / "plants.csv")
    markers = read_csv(folder / "gazebo" / "markers.csv")
    plant_markers = [m for m in markers if m["kind"] == "plant"]
    assert len(plant_markers) == len(plants) == scene.layout.plant_count
    for marker, plant in zip(plant_markers, plants, strict=True):
        assert (marker["field_id"], marker["x_m"], marker["y_m"], marker["z_m"]) == (
            plant["field_id"],
            plant["x_m"],
            plant["y_m"],
            plant["z_m"],
        )
    for spec in scene.recipe.fields:
        ids = [int(m["id"]) for m in plant_markers if m["field_id"] == spec.id]
        assert ids == list(range(len(ids)))
        lines = [m for m in markers if m["kind"] == "row" and m["field_id"] == spec.id]
        assert len(lines) == spec.row_count * spec.agronomy.rows_per_bed or len(lines) >= 1
        starts = np.array([[float(m["x_m"]), float(m["y_m"])] for m in lines])
        ends = np.array([[float(m["end_x_m"]), float(m["end_y_m"])] for m in lines])
        length = np.linalg.norm(ends - starts, axis=1)
        assert np.allclose(length, length[0], atol=1e-3) and length[0] > 0
        rows = [int(m["row"]) for m in plant_markers if m["field_id"] == spec.id]
        assert rows == sorted(rows), "plants run row by row"
        # every plant lies on its row's line, within jitter (far less than half a row gap)
        xy = np.array(
            [[float(m["x_m"]), float(m["y_m"])] for m in plant_markers if m["field_id"] == spec.id]
        )
        a, b = starts[rows], ends[rows]
        direction = (b - a) / np.linalg.norm(b - a, axis=1, keepdims=True)
        offset = xy - a
        across = np.abs(offset[:, 0] * direction[:, 1] - offset[:, 1] * direction[:, 0])
        gap = spec.agronomy.row_spacing_m
        if spec.agronomy.rows_per_bed > 1:
            gap = min(gap, spec.agronomy.bed_row_spacing_m)
        assert across.max() < gap / 2.0


def test_spawn_pose_is_at_the_start_of_the_first_row(written: tuple[Scene, Path]) -> None:
    scene, folder = written
    text = (folder / "gazebo" / "spawn.yaml").read_text("utf-8")
    values = dict(
        line.split(": ", 1) for line in text.splitlines() if line and not line.startswith("#")
    )
    spawn = [float(values[k]) for k in ("x", "y", "z", "yaw")]
    frame = next(f for f in world(folder).iter("frame") if f.get("name") == "robot_spawn")
    x, y, z, _, _, yaw = numbers(frame.findtext("pose"))
    assert [x, y, z, yaw] == pytest.approx(spawn, abs=1e-4)
    first = scene.recipe.fields[0]
    assert values["field_id"] == first.id
    markers = read_csv(folder / "gazebo" / "markers.csv")
    lines = [m for m in markers if m["kind"] == "row" and m["field_id"] == first.id][:2]
    start = np.array([[float(m["x_m"]), float(m["y_m"])] for m in lines]).mean(axis=0)
    end = np.array([[float(m["end_x_m"]), float(m["end_y_m"])] for m in lines]).mean(axis=0)
    along = (end - start) / np.linalg.norm(end - start)
    # facing along the rows, just before their start, in the lane between rows 0 and 1
    assert [math.cos(yaw), math.sin(yaw)] == pytest.approx(list(along), abs=1e-6)
    behind = float((np.array([x, y]) - start) @ along)
    assert -1.0 - 1e-3 <= behind < 0.0  # spawn.yaml and markers.csv hold 0.1 mm decimals
    assert np.linalg.norm(np.array([x, y]) - (start + behind * along)) < 1e-3


def test_sun_follows_the_recipe(written: tuple[Scene, Path]) -> None:
    scene, folder = written
    light = next(iter(world(folder).iter("light")))
    assert light.get("type") == "directional"
    dx, dy, dz = numbers(light.findtext("direction"))
    sun = scene.recipe.environment.sun
    assert dz == pytest.approx(-math.sin(math.radians(sun.elevation_deg)), abs=1e-5)
    # light travels away from the sun: its compass bearing is the azimuth's opposite
    bearing = math.degrees(math.atan2(-dx, -dy)) % 360.0
    assert bearing == pytest.approx(sun.azimuth_deg % 360.0, abs=1e-3)


def test_chunks_cap_triangles_and_keep_every_plant(tmp_path: Path) -> None:
    scene = Scene.from_file(EXAMPLES / "pinot-noir-vineyard-harvest.json")
    GazeboBackend().write(scene, tmp_path / "big")
    GazeboBackend(max_chunk_triangles=200_000).write(scene, tmp_path / "small")
    totals = {}
    for name in ("big", "small"):
        meshes = sorted((tmp_path / name / "gazebo/models/vineyard/meshes").glob("plants_*.stl"))
        totals[name] = (len(meshes), sum(len(read_stl(p)) for p in meshes))
        if name == "small":
            assert max(len(read_stl(p)) for p in meshes) <= 200_000
    assert totals["small"][0] > totals["big"][0]
    assert totals["small"][1] == totals["big"][1]


def test_chunk_bounds_group_rows_and_cut_long_ones() -> None:
    rows = np.repeat(np.arange(4), [3, 3, 10, 2])
    chunks = chunk_bounds(rows, np.full(len(rows), 10), 60)
    # rows 0-1 together; row 2 (100 triangles) cut after 60; its rest shares a chunk with row 3
    assert [(c.start, c.stop) for c in chunks] == [(0, 6), (6, 12), (12, 18)]
    assert [(c.first_row, c.last_row) for c in chunks] == [(0, 1), (2, 2), (2, 3)]
    assert all((c.stop - c.start) * 10 <= 60 for c in chunks)
    assert chunk_bounds(rows[:0], rows[:0], 60) == []


def test_duplicate_mode_writes_leaf_backs(tmp_path: Path) -> None:
    scene = Scene.from_file(EXAMPLES / "pinot-noir-vineyard-harvest.json")
    GazeboBackend().write(scene, tmp_path / "flag")
    GazeboBackend(double_sided="duplicate").write(scene, tmp_path / "dup")
    flagged = (tmp_path / "flag/gazebo/world.sdf").read_text("utf-8")
    duplicated = (tmp_path / "dup/gazebo/world.sdf").read_text("utf-8")
    assert "<double_sided>true</double_sided>" in flagged
    assert "double_sided" not in duplicated

    def triangles(name: str) -> int:
        meshes = (tmp_path / name / "gazebo/models/vineyard/meshes").glob("plants_*.stl")
        return sum(len(read_stl(p)) for p in meshes)

    assert triangles("dup") > triangles("flag")


def test_rewrite_is_identical_and_drops_stale_files(tmp_path: Path) -> None:
    scene = Scene.from_file(EXAMPLES / "pinot-noir-vineyard-harvest.json")
    GazeboBackend(max_chunk_triangles=100_000).write(scene, tmp_path)
    meshes = tmp_path / "gazebo/models/vineyard/meshes"
    many = sorted(p.name for p in meshes.glob("*.stl"))
    stale_model = tmp_path / "gazebo/models/old_field"
    shutil.copytree(tmp_path / "gazebo/models/vineyard", stale_model)
    first = GazeboBackend().write(scene, tmp_path)
    snapshot = {p: p.read_bytes() for p in first}
    fewer = sorted(p.name for p in meshes.glob("*.stl"))
    assert len(fewer) < len(many)
    assert not stale_model.exists()
    second = GazeboBackend().write(scene, tmp_path)
    assert {p: p.read_bytes() for p in second} == snapshot


def test_a_world_over_the_triangle_cap_is_refused_before_writing(tmp_path: Path) -> None:
    scene = Scene.from_file(EXAMPLES / "pinot-noir-vineyard-harvest.json")
    with pytest.raises(BackendError, match="plant triangles") as caught:
        GazeboBackend(max_triangles=10_000).write(scene, tmp_path)
    assert "max_triangles" in (caught.value.hint or "")
    assert not (tmp_path / "gazebo").exists()


def test_proxy_for_a_crop_without_a_mesh() -> None:
    scene = Scene.from_file(EXAMPLES / "pinot-noir-vineyard-harvest.json")
    spec = scene.recipe.fields[0]
    (proxy,) = field_variants(spec, None, scene.knowledge)
    (template,) = proxy.values()
    assert len(template.corners) > 10
    assert template.corners[..., 2].max() == pytest.approx(spec.agronomy.plant_height_m)


@pytest.mark.parametrize(
    "options",
    [
        {"max_chunk_triangles": 0},
        {"max_chunk_triangles": 1.5},
        {"max_triangles": 2.5},
        {"double_sided": "both"},
        {"spawn_clearance_m": -1.0},
        {"world_name": "my world"},
    ],
)
def test_bad_options_are_configuration_errors(options: dict[str, Any]) -> None:
    with pytest.raises(ConfigurationError):
        GazeboBackend(**options)


@pytest.fixture(scope="module")
def sdformat_check(tmp_path_factory: pytest.TempPathFactory) -> Path:
    """libsdformat's own loader as a small program (Debian libsdformat-dev)."""
    import subprocess

    compiler = shutil.which("g++")
    flags = subprocess.run(
        ["pkg-config", "--cflags", "--libs", "sdformat12"], capture_output=True, text=True
    )
    if compiler is None or flags.returncode != 0:
        pytest.skip("libsdformat-dev (sdformat12) or g++ is not installed (scripts/install.sh)")
    binary = tmp_path_factory.mktemp("sdformat") / "sdformat_check"
    source = Path(__file__).with_name("sdformat_check.cc")
    subprocess.run(
        [compiler, "-std=c++17", "-O1", str(source), "-o", str(binary), *flags.stdout.split()],
        check=True,
    )
    return binary


def test_libsdformat_loads_the_world(sdformat_check: Path, written: tuple[Scene, Path]) -> None:
    import subprocess

    scene, folder = written
    result = subprocess.run(
        [str(sdformat_check), str(folder / "gazebo" / "world.sdf")],
        capture_output=True,
        text=True,
    )
    assert result.returncode == 0, result.stdout + result.stderr
    lines = result.stdout.splitlines()
    assert (
        lines[0] == f"world agrirecipe_farm models {len(scene.recipe.fields) + 1} lights 1 frames 1"
    )
    models = {line.split()[1]: line for line in lines if line.startswith("model ")}
    assert set(models) == {"agrirecipe_ground", *(f.id for f in scene.recipe.fields)}
    for spec in scene.recipe.fields:
        visuals = int(models[spec.id].rsplit(" ", 1)[1])
        assert visuals >= 2  # the soil and at least one plant mesh
