"""The plant library (issue 9): valid meshes of the knowledge base's size, within budget,
that a real glTF loader reads, byte-identical for the same inputs, showing the state."""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np
import pytest
import trimesh

from agrirecipe import AgrirecipeError, ConfigurationError
from agrirecipe.cli import main
from agrirecipe.hierarchy import AssetKey
from agrirecipe.knowledge import KnowledgeBase
from agrirecipe.plants import build_library, glb_bytes, plant_mesh, plant_spec
from agrirecipe.plants._library import _shapes

STAGES = ("Vegetative", "Reproductive", "Maturation")
SEASONS = ("Spring", "Summer", "Fall", "Winter")


def sample(knowledge: KnowledgeBase) -> list[AssetKey]:
    """Every crop at every stage and season, healthy and ill (its default variety)."""
    keys = []
    for key in knowledge.hierarchy.assets():
        if key.variety == knowledge.default_variety(key.crop):
            keys.append(key)
    return keys


def test_every_mesh_is_valid_sized_and_within_budget(knowledge: KnowledgeBase) -> None:
    budgets = _shapes()["budgets"]
    keys = sample(knowledge)
    assert len(keys) == 16 * len(STAGES) * len(SEASONS) * 2
    for key in keys:
        spec = plant_spec(knowledge, key)
        mesh = plant_mesh(knowledge, key, variant=1)
        assert 0 < mesh.triangle_count <= budgets[spec.archetype], key
        (x0, y0, z0), (x1, y1, z1) = mesh.bounds
        # exactly the knowledge base's height; its canopy width across the row (a vine's
        # wires run the row's in-row spacing along it)
        assert z0 >= 0.0 and z1 == pytest.approx(spec.height_m, rel=0.05), key
        across = 2 * max(abs(x0), abs(x1))
        width = across if spec.archetype == "vine" else max(across, 2 * max(abs(y0), abs(y1)))
        assert width == pytest.approx(spec.width_m, rel=0.05), key
        for primitive in mesh.primitives:
            p = primitive.positions[primitive.triangles].astype(np.float64)
            area = np.linalg.norm(np.cross(p[:, 1] - p[:, 0], p[:, 2] - p[:, 0]), axis=1)
            assert area.min() > 0.0, (key, primitive.material.name)  # no degenerate faces
            assert np.allclose(np.linalg.norm(primitive.normals, axis=1), 1.0, atol=1e-3)
            assert primitive.triangles.max() < len(primitive.positions)
            assert len(primitive.uvs) == len(primitive.positions)


def test_closed_parts_face_outwards(knowledge: KnowledgeBase) -> None:
    """Winding and normals agree: a fruit's faces point away from its centre."""
    key = AssetKey("Fruits", "Orange", "Valencia", "Maturation", "Winter", "Healthy")
    mesh = plant_mesh(knowledge, key)
    for primitive in mesh.primitives:
        p = primitive.positions[primitive.triangles].astype(np.float64)
        face = np.cross(p[:, 1] - p[:, 0], p[:, 2] - p[:, 0])
        vertex_normals = primitive.normals[primitive.triangles].mean(axis=1)
        agree = np.einsum("ij,ij->i", face, vertex_normals) > 0
        assert agree.mean() > 0.97, primitive.material.name


def materials(knowledge: KnowledgeBase, *key: str) -> dict[str, int]:
    mesh = plant_mesh(knowledge, AssetKey(*key))
    return {p.material.name: len(p.triangles) for p in mesh.primitives}


def test_the_plant_shows_its_stage_season_and_health(knowledge: KnowledgeBase) -> None:
    # a deciduous tree is bare in winter, blossoms in spring, bears ripe fruit
    assert "leaf" not in materials(
        knowledge, "Fruits", "Apple", "Gala", "Maturation", "Winter", "Healthy"
    )
    assert "flower" in materials(
        knowledge, "Fruits", "Apple", "Gala", "Reproductive", "Spring", "Healthy"
    )
    assert "fruit" in materials(
        knowledge, "Fruits", "Apple", "Gala", "Maturation", "Summer", "Healthy"
    )
    # maize carries its tassel once it flowers; wheat its ears
    assert "tassel" in materials(
        knowledge, "Cereals", "Maize", "Dent", "Reproductive", "Summer", "Healthy"
    )
    assert "ear" in materials(
        knowledge, "Cereals", "Wheat", "Durum", "Maturation", "Summer", "Healthy"
    )
    # an ill plant shows the disease on a share of its leaves, not a uniform tint
    ill = materials(knowledge, "Vegetables", "Potato", "Bintje", "Vegetative", "Summer", "Ill")
    share = ill["leaf_ill"] / (ill["leaf_ill"] + ill["leaf"])
    assert 0.25 < share < 0.55
    assert "leaf_ill" not in materials(
        knowledge, "Vegetables", "Potato", "Bintje", "Vegetative", "Summer", "Healthy"
    )
    # ripe fruit has the crop's fruit colour; unripe fruit is greener
    ripe = plant_mesh(
        knowledge, AssetKey("Fruits", "Orange", "Valencia", "Maturation", "Winter", "Healthy")
    )
    fruit = next(p.material for p in ripe.primitives if p.material.name == "fruit")
    assert (
        fruit.rgb
        == knowledge.agronomy(
            AssetKey("Fruits", "Orange", "Valencia", "Maturation", "Winter", "Healthy")
        ).fruit_rgb
    )


def test_variants_differ_and_a_variant_is_always_the_same(knowledge: KnowledgeBase) -> None:
    key = AssetKey("Fruits", "Cherry", "Kordia", "Maturation", "Summer", "Healthy")
    one, two = plant_mesh(knowledge, key, 0), plant_mesh(knowledge, key, 1)
    assert one.primitives[0].positions.tobytes() != two.primitives[0].positions.tobytes()
    again = plant_mesh(knowledge, key, 0)
    assert glb_bytes(one, name="a", generator="g", extras={}) == glb_bytes(
        again, name="a", generator="g", extras={}
    )


def test_the_library_loads_in_a_real_gltf_reader_and_is_byte_identical(
    knowledge: KnowledgeBase, tmp_path: Path
) -> None:
    first = build_library(tmp_path / "a", knowledge=knowledge, crops=["Onion"], variants=2)
    second = build_library(
        tmp_path / "b", knowledge=knowledge, crops=["Onion"], variants=2, workers=2
    )
    onions = [k for k in knowledge.hierarchy.assets() if k.crop == "Onion"]
    assert len(first) == len(onions) * 2 and [f.file for f in first] == [f.file for f in second]
    for a, b in zip(first, second, strict=True):
        assert (tmp_path / "a" / a.file).read_bytes() == (tmp_path / "b" / b.file).read_bytes()
    manifest = json.loads((tmp_path / "a" / "manifest.json").read_text())
    assert manifest == json.loads((tmp_path / "b" / "manifest.json").read_text())
    entry = manifest["assets"][0]
    assert entry["file"].startswith("Vegetables/Onion/") and entry["file"].endswith("_v0.glb")
    assert knowledge.hierarchy.parse_asset_path(entry["asset_path"]).crop == "Onion"
    scene = trimesh.load(tmp_path / "a" / entry["file"], force="scene")
    loaded = sum(len(g.faces) for g in scene.geometry.values())
    assert loaded == entry["triangles"]
    # glTF is Y-up: the plant stands along +Y, as tall as the manifest says
    assert scene.bounds[1][1] == pytest.approx(entry["bounds_m"][1][2], abs=1e-3)


def test_bad_requests_are_clear_errors(knowledge: KnowledgeBase, tmp_path: Path) -> None:
    with pytest.raises(ConfigurationError, match="variants"):
        build_library(tmp_path, knowledge=knowledge, variants=0)
    with pytest.raises(AgrirecipeError, match="Kiwi"):
        build_library(tmp_path, knowledge=knowledge, crops=["Kiwi"])
    assert not any(tmp_path.iterdir())  # nothing half-written


def test_assets_build_command(
    knowledge: KnowledgeBase, tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    carrots = sum(1 for k in knowledge.hierarchy.assets() if k.crop == "Carrot")
    code = main(
        [
            "assets",
            "build",
            "-o",
            str(tmp_path),
            "--crop",
            "Carrot",
            "--variants",
            "1",
            "--no-progress",
        ]
    )
    assert code == 0
    assert f"wrote {carrots} meshes" in capsys.readouterr().out
    assert len(list(tmp_path.rglob("*.glb"))) == carrots
    assert (tmp_path / "manifest.json").is_file()
