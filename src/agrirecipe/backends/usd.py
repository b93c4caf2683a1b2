"""The OpenUSD backend: ``scene.usda``, one ``PointInstancer`` per field.

The stage opens in usdview, Isaac Sim, Omniverse and Unreal's USD importer
without our asset pack: each field's prototypes reference the plant library's
meshes for its asset (one prototype per shape variant, a payload of
``assets/.../SM_..._v<N>.usdc`` written beside the stage, see
:mod:`agrirecipe.plants`), and name the Unreal
asset they stand for. A field whose crop the knowledge base cannot draw gets a
simple proxy mesh sized like the plant (canopy width x height at this stage)
and coloured like its foliage instead. Layout::

    /World                       Xform, default prim, kind = assembly
        Sun                      DistantLight from the recipe's sun
        Surroundings             grass plane under the whole farm (z slightly below 0)
        Fields/<field id>        Xform with the field's attributes (agrirecipe:*)
            Ground               the soil: a quad at z = 0, or ridges / raised beds whose
                                 crests are at z = 0 (the plants' height), furrows below
            Mulch, Track         plastic mulch on the beds, headland tracks (when present)
            Plants               PointInstancer: positions, orientations, scales, protoIndices
                Prototypes/<SM_..._vN>  one shape variant: payload @./assets/...usdc@,
                                 assetInfo, agrirecipe:asset_path, crop attributes
                                 (or <SM_...> with a Proxy mesh child)

Units and axes: ``metersPerUnit = 1``, ``upAxis = Z``, right-handed, X east,
Y north, exactly the recipe's frame. Instance ``i`` of a field's instancer is
the field's ``i``-th row of ``plants.csv``, and shows the prototype of its
``variant`` column. Orientations are half-precision
quaternions (the schema's ``quath[]``) for a yaw about Z; positions and scales
are single precision, as the schema stores them.

``pxr`` (PyPI ``usd-core``, extra ``agrirecipe[usd]``) is imported on first
use; its errors become :class:`~agrirecipe.BackendError`.
"""

from __future__ import annotations

import itertools
import math
from collections.abc import Mapping
from pathlib import Path
from typing import TYPE_CHECKING, Any, ClassVar

import numpy as np

from agrirecipe import __version__
from agrirecipe._errors import BackendError, ConfigurationError
from agrirecipe._files import atomic_path, write_atomic
from agrirecipe.backends._base import Backend

if TYPE_CHECKING:
    from agrirecipe._scene import Scene
    from agrirecipe.layout import FieldPlants
    from agrirecipe.plants import FieldAsset
    from agrirecipe.recipe import FieldSpec, GrowthForm, SceneRecipe

__all__ = [
    "BINARY_ABOVE",
    "PLANTS_LAYER_NAME",
    "STAGE_NAME",
    "UsdBackend",
    "proxy_mesh",
    "yaw_quaternions",
]

#: The file :meth:`UsdBackend.write` creates.
STAGE_NAME = "scene.usda"
#: Beside it, for scenes above ``UsdBackend.binary_above`` plants: the instancers'
#: per-plant arrays as binary crate, a sublayer of ``scene.usda``.
PLANTS_LAYER_NAME = "scene_plants.usdc"
#: Plants above which the per-plant arrays go to the binary sublayer (text would be
#: about 95 bytes per plant: 95 MB per million plants).
BINARY_ABOVE = 100_000

# What a prototype (one asset) says about itself, from the field's attributes.
_ASSET_ATTRIBUTES = (
    "asset_path",
    "category",
    "crop",
    "variety",
    "stage",
    "season",
    "health",
    "growth_form",
    "plant_height_m",
)
_SOIL_RGB = (0.42, 0.31, 0.21)
_GRASS_RGB = (0.33, 0.45, 0.22)
_BARK_RGB = (0.36, 0.27, 0.20)
_SEGMENTS = 8
# Proxy silhouettes by growth form: (radius, height) pairs from the ground up, as
# fractions of half the canopy width and of the plant height, revolved about Z.
# The fraction of the height below which the proxy is drawn as stem/trunk follows.
_PROFILES: dict[str, tuple[tuple[tuple[float, float], ...], float]] = {
    "tree": (
        ((0.0, 0.0), (0.1, 0.0), (0.1, 0.35), (0.8, 0.45), (1.0, 0.7), (0.6, 0.92), (0.0, 1.0)),
        0.4,
    ),
    "vine": (((0.0, 0.0), (0.15, 0.0), (0.15, 0.3), (1.0, 0.5), (1.0, 0.9), (0.0, 1.0)), 0.35),
    "bush": (((0.0, 0.0), (0.6, 0.0), (1.0, 0.4), (0.8, 0.85), (0.0, 1.0)), 0.0),
    "row_crop": (((0.0, 0.0), (0.3, 0.0), (1.0, 0.5), (0.7, 0.9), (0.0, 1.0)), 0.0),
    "leafy_head": (((0.0, 0.0), (0.8, 0.0), (1.0, 0.35), (0.7, 0.85), (0.0, 1.0)), 0.0),
    "cereal": (((0.0, 0.0), (0.25, 0.0), (1.0, 0.8), (0.9, 1.0), (0.0, 1.0)), 0.0),
}


def yaw_quaternions(yaw_rad: np.ndarray[Any, np.dtype[np.float64]]) -> np.ndarray[Any, Any]:
    """Rotations about +Z as an (n, 4) float16 array.

    Columns are x, y, z, w: the order ``Vt.QuathArray.FromNumpy`` expects (``Gf.Quath``
    and ``.usda`` text put the real part first).
    """
    quaternions = np.zeros((yaw_rad.shape[0], 4), dtype=np.float16)
    quaternions[:, 2] = np.sin(yaw_rad * 0.5)
    quaternions[:, 3] = np.cos(yaw_rad * 0.5)
    return quaternions


def proxy_mesh(
    growth_form: GrowthForm,
    height_m: float,
    canopy_width_m: float,
    foliage_rgb: tuple[float, float, float],
) -> tuple[
    list[tuple[float, float, float]], list[int], list[int], list[tuple[float, float, float]]
]:
    """A closed lathe mesh standing on z = 0, ``height_m`` tall and ``canopy_width_m`` wide.

    Returns ``(points, face vertex counts, face vertex indices, vertex colours)``.
    """
    profile, stem_fraction = _PROFILES[growth_form]
    radius = canopy_width_m / 2.0
    points: list[tuple[float, float, float]] = []
    colours: list[tuple[float, float, float]] = []
    rings: list[list[int]] = []
    for radius_fraction, height_fraction in profile:
        z = height_fraction * height_m
        colour = _BARK_RGB if height_fraction < stem_fraction else foliage_rgb
        start = len(points)
        if radius_fraction == 0.0:
            points.append((0.0, 0.0, z))
            colours.append(colour)
        else:
            for segment in range(_SEGMENTS):
                angle = 2.0 * math.pi * segment / _SEGMENTS
                r = radius_fraction * radius
                points.append((r * math.cos(angle), r * math.sin(angle), z))
                colours.append(colour)
        rings.append(list(range(start, len(points))))
    counts: list[int] = []
    indices: list[int] = []
    for lower, upper in itertools.pairwise(rings):
        for segment in range(_SEGMENTS):
            following = (segment + 1) % _SEGMENTS
            # Counter-clockwise seen from outside: the right-handed default orientation.
            face = [
                lower[segment % len(lower)],
                lower[following % len(lower)],
                upper[following % len(upper)],
                upper[segment % len(upper)],
            ]
            face = [v for k, v in enumerate(face) if v not in face[:k]]  # poles: triangles
            counts.append(len(face))
            indices.extend(face)
    return points, counts, indices, colours


class UsdBackend(Backend):
    """Writes ``scene.usda``: metres, Z up, one ``UsdGeom.PointInstancer`` per field.

    Above ``binary_above`` plants (default :data:`BINARY_ABOVE`) the per-plant arrays
    (positions, orientations, scales, prototype indices) go to a binary sublayer,
    ``scene_plants.usdc``, so ``scene.usda`` stays a small readable file and the
    stage opens fast; ``binary_above=None`` keeps everything in the text file.
    """

    name: ClassVar[str] = "usd"
    outputs: ClassVar[tuple[str, ...]] = (STAGE_NAME,)

    def __init__(self, *, binary_above: int | None = BINARY_ABOVE) -> None:
        if binary_above is not None and (
            isinstance(binary_above, bool) or not isinstance(binary_above, int) or binary_above < 0
        ):
            raise ConfigurationError(
                f"binary_above must be a number of plants or None, got {binary_above!r}",
                stage="compile",
            )
        self.binary_above = binary_above

    def write(self, scene: Scene, directory: Path) -> list[Path]:
        """Export the stage atomically to ``directory/scene.usda``, its meshes to ``assets/``
        (and, for large scenes, the plants' arrays to ``scene_plants.usdc``)."""
        from agrirecipe.plants import write_scene_assets

        tf = _import_pxr()
        target = Path(directory) / STAGE_NAME
        binary = Path(directory) / PLANTS_LAYER_NAME
        try:
            write_scene_assets(scene.recipe, directory, knowledge=scene.knowledge, usd=True)
            stage, plants_layer = _build_stage(scene, self._binary(scene))
            root = stage.GetRootLayer()
            if plants_layer is None:
                with atomic_path(target, suffix=".usda") as temporary:
                    if not root.Export(str(temporary)):
                        raise BackendError(
                            f"pxr could not export the stage to {str(target)!r}", stage="compile"
                        )
                binary.unlink(missing_ok=True)  # a smaller scene written over a larger one
                return [target]
            with atomic_path(binary, suffix=".usdc") as temporary:
                if not plants_layer.Export(str(temporary)):
                    raise BackendError(f"pxr could not export {str(binary)!r}", stage="compile")
            # The root names its sublayer by the in-memory layer's identifier: written to
            # disk, it names the file beside it.
            text = root.ExportToString().replace(
                f"@{plants_layer.identifier}@", f"@./{PLANTS_LAYER_NAME}@"
            )
            write_atomic(target, text)
            return [target, binary]
        except (tf.ErrorException, OSError) as exc:
            raise BackendError(
                f"OpenUSD failed while writing {str(target)!r}: {exc}",
                stage="compile",
                hint="check the output folder is writable",
            ) from exc

    def _binary(self, scene: Scene) -> bool:
        return self.binary_above is not None and scene.layout.plant_count > self.binary_above

    def stage(self, scene: Scene) -> Any:
        """The scene as an in-memory ``Usd.Stage`` (for callers who add to it before saving;
        the plants' arrays are in the root layer)."""
        tf = _import_pxr()
        try:
            return _build_stage(scene, False)[0]
        except tf.ErrorException as exc:
            raise BackendError(
                f"OpenUSD failed building the stage: {exc}", stage="compile"
            ) from exc


def _import_pxr() -> Any:
    """``pxr.Tf`` (whose ``ErrorException`` we convert), or a BackendError saying how to install."""
    try:
        from pxr import Tf, Usd, UsdGeom, UsdLux  # noqa: F401 - fail here, not midway

        return Tf
    except ImportError as exc:
        raise BackendError(
            f"the USD backend needs OpenUSD's Python module pxr ({exc})",
            stage="compile",
            hint="pip install 'agrirecipe[usd]' (installs usd-core)",
        ) from exc


def _build_stage(scene: Scene, binary: bool) -> tuple[Any, Any]:
    """The stage, and the in-memory binary layer its per-plant arrays went to (or None)."""
    from pxr import Kind, Sdf, Usd, UsdGeom

    from agrirecipe.layout import field_parameters
    from agrirecipe.plants import field_assets

    recipe = scene.recipe
    # The plant meshes are payloads, resolved against the folder the stage is written
    # to: the in-memory stage leaves them unloaded (it has no folder), every reader of
    # scene.usda loads them.
    stage = Usd.Stage.CreateInMemory(STAGE_NAME, load=Usd.Stage.LoadNone)
    UsdGeom.SetStageUpAxis(stage, UsdGeom.Tokens.z)
    UsdGeom.SetStageMetersPerUnit(stage, UsdGeom.LinearUnits.meters)
    layer = stage.GetRootLayer()
    layer.documentation = f"agrirecipe {__version__} scene (recipe seed {recipe.seed})"
    layer.customLayerData = {
        "agrirecipe": {
            "version": __version__,
            "schema_version": recipe.schema_version,
            "seed": recipe.seed,
            "prompt": recipe.prompt,
            "resolver": recipe.resolver,
            "season": recipe.environment.season,
            "latitude_deg": recipe.environment.latitude_deg,
        }
    }
    parameters = {str(p["id"]): p for p in field_parameters(recipe)}
    world = UsdGeom.Xform.Define(stage, "/World")
    stage.SetDefaultPrim(world.GetPrim())
    Usd.ModelAPI(world.GetPrim()).SetKind(Kind.Tokens.assembly)

    _add_sun(stage, recipe)
    _add_surroundings(stage, recipe, parameters)
    UsdGeom.Scope.Define(stage, "/World/Fields")
    assets = field_assets(recipe, knowledge=scene.knowledge)
    plants_layer = None
    if binary:
        plants_layer = Sdf.Layer.CreateAnonymous(PLANTS_LAYER_NAME)
        layer.subLayerPaths.append(plants_layer.identifier)
    for plants in scene.layout.fields:
        spec = plants.spec
        field_path = Sdf.Path("/World/Fields").AppendChild(spec.id)
        field_prim = UsdGeom.Xform.Define(stage, field_path).GetPrim()
        _set_attributes(field_prim, plants.attributes())
        _add_ground(stage, field_path, spec, parameters[spec.id])
        instancer = _add_instancer(stage, field_path.AppendChild("Plants"), plants, assets[spec.id])
        if plants_layer is not None:
            stage.SetEditTarget(Usd.EditTarget(plants_layer))
        _add_plant_arrays(instancer, plants)
        stage.SetEditTarget(Usd.EditTarget(layer))
    return stage, plants_layer


def _set_attributes(prim: Any, values: Mapping[str, str | int | float | list[str]]) -> None:
    """Typed custom ``agrirecipe:*`` attributes (shown in usdview's property panel)."""
    from pxr import Sdf

    names = Sdf.ValueTypeNames
    for key, value in values.items():
        if isinstance(value, list):
            value_type = names.StringArray
        elif isinstance(value, str):
            value_type = names.String
        elif isinstance(value, int):
            value_type = names.Int64
        else:
            value_type = names.Double
        prim.CreateAttribute(f"agrirecipe:{key}", value_type, custom=True).Set(value)


def _add_sun(stage: Any, recipe: SceneRecipe) -> None:
    """A distant light whose +Z axis points at the sun (the light shines along -Z)."""
    from pxr import Gf, UsdGeom, UsdLux

    sun = recipe.environment.sun
    elevation, azimuth = math.radians(sun.elevation_deg), math.radians(sun.azimuth_deg)
    # Compass azimuth is clockwise from north (+Y); east is +X.
    toward_sun = Gf.Vec3d(
        math.sin(azimuth) * math.cos(elevation),
        math.cos(azimuth) * math.cos(elevation),
        math.sin(elevation),
    )
    light = UsdLux.DistantLight.Define(stage, "/World/Sun")
    light.CreateIntensityAttr(3000.0 if sun.elevation_deg > 0 else 50.0)
    light.CreateAngleAttr(0.53)
    rotation = Gf.Rotation(Gf.Vec3d(0.0, 0.0, 1.0), toward_sun)
    light.AddOrientOp(UsdGeom.XformOp.PrecisionFloat).Set(Gf.Quatf(rotation.GetQuat()))
    light.GetPrim().SetCustomDataByKey(
        "agrirecipe", {"elevation_deg": sun.elevation_deg, "azimuth_deg": sun.azimuth_deg}
    )


def _quad(
    stage: Any,
    path: Any,
    corners: list[tuple[float, float]],
    z: float,
    rgb: tuple[float, float, float],
) -> None:
    from pxr import Gf, Usd, UsdGeom

    mesh = UsdGeom.Mesh.Define(stage, path)
    points = [Gf.Vec3f(x, y, z) for x, y in corners]
    mesh.CreatePointsAttr(points)
    mesh.CreateFaceVertexCountsAttr([4])
    mesh.CreateFaceVertexIndicesAttr([0, 1, 2, 3])
    mesh.CreateNormalsAttr([Gf.Vec3f(0.0, 0.0, 1.0)] * 4)
    mesh.SetNormalsInterpolation(UsdGeom.Tokens.vertex)
    mesh.CreateSubdivisionSchemeAttr(UsdGeom.Tokens.none)
    mesh.CreateDoubleSidedAttr(True)
    mesh.CreateDisplayColorAttr([Gf.Vec3f(*rgb)])
    mesh.CreateExtentAttr(UsdGeom.Boundable.ComputeExtentFromPlugins(mesh, Usd.TimeCode.Default()))


def _add_ground(stage: Any, field_path: Any, spec: FieldSpec, params: dict[str, Any]) -> None:
    """The field's soil (``Ground``: ridges, beds or a flat quad), ``Mulch`` and ``Track``."""
    from pxr import Gf, Usd, UsdGeom, Vt

    from agrirecipe.layout import field_ground, ground_colours

    colours = ground_colours()
    names = {"soil": "Ground", "mulch": "Mulch", "track": "Track"}
    for part in field_ground(spec, params):
        mesh = UsdGeom.Mesh.Define(stage, field_path.AppendChild(names[part["part"]]))
        points = np.asarray(part["points"], dtype=np.float32).reshape(-1, 3)
        triangles = np.asarray(part["triangles"], dtype=np.int32)
        mesh.CreatePointsAttr(Vt.Vec3fArray.FromNumpy(points))
        mesh.CreateFaceVertexCountsAttr(Vt.IntArray.FromNumpy(np.full(len(triangles) // 3, 3)))
        mesh.CreateFaceVertexIndicesAttr(Vt.IntArray.FromNumpy(triangles))
        mesh.CreateSubdivisionSchemeAttr(UsdGeom.Tokens.none)
        mesh.CreateDoubleSidedAttr(True)
        mesh.CreateDisplayColorAttr([Gf.Vec3f(*colours[part["part"]])])
        mesh.CreateExtentAttr(
            UsdGeom.Boundable.ComputeExtentFromPlugins(mesh, Usd.TimeCode.Default())
        )


def _add_surroundings(
    stage: Any, recipe: SceneRecipe, parameters: Mapping[str, dict[str, Any]]
) -> None:
    from agrirecipe.layout import ground_spec
    from agrirecipe.layout._ground import ground_base_depth

    # below every field's furrows (a field with ridges or beds has banks down to it)
    depth = max(
        [0.02]
        + [ground_base_depth(ground_spec(spec, parameters[spec.id])) for spec in recipe.fields]
    )
    corners = [corner for spec in recipe.fields for corner in spec.geometry.corners_m()]
    xs, ys = [x for x, _ in corners], [y for _, y in corners]
    margin = 0.1 * max(max(xs) - min(xs), max(ys) - min(ys)) + 10.0
    x0, x1, y0, y1 = min(xs) - margin, max(xs) + margin, min(ys) - margin, max(ys) + margin
    # A few centimetres below the fields so the soil quads never z-fight with it.
    _quad(
        stage,
        "/World/Surroundings",
        [(x0, y0), (x1, y0), (x1, y1), (x0, y1)],
        -depth,
        _GRASS_RGB,
    )


def _add_instancer(stage: Any, path: Any, plants: FieldPlants, asset: FieldAsset | None) -> Any:
    """The field's instancer with its prototypes and extent (the per-plant arrays follow)."""
    from pxr import Gf, Tf, UsdGeom

    spec = plants.spec
    agronomy = spec.agronomy
    instancer = UsdGeom.PointInstancer.Define(stage, path)
    prototypes = UsdGeom.Scope.Define(stage, path.AppendChild("Prototypes"))
    asset_name = Tf.MakeValidIdentifier(spec.asset_path.rsplit(".", 1)[-1])
    field_attributes = plants.attributes()
    asset_attributes = {key: field_attributes[key] for key in _ASSET_ATTRIBUTES}
    asset_attributes |= {"canopy_width_m": agronomy.canopy_width_m}
    prototype_paths = []
    if asset is None:
        prototype_path = prototypes.GetPath().AppendChild(asset_name)
        prototype = UsdGeom.Xform.Define(stage, prototype_path).GetPrim()
        _describe_prototype(prototype, asset_name, spec.asset_path, asset_attributes)
        _add_proxy(stage, prototype_path.AppendChild("Proxy"), agronomy)
        prototype_paths.append(prototype_path)
    else:
        for variant in range(asset.variants):
            prototype_path = prototypes.GetPath().AppendChild(f"{asset_name}_v{variant}")
            xform = UsdGeom.Xform.Define(stage, prototype_path)
            prototype = xform.GetPrim()
            prototype.GetPayloads().AddPayload(f"./{asset.usd_file(variant)}")
            if asset.scale != (1.0, 1.0, 1.0):
                xform.AddScaleOp().Set(Gf.Vec3f(*asset.scale))
            _describe_prototype(
                prototype,
                asset_name,
                spec.asset_path,
                asset_attributes | {"variant": variant, "mesh_file": asset.files[variant]},
            )
            prototype_paths.append(prototype_path)

    instancer.CreatePrototypesRel().SetTargets(prototype_paths)
    count = plants.plant_count
    # Extent: every instance fits in a cylinder of the canopy radius, scaled (meshes
    # reach at most 5 % beyond the canopy the knowledge base gives).
    reach = 1.05 * agronomy.canopy_width_m / 2.0 * float(plants.scale.max()) if count else 0.0
    low = plants.xyz.min(axis=0) - reach if count else np.zeros(3)
    high = plants.xyz.max(axis=0) + reach if count else np.zeros(3)
    top = 1.05 * agronomy.plant_height_m * (float(plants.scale.max()) if count else 1.0)
    instancer.CreateExtentAttr(
        [
            Gf.Vec3f(float(low[0]), float(low[1]), 0.0),
            Gf.Vec3f(float(high[0]), float(high[1]), top),
        ]
    )
    return instancer


def _add_plant_arrays(instancer: Any, plants: FieldPlants) -> None:
    """Instance i: plants.csv's i-th plant of the field, showing its variant's prototype."""
    from pxr import Vt

    from agrirecipe.plants import plant_variants

    prototypes = len(instancer.GetPrototypesRel().GetTargets())
    indices = plant_variants(plants.plant_count, prototypes)
    instancer.CreateProtoIndicesAttr().Set(Vt.IntArray.FromNumpy(indices))
    instancer.CreatePositionsAttr().Set(Vt.Vec3fArray.FromNumpy(plants.xyz.astype(np.float32)))
    orientations = Vt.QuathArray.FromNumpy(yaw_quaternions(plants.yaw_rad))
    instancer.CreateOrientationsAttr().Set(orientations)
    scales = np.repeat(plants.scale.astype(np.float32)[:, None], 3, axis=1)
    instancer.CreateScalesAttr().Set(Vt.Vec3fArray.FromNumpy(scales))


def _describe_prototype(
    prototype: Any, name: str, asset_path: str, attributes: Mapping[str, Any]
) -> None:
    from pxr import Sdf

    prototype.SetAssetInfoByKey("name", name)
    prototype.SetAssetInfoByKey("identifier", Sdf.AssetPath(asset_path))
    _set_attributes(prototype, attributes)


def _add_proxy(stage: Any, path: Any, agronomy: Any) -> None:
    from pxr import Gf, Usd, UsdGeom

    points, counts, indices, colours = proxy_mesh(
        agronomy.growth_form, agronomy.plant_height_m, agronomy.canopy_width_m, agronomy.foliage_rgb
    )
    mesh = UsdGeom.Mesh.Define(stage, path)
    mesh.CreatePointsAttr([Gf.Vec3f(*p) for p in points])
    mesh.CreateFaceVertexCountsAttr(counts)
    mesh.CreateFaceVertexIndicesAttr(indices)
    mesh.CreateSubdivisionSchemeAttr(UsdGeom.Tokens.none)
    colour = mesh.CreateDisplayColorPrimvar(UsdGeom.Tokens.vertex)
    colour.Set([Gf.Vec3f(*c) for c in colours])
    mesh.CreateExtentAttr(UsdGeom.Boundable.ComputeExtentFromPlugins(mesh, Usd.TimeCode.Default()))
