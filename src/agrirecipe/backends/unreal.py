"""The Unreal Engine 5 backend: one editor Python script that builds the scene.

:class:`UnrealBackend` writes ``unreal_build.py``. Run it in the Unreal Editor
(Python Editor Script Plugin enabled; Tools > Execute Python Script) or
headless (one command line)::

    UnrealEditor-Cmd <project>.uproject -run=pythonscript
        -script=unreal_build.py -unattended -nullrhi

The script is small whatever the plant count: it inlines the standard-library
placement kernel (:func:`agrirecipe.layout.kernel_source`) verbatim and the
per-field kernel parameters as data, so Unreal computes exactly the positions
``plants.csv`` holds. It then, as one undo step (``ScopedEditorTransaction``)
under a cancellable progress dialog (``ScopedSlowTask``):

- spawns one plain ``Actor`` per field, labelled with the field's label and put
  in the outliner folder ``Agrirecipe/<scene>/<field id>``, holding an
  ``InstancedStaticMeshComponent`` (added through the ``SubobjectDataSubsystem``)
  whose instances are added in chunks;
- uses the field's asset (``FieldSpec.asset_path``) when the project has it, and
  otherwise an engine basic shape chosen by growth form (cone for trees,
  cylinder for cereals and vines, sphere for heads and bushes) sized like each
  plant (canopy width x height) and tinted like its foliage, with an
  ``unreal.log_warning`` naming the missing asset;
- imports each field's soil surface (ridges, raised beds, plastic mulch, headland
  track) from ``assets/ground/<field id>.glb`` and places it at the field's origin;
  a flat field without a track gets a soil-coloured ground plane (the 100 cm
  ``/Engine/BasicShapes/Plane`` scaled to the field), as does a field whose
  surface mesh cannot be imported;
- adds a ``DirectionalLight`` for the sun (plus ``SkyAtmosphere`` and
  ``SkyLight`` unless ``sky=False``).

Units and handedness: the recipe is right-handed, Z up, in metres (X east,
Y north); Unreal is left-handed, Z up, in centimetres. A point (x, y, z) m
becomes (100 x, -100 y, 100 z) cm and a yaw of a radians (counter-clockwise
seen from above) becomes ``Rotator(yaw=-degrees(a))``.

Sun: a directional light shines along its actor's forward (+X) axis. With the
recipe's sun at elevation e above the horizon and azimuth A (compass bearing
the light comes from, clockwise from north), the light travels toward the
bearing A + 180 and downward, so ``pitch = -e`` and, after the handedness flip
(north is Unreal -Y, east +X), ``yaw = A + 90`` (normalised to (-180, 180]).
For example the midday sun in the south (A = 180) gives yaw 270 = -90: the
light travels north.

No text from the recipe (prompt, labels) ever becomes code: everything
per-scene is one JSON document embedded as escaped string literals and parsed
with ``json.loads``.
"""

from __future__ import annotations

import ast
import hashlib
import json
import math
import re
from functools import cache
from importlib import resources
from pathlib import Path
from typing import TYPE_CHECKING, Any, ClassVar

from agrirecipe._errors import BackendError, ConfigurationError
from agrirecipe._files import write_atomic
from agrirecipe.backends._base import Backend
from agrirecipe.hierarchy import pascal_case

if TYPE_CHECKING:
    from collections.abc import Mapping

    from agrirecipe._scene import Scene
    from agrirecipe.plants import FieldAsset
    from agrirecipe.recipe import FieldSpec, SceneRecipe, Sun

__all__ = [
    "SCRIPT_NAME",
    "UnrealBackend",
    "unreal_location_cm",
    "unreal_sun_rotation",
    "unreal_yaw_deg",
]

#: The file :meth:`UnrealBackend.write` creates.
SCRIPT_NAME = "unreal_build.py"
#: Version of the JSON document the runtime reads; bumped on incompatible changes.
SCENE_FORMAT = 1

_SCENE_NAME = re.compile(r"[A-Za-z][A-Za-z0-9_]{0,63}")
# Names the generated script binds after the kernel and the runtime.
_SCRIPT_NAMES = frozenset({"SCENE_JSON", "AGRIRECIPE_RESULT", "ASSETS_ROOT"})
# Kernel entry points, best first: a generator keeps a million plants out of memory.
_KERNEL_ENTRY_POINTS = ("iter_field_plants", "place_field")
_MAX_CHUNK_SIZE = 1_000_000


def unreal_location_cm(x_m: float, y_m: float, z_m: float) -> tuple[float, float, float]:
    """A recipe point (right-handed, metres) in Unreal's left-handed centimetres."""
    # "+ 0.0" turns -0.0 into 0.0 so equal recipes print equal scripts.
    return (x_m * 100.0 + 0.0, -y_m * 100.0 + 0.0, z_m * 100.0 + 0.0)


def unreal_yaw_deg(yaw_rad: float) -> float:
    """A recipe yaw (radians, counter-clockwise seen from above) as an Unreal yaw in degrees."""
    return -math.degrees(yaw_rad)


def unreal_sun_rotation(sun: Sun) -> tuple[float, float]:
    """``(pitch_deg, yaw_deg)`` of a DirectionalLight shining from ``sun`` (see module docs)."""
    yaw = (sun.azimuth_deg + 90.0) % 360.0
    if yaw > 180.0:
        yaw -= 360.0
    return (-sun.elevation_deg, yaw)


@cache
def _defaults() -> dict[str, Any]:
    text = (
        resources.files("agrirecipe.backends._unreal")
        .joinpath("defaults.json")
        .read_text(encoding="utf-8")
    )
    loaded: dict[str, Any] = json.loads(text)
    return loaded


@cache
def _runtime_source() -> str:
    return (
        resources.files("agrirecipe.backends._unreal")
        .joinpath("runtime.py")
        .read_text(encoding="utf-8")
    )


class UnrealBackend(Backend):
    """Compiles a scene into ``unreal_build.py``, Unreal Engine 5 editor Python.

    ``scene_name`` names the outliner folder ``Agrirecipe/<scene_name>/...``
    (default: the scene's crops and a digest of the recipe, so two scenes do
    not share folders); ``chunk_size`` is how many instances are added per
    ``add_instances`` call (and between two cancel checks); ``sky`` adds a
    SkyAtmosphere and a SkyLight next to the sun; ``save_level`` makes the
    script save the current level when it finishes (for headless runs).
    """

    name: ClassVar[str] = "unreal"
    outputs: ClassVar[tuple[str, ...]] = (SCRIPT_NAME,)

    def __init__(
        self,
        *,
        scene_name: str | None = None,
        chunk_size: int | None = None,
        sky: bool = True,
        save_level: bool = False,
    ) -> None:
        if scene_name is not None and not _SCENE_NAME.fullmatch(scene_name):
            raise ConfigurationError(
                f"scene_name {scene_name!r} cannot name an Unreal outliner folder",
                stage="compile",
                hint="use 1-64 letters, digits or underscores, starting with a letter",
            )
        size = int(_defaults()["chunk_size"]) if chunk_size is None else chunk_size
        if isinstance(size, bool) or not isinstance(size, int) or not 1 <= size <= _MAX_CHUNK_SIZE:
            raise ConfigurationError(
                f"chunk_size {chunk_size!r} is not a whole number of instances per call",
                stage="compile",
                hint=f"use an int from 1 to {_MAX_CHUNK_SIZE:,}",
            )
        self.scene_name = scene_name
        self.chunk_size = size
        self.sky = sky
        self.save_level = save_level

    def script(self, scene: Scene) -> str:
        """The editor Python that builds ``scene`` in Unreal (deterministic text)."""
        from agrirecipe.layout import field_parameters, kernel_source
        from agrirecipe.plants import field_assets

        kernel = kernel_source()
        runtime = _runtime_source()
        entry_point = _check_sources(kernel, runtime)
        assets = field_assets(scene.recipe, knowledge=scene.knowledge)
        document = self.scene_document(scene.recipe, field_parameters(scene.recipe), assets)
        return _assemble(kernel, runtime, document, scene.recipe, entry_point)

    def write(self, scene: Scene, directory: Path) -> list[Path]:
        """Write ``unreal_build.py`` into ``directory`` atomically, its meshes to ``assets/``."""
        from agrirecipe.plants import write_ground_assets, write_scene_assets

        write_scene_assets(scene.recipe, directory, knowledge=scene.knowledge)
        write_ground_assets(scene.recipe, directory)
        return [write_atomic(Path(directory) / SCRIPT_NAME, self.script(scene))]

    def scene_document(
        self,
        recipe: SceneRecipe,
        kernel_parameters: list[dict[str, Any]],
        assets: Mapping[str, FieldAsset | None] | None = None,
    ) -> dict[str, Any]:
        """The JSON-able description the script's runtime builds (all values pre-converted).

        ``assets`` are the fields' plant meshes (:func:`agrirecipe.plants.field_assets`);
        without them every field falls back to its project asset or a basic shape.
        """
        defaults = _defaults()
        assets = assets or {}
        by_id = {str(params["id"]): params for params in kernel_parameters}
        missing = [spec.id for spec in recipe.fields if spec.id not in by_id]
        if missing:
            raise BackendError(
                f"the layout gave no kernel parameters for field(s) {', '.join(missing)}",
                stage="compile",
            )
        scene_name = self.scene_name or default_scene_name(recipe)
        root = f"{defaults['folder_root']}/{scene_name}"
        fields = [
            self._field_document(spec, by_id[spec.id], root, defaults, assets.get(spec.id))
            for spec in recipe.fields
        ]
        nominal = recipe.drawn_plant_count
        # One unit per plant, plus one per field set-up and ground, plus the light.
        work = nominal + 2 * len(fields) + 1
        centre_x, centre_y = _scene_centre_m(recipe)
        pitch, yaw = unreal_sun_rotation(recipe.environment.sun)
        prompt = recipe.prompt if len(recipe.prompt) <= 300 else recipe.prompt[:297] + "..."
        return {
            "format": SCENE_FORMAT,
            "scene": {
                "name": scene_name,
                "prompt": recipe.prompt,
                "seed": recipe.seed,
                "work": work,
                "save_level": self.save_level,
                "transaction": f"agrirecipe: build scene {scene_name}",
                "title": f"agrirecipe: building {len(fields)} field(s), about {nominal:,} plants",
                "environment_progress": "agrirecipe: sun and sky",
                "log_start": f"agrirecipe: building scene {scene_name} "
                f"({len(fields)} field(s), about {nominal:,} plants) for the request {prompt!r}",
                "log_done": f"agrirecipe: scene {scene_name} built",
                "log_cancelled": f"agrirecipe: building scene {scene_name} was cancelled",
            },
            "engine": {
                "basic_shape_material": defaults["basic_shape_material"],
                "colour_parameter": defaults["colour_parameter"],
                "ground_mesh": defaults["ground_mesh"],
                "soil_rgb": list(defaults["soil_rgb"]),
                "chunk_size": self.chunk_size,
            },
            "environment": {
                "folder": f"{root}/Environment",
                "sky": self.sky,
                "sky_atmosphere_label": "Sky atmosphere",
                "sky_light_label": "Sky light",
                "sun": {
                    "label": f"Sun ({recipe.environment.season}, "
                    f"{recipe.environment.latitude_deg:g} deg latitude)",
                    "pitch_deg": pitch,
                    "yaw_deg": yaw,
                    "location_cm": list(
                        unreal_location_cm(centre_x, centre_y, float(defaults["sun_height_m"]))
                    ),
                },
            },
            "fields": fields,
        }

    def _field_document(
        self,
        spec: FieldSpec,
        kernel_parameters: dict[str, Any],
        root: str,
        defaults: dict[str, Any],
        asset: FieldAsset | None,
    ) -> dict[str, Any]:
        geometry = spec.geometry
        fallback = defaults["fallback_meshes"].get(spec.agronomy.growth_form)
        if fallback is None:
            raise BackendError(
                f"no placeholder shape for growth form {spec.agronomy.growth_form!r}",
                stage="compile",
                path=f"fields[{spec.id}].agronomy.growth_form",
                hint="known: " + ", ".join(sorted(defaults["fallback_meshes"])),
            )
        corners = geometry.corners_m()
        centre_x = sum(x for x, _ in corners) / 4.0
        centre_y = sum(y for _, y in corners) / 4.0
        width_m, length_m = geometry.size_m
        return {
            "id": spec.id,
            "label": spec.label,
            "folder": f"{root}/{spec.id}",
            "asset_path": spec.asset_path,
            "plant_meshes": None if asset is None else _plant_meshes(spec, asset),
            "fallback_mesh": fallback,
            "canopy_width_m": spec.agronomy.canopy_width_m,
            "foliage_rgb": list(spec.agronomy.foliage_rgb),
            "location_cm": list(unreal_location_cm(*geometry.origin_m, 0.0)),
            "nominal_plants": spec.drawn_plant_count(),
            "kernel": kernel_parameters,
            "progress_setup": f"agrirecipe: field {spec.id}: actor and mesh",
            "progress_plants": f"agrirecipe: field {spec.id}: plants",
            "progress_ground": f"agrirecipe: field {spec.id}: ground",
            "log_missing_asset": (
                f"agrirecipe: asset {spec.asset_path} is not a static mesh in this project "
                f"and its plant meshes could not be imported; field {spec.id} is drawn with "
                f"the placeholder {fallback} (keep the assets/ folder beside this script, "
                "or import your own asset pack, to see the real plants)"
            ),
            "ground": {
                "label": f"{spec.label} ground",
                "location_cm": list(unreal_location_cm(centre_x, centre_y, 0.0)),
                "yaw_deg": -geometry.rotation_deg,
                # The engine plane is 100 cm square: a scale of 1.0 is one metre.
                "scale": [width_m, length_m, 1.0],
                # Ridges, beds, mulch and tracks: the field's surface mesh in assets/,
                # placed at the field's origin (its own frame); the plane if it fails.
                "mesh": _ground_mesh_plan(spec, kernel_parameters, root),
            },
        }


def _ground_mesh_plan(
    spec: FieldSpec, kernel_parameters: dict[str, Any], root: str
) -> dict[str, Any] | None:
    """Where a field's surface mesh is and where it lands (None: a flat field)."""
    from agrirecipe.plants import ASSETS_FOLDER, ground_file, has_relief

    if not has_relief(spec, kernel_parameters):
        return None
    # beside the catalogue's meshes: /Game/Agriculture/Ground/<scene name>
    content_root = "/".join(spec.asset_path.split("/")[:3])
    return {
        "file": f"{ASSETS_FOLDER}/{ground_file(spec.id)}",
        "destination_path": f"{content_root}/Ground/{root.rsplit('/', 1)[-1]}",
        "name": f"SM_Ground_{spec.id}",
        "origin_cm": list(unreal_location_cm(*spec.geometry.origin_m, 0.0)),
    }


def _plant_meshes(spec: FieldSpec, asset: FieldAsset) -> dict[str, Any]:
    """Where a field's shape variants are and where they are imported to in the project."""
    folder, _, _ = spec.asset_path.rpartition("/")
    return {
        "files": list(asset.files),
        "destination_path": folder,
        "names": [Path(relative).stem for relative in asset.files],
        "scale": list(asset.scale),
    }


def default_scene_name(recipe: SceneRecipe) -> str:
    """A folder-safe scene name: the crops, then a digest of the recipe (stable per recipe)."""
    crops: list[str] = []
    for spec in recipe.fields:
        crop = pascal_case(spec.crop)
        if crop not in crops:
            crops.append(crop)
    digest = hashlib.sha256(
        json.dumps(recipe.model_dump(mode="json"), sort_keys=True).encode("utf-8")
    ).hexdigest()[:8]
    stem = re.sub(r"[^A-Za-z0-9_]", "", "_".join(crops))[:48] or "Scene"
    if not stem[0].isalpha():
        stem = "Scene_" + stem
    return f"{stem}_{digest}"


def _scene_centre_m(recipe: SceneRecipe) -> tuple[float, float]:
    points = [corner for spec in recipe.fields for corner in spec.geometry.corners_m()]
    xs = [x for x, _ in points]
    ys = [y for _, y in points]
    return ((min(xs) + max(xs)) / 2.0, (min(ys) + max(ys)) / 2.0)


def _top_level_bindings(source: str, label: str) -> tuple[dict[str, str], str]:
    """Names a module binds at top level (imports map to what they import), and its first
    kernel entry point found."""
    try:
        tree = ast.parse(source)
    except SyntaxError as exc:
        raise BackendError(
            f"the {label} source is not valid Python: {exc}", stage="compile"
        ) from exc
    names: dict[str, str] = {}
    for node in tree.body:
        if isinstance(node, ast.Import | ast.ImportFrom):
            module = node.module if isinstance(node, ast.ImportFrom) else ""
            for alias in node.names:
                names[alias.asname or alias.name.split(".")[0]] = f"import {module}:{alias.name}"
        elif isinstance(node, ast.FunctionDef | ast.AsyncFunctionDef | ast.ClassDef):
            names[node.name] = "definition"
        elif isinstance(node, ast.Assign | ast.AnnAssign | ast.AugAssign):
            targets = node.targets if isinstance(node, ast.Assign) else [node.target]
            for target in targets:
                for leaf in ast.walk(target):
                    if isinstance(leaf, ast.Name):
                        names[leaf.id] = "definition"
    entry = next((name for name in _KERNEL_ENTRY_POINTS if names.get(name) == "definition"), "")
    return names, entry


def _check_sources(kernel: str, runtime: str) -> str:
    """Refuse to inline sources whose top-level names clash; return the kernel entry point."""
    kernel_names, entry_point = _top_level_bindings(kernel, "placement kernel")
    runtime_names, _ = _top_level_bindings(runtime, "Unreal runtime")
    if not entry_point:
        raise BackendError(
            "the placement kernel defines none of " + ", ".join(_KERNEL_ENTRY_POINTS),
            stage="compile",
        )
    clashes = sorted(
        name
        for name in (set(kernel_names) & set(runtime_names)) | (set(kernel_names) & _SCRIPT_NAMES)
        if kernel_names[name] != runtime_names.get(name) or kernel_names[name] == "definition"
    )
    if clashes:
        raise BackendError(
            "the placement kernel and the Unreal runtime both define " + ", ".join(clashes),
            stage="compile",
            hint="rename the kernel helper (kernel helpers start with _kernel_)",
        )
    return entry_point


def _string_literal_lines(text: str, indent: str, width: int = 76) -> str:
    """``text`` as implicitly concatenated string literals of about ``width`` characters.

    Each piece is ``repr``-escaped on its own, so cutting ``text`` anywhere is
    safe; pieces end after a comma where possible, to keep the JSON readable.
    """
    pieces: list[str] = []
    current = ""
    for token in re.split(r"(?<=,)", text):
        if current and len(current) + len(token) > width:
            pieces.append(current)
            current = ""
        while len(token) > width:
            pieces.append(token[:width])
            token = token[width:]
        current += token
    if current:
        pieces.append(current)
    return "\n".join(indent + repr(piece) for piece in pieces)


def _assemble(
    kernel: str, runtime: str, document: dict[str, Any], recipe: SceneRecipe, entry_point: str
) -> str:
    document_text = json.dumps(
        document, sort_keys=True, ensure_ascii=True, separators=(",", ":"), allow_nan=False
    )
    # Only numbers and fixed words go into comments: recipe text could end a comment line.
    header = (
        "# unreal_build.py: an agrirecipe scene for Unreal Engine 5 (generated; edit the\n"
        "# recipe and recompile rather than this file).\n"
        "#\n"
        f"# {len(recipe.fields)} field(s), about {recipe.nominal_plant_count:,} plants, "
        f"seed {recipe.seed}, scene format {SCENE_FORMAT}.\n"
        "#\n"
        "# In the editor (Python Editor Script Plugin enabled): Tools > Execute Python\n"
        "# Script, or `py <path>/unreal_build.py` in the Output Log's Python console.\n"
        "# Headless:\n"
        "#   UnrealEditor-Cmd <project>.uproject -run=pythonscript -script=unreal_build.py "
        "-unattended -nullrhi\n"
        "#\n"
        "# The build is one undo step and can be cancelled from its progress dialog.\n"
        + (
            "# When it finishes it saves the current level.\n"
            if document["scene"]["save_level"]
            else "# It does not save the level (headless runs: generate with save_level=True).\n"
        )
        + "# Plants are placed by the agrirecipe placement kernel below, the same code\n"
        "# that wrote plants.csv, from the per-field parameters in SCENE_JSON.\n"
        "# A field's asset from the project is used when it exists; otherwise the plant\n"
        "# meshes in assets/ beside this script are imported (once) into that content\n"
        "# folder, and only without them does an engine basic shape stand in, with a\n"
        "# warning in the Output Log.\n"
    )
    return (
        header
        + "\n"
        + kernel.rstrip("\n")
        + "\n\n\n"
        + runtime.rstrip("\n")
        + "\n\n\n"
        + "# The scene, as JSON (all recipe text stays inside these string literals).\n"
        + "SCENE_JSON = (\n"
        + _string_literal_lines(document_text, "    ")
        + "\n)\n\n"
        + "# The folder holding the plant meshes' assets/ folder (None: this script's folder).\n"
        + "ASSETS_ROOT = None\n\n"
        + f"AGRIRECIPE_RESULT = run(SCENE_JSON, {entry_point}, ASSETS_ROOT)\n"
    )
