"""The Blender backend: a bpy script that builds the scene, and headless rendering.

:class:`BlenderBackend` writes ``blender_build.py``. Run it headless with
Blender, or with Python where the ``bpy`` module is installed::

    blender -b -P blender_build.py -- --render scene.png --resolution 1920x1080
    python blender_build.py --render scene.png --save scene.blend

The script is small whatever the plant count: it holds the render settings
(variables at its top), the standard-library placement kernel
(:func:`agrirecipe.layout.kernel_source`) verbatim, the per-field kernel
parameters and proxy plans as one data literal, and the builder
(``_blender/scene_builder.py``) verbatim. Blender therefore computes exactly
the positions ``plants.csv`` holds. Starting from Blender's empty factory
scene, it makes:

- per field, a collection named by the field id holding a point-cloud mesh
  object of that name (one vertex per plant, with ``yaw``, ``scale``,
  ``height_m`` and ``variant`` point attributes) whose Geometry Nodes modifier
  instances a plant on every point (Instance on Points; Collection Info + Pick
  Instance over the field's shape variants by ``variant``, the column of
  ``plants.csv``; rotation from ``yaw``, uniform scale from ``scale``), so a
  million plants build in seconds;
- the plants are the plant library's meshes (:mod:`agrirecipe.plants`), imported
  from the ``.glb`` files in ``assets/`` beside the script (written with it);
  with ``--plants proxies``, or where a file is missing, procedural proxy
  plants per growth form (tree, vine, bush, row crop, leafy
  head, cereal) built from primitive meshes, sized by the field's plant height
  and canopy width, whose look follows the agronomy's foliage state (leafless
  trees keep only trunk and branches, autumn and senescent colours, blossom
  when flowering, fruit in ``fruit_rgb`` when fruiting) and ``foliage_rgb``
  (which carries the ill tint); proportions and colours come from
  ``_blender/style.yaml``;
- a soil quad under each field and a larger grass base, a sun lamp from
  ``recipe.environment.sun``, an oblique camera framing every field, a sky;
- render settings: CPU Cycles with few samples (denoised), or Workbench.

Coordinates need no conversion: the recipe and Blender are both right-handed,
Z up, in metres. No text from the recipe becomes code: labels and names are
only ever inside the escaped data literal.

:func:`render` builds and renders a scene to PNG (in this process through
``bpy``, or in a child Python process); :func:`build` only builds it.
"""

from __future__ import annotations

import ast
import importlib.util
import math
import os
import pprint
import subprocess
import sys
import tempfile
import time
from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from importlib import resources
from pathlib import Path
from typing import TYPE_CHECKING, Any, ClassVar, Literal

from agrirecipe._errors import BackendError, ConfigurationError
from agrirecipe._files import write_atomic
from agrirecipe.backends._base import Backend
from agrirecipe.backends._blender._proxies import BlenderStyle, load_style, proxy_plan
from agrirecipe.recipe import SceneRecipe

if TYPE_CHECKING:
    from agrirecipe._scene import Scene
    from agrirecipe.knowledge import KnowledgeBase

__all__ = [
    "ENGINES",
    "SCRIPT_NAME",
    "BlenderBackend",
    "BuildReport",
    "EngineName",
    "RenderSettings",
    "blender_script",
    "build",
    "render",
    "scene_description",
]

#: The file :meth:`BlenderBackend.write` creates.
SCRIPT_NAME = "blender_build.py"
EngineName = Literal["cycles", "workbench", "eevee"]
#: Render engines :class:`RenderSettings` accepts (EEVEE works but is very slow on CPU).
ENGINES: tuple[EngineName, ...] = ("cycles", "workbench", "eevee")
PlantMode = Literal["meshes", "proxies"]
ViewName = Literal["overview", "ground"]
#: Render cameras: an oblique view of every field, or a robot's eye in the first field.
VIEWS: tuple[ViewName, ...] = ("overview", "ground")
#: How plants are drawn: the plant library's meshes, or the builder's proxies.
PLANT_MODES: tuple[PlantMode, ...] = ("meshes", "proxies")
_MAX_PIXELS_PER_SIDE = 16384
_MAX_SAMPLES = 4096
_LOG_LINES = 25


@dataclass(frozen=True)
class RenderSettings:
    """How a generated script renders: image size, samples and engine.

    The defaults render a 960 x 540 image with 16 CPU Cycles samples, denoised,
    with the plant library's meshes (``plants="proxies"``: the simple proxies).
    Out-of-range values raise :class:`~agrirecipe.ConfigurationError`.
    """

    resolution: tuple[int, int] = (960, 540)
    samples: int = 16
    engine: EngineName = "cycles"
    denoise: bool = True
    plants: PlantMode = "meshes"
    view: ViewName = "overview"

    def __post_init__(self) -> None:
        resolution = self.resolution
        if (
            not isinstance(resolution, tuple)
            or len(resolution) != 2
            or not all(isinstance(v, int) and not isinstance(v, bool) for v in resolution)
            or not all(1 <= v <= _MAX_PIXELS_PER_SIDE for v in resolution)
        ):
            raise ConfigurationError(
                f"resolution {resolution!r} is not a (width, height) pair of pixel counts",
                stage="render",
                hint=f"two integers from 1 to {_MAX_PIXELS_PER_SIDE}, e.g. (960, 540)",
            )
        if (
            isinstance(self.samples, bool)
            or not isinstance(self.samples, int)
            or not (1 <= self.samples <= _MAX_SAMPLES)
        ):
            raise ConfigurationError(
                f"samples {self.samples!r} is not a sample count",
                stage="render",
                hint=f"an integer from 1 to {_MAX_SAMPLES}; 8-32 is plenty with denoising",
            )
        if self.engine not in ENGINES:
            raise ConfigurationError(
                f"unknown render engine {self.engine!r}",
                stage="render",
                hint="engines: " + ", ".join(ENGINES),
            )
        if self.view not in VIEWS:
            raise ConfigurationError(
                f"unknown view {self.view!r}", stage="render", hint="views: " + ", ".join(VIEWS)
            )
        if self.plants not in PLANT_MODES:
            raise ConfigurationError(
                f"unknown plant mode {self.plants!r}",
                stage="render",
                hint="plants: " + ", ".join(PLANT_MODES),
            )


@dataclass(frozen=True)
class BuildReport:
    """What a scene build made: plants per field id, and how long it took.

    ``timings`` splits ``seconds`` into ``kernel`` (placing plants with the
    inlined kernel), ``points`` (filling the point clouds), ``proxies`` (proxy
    meshes and materials) and ``rest`` (scene, ground, light, camera).
    """

    plants: Mapping[str, int]
    seconds: float
    timings: Mapping[str, float]

    @property
    def plant_count(self) -> int:
        """Plants in all fields."""
        return sum(self.plants.values())


def _recipe_of(scene: Scene | SceneRecipe) -> SceneRecipe:
    return scene if isinstance(scene, SceneRecipe) else scene.recipe


def _knowledge_of(scene: Scene | SceneRecipe) -> KnowledgeBase | None:
    return None if isinstance(scene, SceneRecipe) else scene.knowledge


def scene_description(
    scene: Scene | SceneRecipe, style: BlenderStyle | None = None
) -> dict[str, Any]:
    """The data a generated script embeds: per field its kernel parameters and proxy plan.

    Plain JSON-able data (no plant positions: Blender computes those with the
    inlined kernel); its size grows with the number of fields, not plants.
    """
    from agrirecipe import __version__
    from agrirecipe.layout import field_parameters, ground_colours, ground_spec
    from agrirecipe.layout._kernel import KERNEL_MIN_SCALE, KERNEL_VERSION
    from agrirecipe.plants import field_assets

    recipe = _recipe_of(scene)
    style = style or load_style()
    assets = field_assets(recipe, knowledge=_knowledge_of(scene))
    fields = []
    for spec, params in zip(recipe.fields, field_parameters(recipe), strict=True):
        variation = spec.placement.size_variation
        # The tallest plant the kernel can produce: uniform size noise spans ±sqrt(3) s.d.
        tallest = spec.agronomy.plant_height_m * max(1.0 + 3**0.5 * variation, KERNEL_MIN_SCALE)
        fields.append(
            {
                "id": spec.id,
                "label": spec.label,
                "crop": spec.crop,
                "variety": spec.variety,
                "stage": spec.stage,
                "season": spec.season,
                "health": spec.health,
                "asset_path": spec.asset_path,
                "corners_m": [[round(x, 6), round(y, 6)] for x, y in spec.geometry.corners_m()],
                "max_plant_height_m": round(tallest, 6),
                "params": params,
                "ground_view": ground_view(params, tallest),
                "ground": ground_spec(spec, params),
                "proxy": proxy_plan(spec, style),
                "assets": None
                if (asset := assets[spec.id]) is None
                else {"files": list(asset.files), "scale": list(asset.scale)},
            }
        )
    colours = style.colours
    return {
        "generator": {"agrirecipe": __version__, "kernel_version": KERNEL_VERSION},
        "environment": {
            "season": recipe.environment.season,
            "latitude_deg": recipe.environment.latitude_deg,
            "sun": recipe.environment.sun.model_dump(),
        },
        "ground_colours": {k: list(v) for k, v in ground_colours().items()},
        "style": {
            "colours": {"soil": colours.soil, "ground": colours.ground, "sky": colours.sky},
            "camera": style.camera.model_dump(),
            "sun": style.sun.model_dump(),
            "world": style.world.model_dump(),
        },
        "fields": fields,
    }


#: A robot's camera height (metres); taller crops raise it to 60 % of the plants.
GROUND_EYE_M = 1.4


def ground_view(params: Mapping[str, Any], tallest_m: float) -> dict[str, Any]:
    """Where a robot's-eye camera stands in a field: before the first plants, between
    the first two rows (or beside a single row), at eye height, looking along the rows.

    Returns ``{"location_m": [x, y, z], "bearing_deg": b}`` (compass bearing of the
    rows' local +Y: the field rotation turns +Y towards -X, so b = -rotation).
    """
    from agrirecipe.layout._kernel import plant_grid

    beds, rows_per_bed, _, x_start, y_start = plant_grid(dict(params))
    if rows_per_bed > 1:
        between = float(params["bed_row_spacing_m"]) / 2.0
    elif beds > 1:
        between = float(params["row_spacing_m"]) / 2.0
    else:
        between = 0.75
    local_x, local_y = x_start + between, max(y_start - 2.0, 0.0)
    turn = math.radians(float(params["rotation_deg"]))
    origin = params["origin_m"]
    x = float(origin[0]) + local_x * math.cos(turn) - local_y * math.sin(turn)
    y = float(origin[1]) + local_x * math.sin(turn) + local_y * math.cos(turn)
    eye = max(GROUND_EYE_M, 0.6 * tallest_m)
    return {
        "location_m": [round(x, 6), round(y, 6), round(eye, 6)],
        "bearing_deg": round(-float(params["rotation_deg"]) % 360.0, 6),
    }


def _python_literal(data: Any) -> str:
    """``data`` as a readable, ASCII-only Python literal that evaluates back to ``data``.

    ``pprint`` writes strings with ``repr``, so quotes, newlines and code in a
    label stay inside a string; non-ASCII characters (only ever inside string
    literals) become escapes. The round trip is checked, not assumed.
    """
    text = pprint.pformat(data, width=100, sort_dicts=False)
    text = text.encode("ascii", "backslashreplace").decode("ascii")
    if ast.literal_eval(text) != data:  # pragma: no cover - a bug, never user input
        raise BackendError("the scene description did not survive quoting", stage="compile")
    return text


def _without_header(source: str) -> str:
    """A module's source without its docstring (the script keeps one at its top)."""
    tree = ast.parse(source)
    first = tree.body[0] if tree.body else None
    if isinstance(first, ast.Expr) and isinstance(first.value, ast.Constant):
        return "\n".join(source.splitlines()[first.end_lineno :]).lstrip("\n")
    return source


def _builder_source() -> str:
    return (
        resources.files("agrirecipe.backends._blender")
        .joinpath("scene_builder.py")
        .read_text(encoding="utf-8")
    )


def _settings_block(
    settings: RenderSettings,
    render_png: str | None,
    save_blend: str | None,
    verbose: bool,
    assets_root: str | None,
) -> str:
    width, height = settings.resolution
    return "\n".join(
        [
            "# --- settings: edit here, or pass options after `--` (they win) ---",
            f"RESOLUTION = ({width}, {height})  # pixels",
            f"SAMPLES = {settings.samples}  # render samples (Cycles, EEVEE) or anti-aliasing",
            f"ENGINE = {settings.engine!r}  # 'cycles' (CPU), 'workbench' or 'eevee'",
            f"DENOISE = {settings.denoise!r}  # Cycles denoising (OpenImageDenoise)",
            f"RENDER_PNG = {render_png!r}  # a .png path to render to after building",
            f"SAVE_BLEND = {save_blend!r}  # a .blend path to save the built scene to",
            f"VERBOSE = {verbose!r}  # print progress",
            f"PLANTS = {settings.plants!r}  # 'meshes' (the .glb files in assets/) or 'proxies'",
            f"VIEW = {settings.view!r}  # 'overview' or 'ground' (a robot's eye in the rows)",
            f"ASSETS_ROOT = {assets_root!r}  # the folder holding assets/ (None: this script's)",
        ]
    )


_HEADER = '''\
# agrirecipe: Blender scene build script (generated; edit the settings below).
#
# Builds the scene of a recipe in Blender with Geometry Nodes instancing:
#     blender -b -P {script} -- --render scene.png --resolution 1920x1080
#     python {script} --render scene.png --save scene.blend   (bpy module)
# Options: --render PNG, --save BLEND, --resolution WxH, --samples N,
#          --engine cycles|workbench|eevee, --plants meshes|proxies, --assets DIR,
#          --view overview|ground
# Without options the scene is only built (headless: nothing is written).
# {fields} field(s), {nominal:,} planting positions; agrirecipe {version}.
"""Build an agrirecipe scene in Blender (generated by agrirecipe's Blender backend)."""

import sys

'''

_TAIL = """


# --- run ---
if __name__ == "__main__":
    AGRIRECIPE_REPORT = main(
        SCENE,
        place_field,
        {
            "resolution": RESOLUTION,
            "samples": SAMPLES,
            "engine": ENGINE,
            "denoise": DENOISE,
            "render_png": RENDER_PNG,
            "save_blend": SAVE_BLEND,
            "verbose": VERBOSE,
            "plants": PLANTS,
            "view": VIEW,
            "assets_root": ASSETS_ROOT,
        },
        sys.argv,
    )
"""


def blender_script(
    scene: Scene | SceneRecipe,
    settings: RenderSettings | None = None,
    *,
    render_png: str | os.PathLike[str] | None = None,
    save_blend: str | os.PathLike[str] | None = None,
    verbose: bool = True,
    assets_root: str | os.PathLike[str] | None = None,
) -> str:
    """The bpy script that builds ``scene`` (see the module docstring).

    ``settings`` become the variables at the script's top; with ``render_png``
    (or ``save_blend``) the script also renders (or saves) after building.
    ``assets_root`` is the folder whose ``assets/`` holds the plant meshes
    (default: the folder the script is run from).
    """
    from agrirecipe import __version__
    from agrirecipe.layout import ground_source, kernel_source

    recipe = _recipe_of(scene)
    settings = settings or RenderSettings()
    description = scene_description(recipe)
    parts = [
        _HEADER.format(
            script=SCRIPT_NAME,
            fields=len(recipe.fields),
            nominal=recipe.drawn_plant_count,
            version=__version__,
        ),
        _settings_block(
            settings,
            None if render_png is None else os.fspath(render_png),
            None if save_blend is None else os.fspath(save_blend),
            verbose,
            None if assets_root is None else os.fspath(assets_root),
        ),
        "\n\n# --- placement kernel: agrirecipe.layout, inlined verbatim ---\n",
        kernel_source().rstrip(),
        "\n\n\n# --- soil surface: agrirecipe.layout._ground, inlined verbatim ---\n",
        _without_header(ground_source()).rstrip(),
        "\n\n\n# --- the scene: kernel parameters and proxy plans per field (data only) ---\n",
        "SCENE = " + _python_literal(description),
        "\n\n\n# --- builder: agrirecipe.backends._blender.scene_builder, inlined verbatim ---\n",
        _builder_source().rstrip(),
        _TAIL,
    ]
    return "".join(parts)


class BlenderBackend(Backend):
    """Writes ``blender_build.py``: the scene built in Blender with Geometry Nodes instancing."""

    name: ClassVar[str] = "blender"
    outputs: ClassVar[tuple[str, ...]] = (SCRIPT_NAME,)

    def script(self, scene: Scene) -> str:
        """The generated bpy script with the default :class:`RenderSettings`."""
        return blender_script(scene)

    def write(self, scene: Scene, directory: Path) -> list[Path]:
        """Write ``blender_build.py`` into ``directory`` atomically, its meshes to ``assets/``."""
        from agrirecipe.plants import write_scene_assets

        write_scene_assets(scene.recipe, directory, knowledge=scene.knowledge)
        return [write_atomic(Path(directory) / SCRIPT_NAME, self.script(scene))]


# --- running scripts in Blender ---


def _require_bpy() -> None:
    if importlib.util.find_spec("bpy") is None:
        raise BackendError(
            "Blender's Python module bpy is not installed",
            stage="render",
            hint="pip install 'agrirecipe[blender]' (bpy 5.0 needs Python 3.11), or run "
            "blender_build.py with Blender: blender -b -P blender_build.py",
        )


def _run_in_process(script: str) -> dict[str, Any]:
    """Execute a generated script with this process's ``bpy``; bpy failures -> BackendError."""
    _require_bpy()
    namespace: dict[str, Any] = {"__name__": "agrirecipe_blender_build"}
    try:
        import bpy  # noqa: F401 - fail here, not half-way through the script

        exec(compile(script, SCRIPT_NAME, "exec"), namespace)
        settings = {
            "resolution": namespace["RESOLUTION"],
            "samples": namespace["SAMPLES"],
            "engine": namespace["ENGINE"],
            "denoise": namespace["DENOISE"],
            "render_png": namespace["RENDER_PNG"],
            "save_blend": namespace["SAVE_BLEND"],
            "verbose": namespace["VERBOSE"],
            "plants": namespace["PLANTS"],
            "view": namespace["VIEW"],
            "assets_root": namespace["ASSETS_ROOT"],
        }
        report: dict[str, Any] = namespace["main"](
            namespace["SCENE"], namespace["place_field"], settings, ()
        )
    except Exception as exc:  # everything the generated script raises comes from Blender
        raise BackendError(
            f"Blender failed to build the scene: {type(exc).__name__}: {exc}", stage="render"
        ) from exc
    return report


def run_bpy_child(script: Path, args: Sequence[str] = (), *, timeout_s: float | None) -> None:
    """Run a bpy script in a child Python process (a fresh Blender state, in the script's
    folder); a time-out or a failure is a BackendError with the end of Blender's log."""
    _require_bpy()
    try:
        completed = subprocess.run(
            [sys.executable, str(script), *args],
            cwd=script.parent,
            capture_output=True,
            text=True,
            errors="replace",
            timeout=timeout_s,
            check=False,
        )
    except subprocess.TimeoutExpired as exc:
        raise BackendError(
            f"Blender did not finish within {timeout_s:g} s",
            stage="render",
            hint="lower the resolution or samples, or pass a longer timeout",
        ) from exc
    if completed.returncode != 0:
        log = (completed.stdout + completed.stderr).strip().splitlines()
        tail = "\n".join(log[-_LOG_LINES:])
        raise BackendError(
            f"Blender exited with status {completed.returncode}:\n{tail}", stage="render"
        )


def _run_isolated(script: str, timeout_s: float | None) -> None:
    """Run a generated script in a child Python process (a fresh Blender state)."""
    with tempfile.TemporaryDirectory(prefix="agrirecipe-blender-") as folder:
        path = Path(folder) / SCRIPT_NAME
        path.write_text(script, encoding="utf-8")
        run_bpy_child(path, timeout_s=timeout_s)


def _cached_assets(scene: Scene | SceneRecipe) -> Path:
    """A folder whose ``assets/`` holds the scene's plant meshes (in the cache folder)."""
    from agrirecipe.knowledge import default_knowledge_base
    from agrirecipe.localmodels import cache_dir
    from agrirecipe.plants import write_scene_assets

    knowledge = _knowledge_of(scene) or default_knowledge_base()
    root = cache_dir() / "plants" / knowledge.digest()[:16]
    write_scene_assets(_recipe_of(scene), root, knowledge=knowledge)
    return root


def build(scene: Scene | SceneRecipe, *, verbose: bool = False) -> BuildReport:
    """Build the scene in this process's ``bpy`` (replacing whatever Blender held).

    Needs the ``bpy`` module (``pip install 'agrirecipe[blender]'``); Blender
    errors raise :class:`~agrirecipe.BackendError`.
    """
    report = _run_in_process(
        blender_script(scene, verbose=verbose, assets_root=_cached_assets(scene))
    )
    return BuildReport(
        plants=dict(report["plants"]),
        seconds=float(report["seconds"]),
        timings={name: float(value) for name, value in report["timings"].items()},
    )


def render(
    scene: Scene | SceneRecipe,
    png_path: str | os.PathLike[str],
    *,
    resolution: tuple[int, int] = (960, 540),
    samples: int = 16,
    engine: EngineName = "cycles",
    denoise: bool = True,
    plants: PlantMode = "meshes",
    view: ViewName = "overview",
    isolated: bool = False,
    timeout_s: float | None = None,
    save_blend: str | os.PathLike[str] | None = None,
    verbose: bool = False,
) -> Path:
    """Build ``scene`` in Blender and render it headless on the CPU to ``png_path``.

    By default Blender runs in this process through ``bpy`` (which holds one
    scene at a time: whatever it held is replaced). With ``isolated=True`` it
    runs in a child Python process instead, which leaves this process's
    Blender state alone and survives Blender crashes; ``timeout_s`` bounds it.
    The PNG appears atomically (rendered to a temporary name, then renamed).
    With ``save_blend`` the built scene is also saved as a ``.blend`` file.
    Returns the PNG's path. Bad settings raise
    :class:`~agrirecipe.ConfigurationError`, Blender failures
    :class:`~agrirecipe.BackendError`.
    """
    settings = RenderSettings(
        resolution=resolution,
        samples=samples,
        engine=engine,
        denoise=denoise,
        plants=plants,
        view=view,
    )
    target = Path(png_path)
    if target.suffix.lower() != ".png":
        raise ConfigurationError(
            f"render output {str(target)!r} is not a .png file",
            stage="render",
            hint="name the output like scene.png",
        )
    if target.is_dir():
        raise ConfigurationError(f"render output {str(target)!r} is a folder", stage="render")
    target = target.resolve()
    target.parent.mkdir(parents=True, exist_ok=True)
    temporary = target.with_name(f".{target.stem}.{os.getpid()}.{time.time_ns()}.tmp.png")
    blend = None if save_blend is None else Path(save_blend).resolve()
    if blend is not None:
        if blend.suffix.lower() != ".blend":
            raise ConfigurationError(
                f"{str(save_blend)!r} is not a .blend file", stage="render", hint="e.g. scene.blend"
            )
        blend.parent.mkdir(parents=True, exist_ok=True)
    script = blender_script(
        scene,
        settings,
        render_png=temporary,
        save_blend=blend,
        verbose=verbose,
        assets_root=_cached_assets(scene) if settings.plants == "meshes" else None,
    )
    try:
        if isolated:
            _run_isolated(script, timeout_s)
        else:
            _run_in_process(script)
        if not temporary.is_file() or temporary.stat().st_size == 0:
            raise BackendError(
                "Blender finished but wrote no image", stage="render", hint=f"expected {temporary}"
            )
        temporary.replace(target)
    finally:
        temporary.unlink(missing_ok=True)
    return target
