"""A plant mesh as a USD asset (``.usdc``) that a scene's prototypes reference.

OpenUSD cannot read glTF without a plugin that usd-core does not ship, so every
``.glb`` of a scene gets a binary USD companion with the same geometry::

    /Plant                 Xform, default prim, kind = component
        Looks/<material>   Material with a UsdPreviewSurface (linear base colour)
        <material>         Mesh: points, vertex normals, primvars:st, bound material

Metres, Z up, the plant's base at the origin: the scene's own frame, so a
prototype needs no transform. ``pxr`` is imported on first use.
"""

from __future__ import annotations

from pathlib import Path
from typing import Any

import numpy as np

from agrirecipe._files import atomic_path
from agrirecipe.plants._gltf import linear_rgb
from agrirecipe.plants._mesh import PlantMesh

__all__ = ["usd_asset_stage", "write_usd_asset"]

PLANT_PRIM = "/Plant"


def usd_asset_stage(mesh: PlantMesh, *, name: str) -> Any:
    """The asset as an in-memory ``Usd.Stage``."""
    from pxr import Gf, Kind, Sdf, Tf, Usd, UsdGeom, UsdShade, Vt

    stage = Usd.Stage.CreateInMemory()
    UsdGeom.SetStageUpAxis(stage, UsdGeom.Tokens.z)
    UsdGeom.SetStageMetersPerUnit(stage, UsdGeom.LinearUnits.meters)
    root = UsdGeom.Xform.Define(stage, PLANT_PRIM)
    stage.SetDefaultPrim(root.GetPrim())
    Usd.ModelAPI(root.GetPrim()).SetKind(Kind.Tokens.component)
    root.GetPrim().SetAssetInfoByKey("name", name)
    looks = UsdGeom.Scope.Define(stage, f"{PLANT_PRIM}/Looks")
    for primitive in mesh.primitives:
        identifier = Tf.MakeValidIdentifier(primitive.material.name)
        rgb = Gf.Vec3f(*linear_rgb(primitive.material.rgb))
        material = UsdShade.Material.Define(stage, looks.GetPath().AppendChild(identifier))
        shader = UsdShade.Shader.Define(stage, material.GetPath().AppendChild("Surface"))
        shader.CreateIdAttr("UsdPreviewSurface")
        shader.CreateInput("diffuseColor", Sdf.ValueTypeNames.Color3f).Set(rgb)
        shader.CreateInput("roughness", Sdf.ValueTypeNames.Float).Set(
            float(primitive.material.roughness)
        )
        shader.CreateInput("metallic", Sdf.ValueTypeNames.Float).Set(0.0)
        material.CreateSurfaceOutput().ConnectToSource(shader.ConnectableAPI(), "surface")

        geometry = UsdGeom.Mesh.Define(stage, root.GetPath().AppendChild(identifier))
        triangles = primitive.triangles.astype(np.int32)
        geometry.CreatePointsAttr(Vt.Vec3fArray.FromNumpy(primitive.positions))
        geometry.CreateFaceVertexCountsAttr(Vt.IntArray.FromNumpy(np.full(len(triangles), 3)))
        geometry.CreateFaceVertexIndicesAttr(Vt.IntArray.FromNumpy(triangles.reshape(-1)))
        geometry.CreateNormalsAttr(Vt.Vec3fArray.FromNumpy(primitive.normals))
        geometry.SetNormalsInterpolation(UsdGeom.Tokens.vertex)
        geometry.CreateSubdivisionSchemeAttr(UsdGeom.Tokens.none)
        geometry.CreateDoubleSidedAttr(bool(primitive.material.double_sided))
        geometry.CreateDisplayColorAttr([rgb])
        st = UsdGeom.PrimvarsAPI(geometry).CreatePrimvar(
            "st", Sdf.ValueTypeNames.TexCoord2fArray, UsdGeom.Tokens.vertex
        )
        st.Set(Vt.Vec2fArray.FromNumpy(primitive.uvs))
        low, high = primitive.positions.min(axis=0), primitive.positions.max(axis=0)
        geometry.CreateExtentAttr([Gf.Vec3f(*map(float, low)), Gf.Vec3f(*map(float, high))])
        UsdShade.MaterialBindingAPI.Apply(geometry.GetPrim()).Bind(material)
    return stage


def write_usd_asset(path: str | Path, mesh: PlantMesh, *, name: str) -> Path:
    """Write the asset atomically to ``path`` (``.usdc``: binary crate)."""
    target = Path(path)
    stage = usd_asset_stage(mesh, name=name)
    with atomic_path(target, suffix=target.suffix) as temporary:
        if not stage.GetRootLayer().Export(str(temporary)):
            raise OSError(f"pxr could not export {str(target)!r}")
    return target
