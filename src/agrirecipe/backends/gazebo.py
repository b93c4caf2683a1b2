"""The Gazebo backend: ``gazebo/world.sdf``, a model folder per field, spawn pose, markers.

Writes, under ``gazebo/`` in the output folder::

    world.sdf                    SDFormat 1.7 world: sun, ground, every field model inline,
                                 a <frame name="robot_spawn">
    spawn.yaml                   the robot's spawn pose (x, y, z, yaw) in the world frame
    markers.csv                  ground truth map: every plant and every row line
    models/<field id>/           one static model per field (loadable on its own too)
        model.config, model.sdf
        meshes/ground_<part>.stl the field's soil (ridges, beds), mulch, track
        meshes/plants_c<k>_<material>.stl   chunk k of the plants, one file per material

Frames: the world frame is the recipe's and ``plants.csv``'s (metres, X east,
Y north, Z up). A field model's pose is the field's origin and rotation; its
meshes are in the field's own frame. Plants are merged per group of rows
(:mod:`agrirecipe.backends._gazebo._meshes`): a mesh never exceeds
``max_chunk_triangles`` triangles, and the world has a few visuals per field
whatever its plant count. Mesh URIs are ``model://<field id>/meshes/...``:
put ``gazebo/models`` on ``GZ_SIM_RESOURCE_PATH`` (gz-sim) or
``GAZEBO_MODEL_PATH`` (Gazebo Classic); ``docs/GAZEBO.md`` shows the commands.
"""

from __future__ import annotations

import copy
import math
import shutil
import xml.etree.ElementTree as ET
from pathlib import Path
from typing import TYPE_CHECKING, Any, ClassVar, Literal

import numpy as np

from agrirecipe import __version__
from agrirecipe._errors import BackendError, ConfigurationError
from agrirecipe._files import write_atomic
from agrirecipe.backends._base import Backend
from agrirecipe.backends._gazebo._meshes import (
    Template,
    chunk_bounds,
    stl_records,
    template,
    templates,
    write_chunk_meshes,
    write_stl,
)
from agrirecipe.backends._gazebo._sdf import (
    SDF_VERSION,
    child,
    mesh_visual,
    pose_text,
    sdf_text,
    sun_light,
    world_element,
)
from agrirecipe.backends._gazebo._truth import (
    FieldRows,
    field_rows,
    spawn_pose,
    write_markers_csv,
)

if TYPE_CHECKING:
    from agrirecipe._scene import Scene
    from agrirecipe.knowledge import KnowledgeBase
    from agrirecipe.layout import FieldPlants
    from agrirecipe.plants import FieldAsset
    from agrirecipe.recipe import FieldSpec

__all__ = [
    "GAZEBO_FOLDER",
    "MAX_CHUNK_TRIANGLES",
    "MAX_WORLD_TRIANGLES",
    "DoubleSided",
    "GazeboBackend",
    "field_variants",
]

#: How double-sided plant parts are drawn (see :class:`GazeboBackend`).
DoubleSided = Literal["flag", "duplicate"]

#: The folder of an output directory the backend writes into.
GAZEBO_FOLDER = "gazebo"
#: Default cap on the triangles of one merged plant mesh (a 50 MB STL file).
MAX_CHUNK_TRIANGLES = 1_000_000
#: The most plant triangles a world may hold (about 2.3 GiB of STL; 100,000 maize
#: plants are about 43 million): larger worlds are refused before anything is written.
MAX_WORLD_TRIANGLES = 50_000_000
_GRASS_RGB = (0.33, 0.45, 0.22)
_MARKER = "agrirecipe"  # model.config files carrying it are ours to replace


def field_variants(
    spec: FieldSpec,
    asset: FieldAsset | None,
    knowledge: KnowledgeBase | None = None,
    *,
    duplicate: bool = False,
) -> list[dict[str, Template]]:
    """The shapes a field's plants are drawn with: one template set per shape variant.

    The plant library's meshes (the same variants as ``assets/`` and the ``variant``
    column of ``plants.csv``), or, for a crop the knowledge base cannot draw, the
    USD backend's proxy silhouette in the foliage colour.
    """
    from agrirecipe.knowledge import default_knowledge_base
    from agrirecipe.plants import plant_mesh
    from agrirecipe.plants._scene import _key

    knowledge = knowledge or default_knowledge_base()
    if asset is not None:
        return [
            templates(plant_mesh(knowledge, _key(spec), variant), asset.scale, duplicate=duplicate)
            for variant in range(asset.variants)
        ]
    from agrirecipe.backends.usd import proxy_mesh

    agronomy = spec.agronomy
    points, counts, indices, _ = proxy_mesh(
        agronomy.growth_form,
        agronomy.plant_height_m,
        agronomy.canopy_width_m,
        agronomy.foliage_rgb,
    )
    triangles: list[list[int]] = []
    offset = 0
    for count in counts:
        face = indices[offset : offset + count]
        triangles += [[face[0], face[k], face[k + 1]] for k in range(1, count - 1)]
        offset += count
    corners = np.asarray(points, dtype=np.float64)[np.asarray(triangles, dtype=np.int64)]
    proxy = template("proxy", agronomy.foliage_rgb, corners)
    return [{proxy.material: proxy}]


class GazeboBackend(Backend):
    """Writes a Gazebo world (gz-sim and Gazebo Classic 11) with ground truth.

    ``max_chunk_triangles`` caps each merged plant mesh (default
    :data:`MAX_CHUNK_TRIANGLES`); ``max_triangles`` caps the whole world's plant
    meshes (default :data:`MAX_WORLD_TRIANGLES`, about 2.3 GiB of STL), checked before
    anything is written. ``double_sided`` says how thin double-sided parts
    (leaf blades) show both faces: ``"flag"`` sets the SDF material's
    ``<double_sided>`` (gz-sim honours it; Gazebo Classic ignores it and culls leaf
    backs), ``"duplicate"`` writes their triangles twice, the copy reversed (right in
    both simulators, about 60 % more triangles for a maize field).
    ``spawn_clearance_m`` is how far before the first plant of the first row the robot
    starts; ``world_name`` names the SDF world.
    """

    name: ClassVar[str] = "gazebo"
    outputs: ClassVar[tuple[str, ...]] = (
        f"{GAZEBO_FOLDER}/world.sdf",
        f"{GAZEBO_FOLDER}/spawn.yaml",
        f"{GAZEBO_FOLDER}/markers.csv",
    )

    def __init__(
        self,
        *,
        max_chunk_triangles: int = MAX_CHUNK_TRIANGLES,
        max_triangles: int = MAX_WORLD_TRIANGLES,
        double_sided: DoubleSided = "flag",
        spawn_clearance_m: float = 1.0,
        world_name: str = "agrirecipe_farm",
    ) -> None:
        if double_sided not in ("flag", "duplicate"):
            raise ConfigurationError(
                f"unknown double_sided mode {double_sided!r}",
                stage="compile",
                hint="'flag' (gz-sim draws both faces) or 'duplicate' (also Gazebo Classic)",
            )
        if isinstance(max_chunk_triangles, bool) or not isinstance(max_chunk_triangles, int):
            raise ConfigurationError(
                f"max_chunk_triangles must be a whole number, got {max_chunk_triangles!r}",
                stage="compile",
            )
        if max_chunk_triangles < 1:
            raise ConfigurationError(
                f"max_chunk_triangles must be at least 1, got {max_chunk_triangles}",
                stage="compile",
                hint="the default is 1,000,000 triangles (a 50 MB STL file)",
            )
        if not math.isfinite(spawn_clearance_m) or spawn_clearance_m < 0.0:
            raise ConfigurationError(
                f"spawn_clearance_m must be a distance >= 0, got {spawn_clearance_m!r}",
                stage="compile",
            )
        if not world_name or not world_name.replace("_", "").isalnum():
            raise ConfigurationError(
                f"world_name must be letters, digits and underscores, got {world_name!r}",
                stage="compile",
            )
        if isinstance(max_triangles, bool) or not isinstance(max_triangles, int):
            raise ConfigurationError(
                f"max_triangles must be a whole number, got {max_triangles!r}", stage="compile"
            )
        self.max_chunk_triangles = max_chunk_triangles
        self.max_triangles = max_triangles
        self.double_sided: DoubleSided = double_sided
        self.spawn_clearance_m = spawn_clearance_m
        self.world_name = world_name

    def write(self, scene: Scene, directory: Path) -> list[Path]:
        """Write the world, the field models and their meshes, ``spawn.yaml`` and
        ``markers.csv`` into ``directory/gazebo`` (each file atomically)."""
        folder = Path(directory) / GAZEBO_FOLDER
        try:
            return self._write(scene, folder)
        except OSError as exc:
            raise BackendError(
                f"could not write the Gazebo world to {str(folder)!r}: {exc}",
                stage="compile",
                hint="check the output folder is writable and has space",
            ) from exc

    def _write(self, scene: Scene, folder: Path) -> list[Path]:
        from agrirecipe.layout import field_parameters
        from agrirecipe.plants import field_assets

        recipe = scene.recipe
        parameters = {str(p["id"]): p for p in field_parameters(recipe)}
        assets = field_assets(recipe, knowledge=scene.knowledge)
        sdf, world = world_element(self.world_name)
        corners = [c for spec in recipe.fields for c in spec.geometry.corners_m()]
        centre = (
            (min(x for x, _ in corners) + max(x for x, _ in corners)) / 2.0,
            (min(y for _, y in corners) + max(y for _, y in corners)) / 2.0,
        )
        sun = recipe.environment.sun
        sun_light(world, sun.elevation_deg, sun.azimuth_deg, centre)
        _ground_plane(world, scene, parameters)

        cache: dict[str, list[dict[str, Template]]] = {}
        keys: dict[str, str] = {}
        for plants in scene.layout.fields:
            spec = plants.spec
            asset = assets[spec.id]
            keys[spec.id] = key = asset.asset_path if asset is not None else f"proxy:{spec.id}"
            if key not in cache:
                duplicate = self.double_sided == "duplicate"
                cache[key] = field_variants(spec, asset, scene.knowledge, duplicate=duplicate)
        self._check_size(scene, cache, keys)

        written: list[Path] = []
        truth: list[tuple[FieldPlants, FieldRows]] = []
        for plants in scene.layout.fields:
            spec = plants.spec
            params = parameters[spec.id]
            rows = field_rows(plants, params)
            truth.append((plants, rows))
            variants = cache[keys[spec.id]]
            model, files = self._field_model(folder / "models", plants, params, rows, variants)
            world.append(copy.deepcopy(model))
            written += files

        first_plants, first_rows = truth[0]
        clearance = min(self.spawn_clearance_m, max(first_rows.y_start / 2.0, 0.0))
        spawn = spawn_pose(first_plants.field_id, first_rows, clearance)
        frame = child(world, "frame", name="robot_spawn")
        child(frame, "pose", pose_text(spawn.x_m, spawn.y_m, spawn.z_m, spawn.yaw_rad))

        _remove_stale_models(folder / "models", {p.field_id for p in scene.layout.fields})
        comment = (
            f"agrirecipe {__version__} Gazebo world (recipe seed {recipe.seed}). "
            "World frame = plants.csv frame: metres, X east, Y north, Z up. Meshes are "
            "model://<field>/meshes/...: add gazebo/models to GZ_SIM_RESOURCE_PATH (gz sim) "
            "or GAZEBO_MODEL_PATH (gazebo)."
        )
        world_path = write_atomic(folder / "world.sdf", sdf_text(sdf, comment))
        spawn_path = write_atomic(folder / "spawn.yaml", spawn.yaml(self.world_name))
        markers = write_markers_csv(folder / "markers.csv", truth)
        return [world_path, spawn_path, markers, *written]

    def _check_size(
        self,
        scene: Scene,
        cache: dict[str, list[dict[str, Template]]],
        keys: dict[str, str],
    ) -> None:
        """Refuse, before writing anything, a world whose merged plant meshes would
        exceed ``max_triangles`` (about 50 bytes of STL each)."""
        from agrirecipe.plants import plant_variants

        total = 0
        for plants in scene.layout.fields:
            variants = cache[keys[plants.field_id]]
            sizes = np.array([sum(len(t.corners) for t in v.values()) for v in variants])
            total += int(sizes[plant_variants(plants.plant_count, len(variants))].sum())
        if total > self.max_triangles:
            raise BackendError(
                f"the Gazebo world would hold {total:,} plant triangles "
                f"({total * 50 / 2**30:.1f} GiB of meshes), more than the cap of "
                f"{self.max_triangles:,}",
                stage="compile",
                hint="ask for smaller fields (a few thousand plants per field load well in "
                "Gazebo), or raise it: GazeboBackend(max_triangles=N)",
            )

    def _field_model(
        self,
        models: Path,
        plants: FieldPlants,
        params: dict[str, Any],
        rows: FieldRows,
        variants: list[dict[str, Template]],
    ) -> tuple[ET.Element, list[Path]]:
        """One field's static model: its ground and its plants merged per row group."""
        from agrirecipe.plants import plant_variants

        spec = plants.spec
        folder = models / spec.id
        meshes = folder / "meshes"
        model = ET.Element("model", name=spec.id)
        child(model, "static", "true")
        child(model, "pose", pose_text(rows.origin[0], rows.origin[1], 0.0, rows.rotation_rad))
        written = _field_ground(model, meshes, spec, params, rows)

        link = child(model, "link", name="plants")
        variant = plant_variants(plants.plant_count, len(variants))
        sizes = np.array([max(len(t.corners) for t in v.values()) for v in variants])
        chunks = chunk_bounds(rows.plant_row, sizes[variant], self.max_chunk_triangles)
        local_yaw = plants.yaw_rad - rows.rotation_rad
        triangles = 0
        for chunk in chunks:
            part = slice(chunk.start, chunk.stop)
            stem = f"plants_c{chunk.index:03d}"
            for material, rgb, path, count in write_chunk_meshes(
                meshes,
                stem,
                variants,
                variant[part],
                rows.local_xy[part],
                plants.xyz[part, 2],
                local_yaw[part],
                plants.scale[part],
            ):
                two_faces = self.double_sided == "flag" and any(
                    v[material].double_sided for v in variants if material in v
                )
                mesh_visual(
                    link, f"{stem}_{material}", _uri(spec.id, path), rgb, double_sided=two_faces
                )
                written.append(path)
                triangles += count
        _remove_stale_meshes(meshes, written)

        model_sdf = ET.Element("sdf", version=SDF_VERSION)
        model_sdf.append(model)
        description = (
            f"{spec.variety} {spec.crop}, {spec.stage}, {spec.season}, {spec.health}: "
            f"{plants.plant_count} plants in {len(chunks)} row group(s), {triangles} triangles"
        )
        written.append(
            write_atomic(
                folder / "model.sdf",
                sdf_text(model_sdf, f"agrirecipe {__version__} field model: {description}"),
            )
        )
        written.append(write_atomic(folder / "model.config", _model_config(spec.id, description)))
        return model, written


def _uri(field_id: str, path: Path) -> str:
    return f"model://{field_id}/meshes/{path.name}"


def _field_ground(
    model: ET.Element, meshes: Path, spec: FieldSpec, params: dict[str, Any], rows: FieldRows
) -> list[Path]:
    """The field's soil surface (and mulch, track) as meshes in the field's frame."""
    from agrirecipe.layout import field_ground, ground_colours

    colours = ground_colours()
    link = child(model, "link", name="ground")
    written = []
    cos_r, sin_r = math.cos(rows.rotation_rad), math.sin(rows.rotation_rad)
    for part in field_ground(spec, params):
        points = np.asarray(part["points"], dtype=np.float64).reshape(-1, 3)
        dx, dy = points[:, 0] - rows.origin[0], points[:, 1] - rows.origin[1]
        local = np.stack([dx * cos_r + dy * sin_r, -dx * sin_r + dy * cos_r, points[:, 2]], 1)
        triangles = np.asarray(part["triangles"], dtype=np.int64).reshape(-1, 3)
        surface = template(str(part["part"]), colours[part["part"]], local[triangles])
        records = stl_records(surface.corners, surface.normals)
        path = write_stl(meshes / f"ground_{surface.material}.stl", records)
        mesh_visual(link, str(part["part"]), _uri(spec.id, path), surface.rgb, shadows=False)
        written.append(path)
    return written


def _ground_plane(world: ET.Element, scene: Scene, parameters: dict[str, dict[str, Any]]) -> None:
    """Grass around the fields and a flat collision plane at z = 0 for the robot."""
    from agrirecipe.layout import ground_spec
    from agrirecipe.layout._ground import ground_base_depth

    recipe = scene.recipe
    depth = max(
        [0.02]
        + [ground_base_depth(ground_spec(spec, parameters[spec.id])) for spec in recipe.fields]
    )
    corners = [c for spec in recipe.fields for c in spec.geometry.corners_m()]
    xs, ys = [x for x, _ in corners], [y for _, y in corners]
    margin = 0.1 * max(max(xs) - min(xs), max(ys) - min(ys)) + 10.0
    size = f"{max(xs) - min(xs) + 2 * margin:.3f} {max(ys) - min(ys) + 2 * margin:.3f}"
    model = child(world, "model", name="agrirecipe_ground")
    child(model, "static", "true")
    child(model, "pose", pose_text((min(xs) + max(xs)) / 2.0, (min(ys) + max(ys)) / 2.0, 0.0))
    link = child(model, "link", name="ground")
    collision = child(link, "collision", name="ground")
    plane = child(child(collision, "geometry"), "plane")
    child(plane, "normal", "0 0 1")
    child(plane, "size", size)
    visual = child(link, "visual", name="grass")
    child(visual, "cast_shadows", "false")
    # below the fields' furrows, so the grass never covers a field's soil
    child(visual, "pose", pose_text(0.0, 0.0, -depth))
    plane = child(child(visual, "geometry"), "plane")
    child(plane, "normal", "0 0 1")
    child(plane, "size", size)
    material = child(visual, "material")
    child(material, "ambient", " ".join(f"{c * 0.8:.3f}" for c in _GRASS_RGB) + " 1")
    child(material, "diffuse", " ".join(f"{c:.3f}" for c in _GRASS_RGB) + " 1")
    child(material, "specular", "0.02 0.02 0.02 1")


def _model_config(field_id: str, description: str) -> str:
    config = ET.Element("model")
    child(config, "name", field_id)
    child(config, "version", "1.0")
    child(config, "sdf", "model.sdf", version=SDF_VERSION)
    author = child(config, "author")
    child(author, "name", _MARKER)
    child(author, "email", "")
    child(config, "description", description)
    ET.indent(config, space="  ")
    return '<?xml version="1.0" encoding="UTF-8"?>\n' + ET.tostring(config, "unicode") + "\n"


def _remove_stale_meshes(meshes: Path, keep: list[Path]) -> None:
    """Delete meshes of an earlier, larger write of this field (more chunks or materials)."""
    kept = {path.name for path in keep}
    for path in meshes.glob("*.stl"):
        if path.name not in kept:
            path.unlink(missing_ok=True)


def _remove_stale_models(models: Path, field_ids: set[str]) -> None:
    """Delete the model folders we wrote for fields this recipe no longer has."""
    if not models.is_dir():
        return
    for folder in models.iterdir():
        config = folder / "model.config"
        if folder.name in field_ids or not config.is_file():
            continue
        if f"<name>{_MARKER}</name>" in config.read_text("utf-8", errors="replace"):
            shutil.rmtree(folder)
