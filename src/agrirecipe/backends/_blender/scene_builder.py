# agrirecipe Blender scene builder.
#
# The library never imports this file: the Blender backend appends its source,
# verbatim, to every generated blender_build.py after the settings, the
# placement kernel and the scene description. It runs inside Blender's Python
# (Blender 4.2 or newer, or the bpy module from PyPI) and uses only bpy and the
# standard library. Rules that keep generated scripts working:
# - no `from __future__` (it would have to be the first statement of the script);
# - no agrirecipe import, no module-level state besides constants;
# - every name the script's tail calls (`main`) is defined here.
"""Build an agrirecipe scene in Blender: plant meshes instanced with Geometry Nodes."""

import argparse
import math
import time
from collections.abc import Callable, Sequence
from pathlib import Path
from typing import Any

import bpy

#: Bumped whenever the scene this builder makes from the same description changes.
BUILDER_VERSION = 2
ROOT_COLLECTION = "agrirecipe"
PROXY_COLLECTION = "agrirecipe_proxies"
NODE_GROUP = "agrirecipe_plants"
#: Render engines by the short names the library and the command line accept.
ENGINES = {"cycles": "CYCLES", "workbench": "BLENDER_WORKBENCH", "eevee": "BLENDER_EEVEE"}
#: Per-plant attributes stored on each field's points (and so on its instances).
PLANT_ATTRIBUTES = ("yaw", "scale", "height_m")
#: What plants are drawn with: the plant library's meshes (``assets/``) or proxies.
PLANT_MODES = ("meshes", "proxies")
# Knuth's multiplicative hash: agrirecipe.plants.plant_variant, the same formula.
_FIBONACCI = 0x9E3779B1
_GOLDEN_ANGLE = math.pi * (3.0 - math.sqrt(5.0))
_SEGMENTS = {"part": 10, "scatter": 6}
#: Materials whose brightness varies from plant to plant (leaves, not bark or fruit).
_VARIED_MATERIALS = ("foliage", "stem", "ear")

Vec3 = tuple[float, float, float]
# An affine placement of a unit primitive: centre, then the images of its x, y, z axes.
Placement = tuple[Vec3, Vec3, Vec3, Vec3]
PlaceField = Callable[[dict[str, Any]], list[tuple[float, float, float, float, float, float]]]


# --- small vector helpers (no mathutils: the builder stays plain Python) ---


def _add(a: Vec3, b: Vec3) -> Vec3:
    return (a[0] + b[0], a[1] + b[1], a[2] + b[2])


def _sub(a: Vec3, b: Vec3) -> Vec3:
    return (a[0] - b[0], a[1] - b[1], a[2] - b[2])


def _mul(a: Vec3, k: float) -> Vec3:
    return (a[0] * k, a[1] * k, a[2] * k)


def _cross(a: Vec3, b: Vec3) -> Vec3:
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def _norm(a: Vec3) -> float:
    return math.sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2])


def _unit(a: Vec3) -> Vec3:
    length = _norm(a)
    return _mul(a, 1.0 / length) if length > 1e-12 else (0.0, 0.0, 0.0)


def _rotate_z(a: Vec3, angle: float) -> Vec3:
    cos_a, sin_a = math.cos(angle), math.sin(angle)
    return (a[0] * cos_a - a[1] * sin_a, a[0] * sin_a + a[1] * cos_a, a[2])


def srgb_to_linear(rgb: Sequence[float]) -> tuple[float, float, float, float]:
    """An sRGB colour (as written in recipes) as the linear RGBA Blender stores."""

    def channel(value: float) -> float:
        if value <= 0.04045:
            return value / 12.92
        return float(((value + 0.055) / 1.055) ** 2.4)

    return (channel(rgb[0]), channel(rgb[1]), channel(rgb[2]), 1.0)


# --- unit primitives: diameter 1 and height 1, centred on the origin ---


def unit_primitive(shape: str, segments: int) -> tuple[list[Vec3], list[tuple[int, ...]], bool]:
    """Vertices, faces and smooth shading of a unit ``cylinder``/``cone``/``sphere``/``cube``."""
    if shape == "cube":
        verts = [(x * 0.5, y * 0.5, z * 0.5) for x in (-1, 1) for y in (-1, 1) for z in (-1, 1)]
        faces: list[tuple[int, ...]] = [
            (0, 1, 3, 2), (4, 6, 7, 5), (0, 4, 5, 1), (2, 3, 7, 6), (0, 2, 6, 4), (1, 5, 7, 3)
        ]  # fmt: skip
        return verts, faces, False
    ring = [
        (0.5 * math.cos(2 * math.pi * k / segments), 0.5 * math.sin(2 * math.pi * k / segments))
        for k in range(segments)
    ]
    if shape in ("cylinder", "cone"):
        verts = [(x, y, -0.5) for x, y in ring]
        if shape == "cylinder":
            verts += [(x, y, 0.5) for x, y in ring]
            faces = [(k, (k + 1) % segments, segments + (k + 1) % segments, segments + k)
                     for k in range(segments)]  # fmt: skip
            faces.append(tuple(range(2 * segments - 1, segments - 1, -1)))
        else:
            verts.append((0.0, 0.0, 0.5))
            faces = [(k, (k + 1) % segments, segments) for k in range(segments)]
        faces.append(tuple(range(segments)))
        # Bottom cap faces down: reverse it.
        faces[-1] = tuple(reversed(faces[-1]))
        return verts, faces, True
    if shape == "sphere":
        rings = max(3, segments // 2 + 1)
        verts = [(0.0, 0.0, -0.5)]
        for r in range(1, rings):
            polar = math.pi * r / rings - math.pi / 2
            radius, z = math.cos(polar), 0.5 * math.sin(polar)
            verts += [(x * radius, y * radius, z) for x, y in ring]
        verts.append((0.0, 0.0, 0.5))
        top = len(verts) - 1
        faces = [((k + 1) % segments + 1, k + 1, 0) for k in range(segments)]
        for r in range(rings - 2):
            base = 1 + r * segments
            for k in range(segments):
                k1 = (k + 1) % segments
                faces.append((base + k, base + k1, base + segments + k1, base + segments + k))
        last = 1 + (rings - 2) * segments
        faces += [(last + k, last + (k + 1) % segments, top) for k in range(segments)]
        return verts, faces, True
    raise ValueError(f"unknown primitive shape {shape!r}")


# --- proxy plants ---


def segment_placement(start: Vec3, end: Vec3, width: float, thickness: float) -> Placement:
    """A unit primitive stretched from ``start`` to ``end``, ``width`` across.

    The part is flattened (``thickness`` < 1) across its horizontal normal, so a
    leaf blade lies in the plane that holds its axis and the horizontal.
    """
    axis = _sub(end, start)
    length = _norm(axis)
    along = _unit(axis) if length > 1e-9 else (0.0, 0.0, 1.0)
    side = _cross((0.0, 0.0, 1.0), along)
    side = _unit(side) if _norm(side) > 1e-6 else (1.0, 0.0, 0.0)
    across = _cross(along, side)
    centre = _mul(_add(start, end), 0.5)
    return (centre, _mul(side, width), _mul(across, width * thickness), _mul(along, length))


def blob_placement(at: Sequence[float], size: Sequence[float]) -> Placement:
    """A unit primitive centred at ``at`` with diameters ``size`` along x, y, z."""
    return (
        (at[0], at[1], at[2]),
        (size[0], 0.0, 0.0),
        (0.0, size[1], 0.0),
        (0.0, 0.0, size[2]),
    )


def _turned(placement: Placement, angle: float) -> Placement:
    centre, ax, ay, az = placement
    return (
        _rotate_z(centre, angle),
        _rotate_z(ax, angle),
        _rotate_z(ay, angle),
        _rotate_z(az, angle),
    )


def part_placements(part: dict[str, Any], variant: int) -> list[Placement]:
    """Every copy of one proxy part (repeats about the plant axis, scatters on an ellipsoid).

    ``variant`` turns repeats and scatters by a variant-specific phase so the
    proxies of one field differ; parts that are not repeated keep their
    orientation (a vine's cordon stays along the row).
    """
    kind = part["kind"]
    if kind == "scatter":
        count = int(part["count"])
        low, high = part["band"]
        centre, size = part["at"], part["size"]
        diameter = float(part["diameter"])
        phase = math.radians(part["phase_deg"]) + variant * 1.3
        placements = []
        for index in range(count):
            height = low + (high - low) * (index + 0.5) / count
            radius = math.sqrt(max(0.0, 1.0 - height * height))
            angle = index * _GOLDEN_ANGLE + phase
            point = (
                centre[0] + 0.5 * size[0] * radius * math.cos(angle),
                centre[1] + 0.5 * size[1] * radius * math.sin(angle),
                centre[2] + 0.5 * size[2] * height,
            )
            blob_size = (diameter, diameter, diameter * float(part["elongation"]))
            placements.append(blob_placement(point, blob_size))
        return placements
    if kind == "segment":
        base = segment_placement(
            tuple(part["start"]), tuple(part["end"]), float(part["width"]), float(part["thickness"])
        )
    else:
        base = blob_placement(part["at"], part["size"])
    repeat = int(part["repeat"])
    if repeat == 1:
        return [base]
    step = 2 * math.pi / repeat
    phase = math.radians(part["phase_deg"]) + variant * step * 0.38
    return [_turned(base, phase + index * step) for index in range(repeat)]


def proxy_geometry(
    plan: dict[str, Any], variant: int
) -> tuple[list[Vec3], list[tuple[int, ...]], list[int], list[bool], list[str]]:
    """A proxy plant's mesh: vertices, faces, per-face material slot and smoothing, slot names."""
    verts: list[Vec3] = []
    faces: list[tuple[int, ...]] = []
    face_slots: list[int] = []
    face_smooth: list[bool] = []
    slots: list[str] = []
    cache: dict[tuple[str, int], tuple[list[Vec3], list[tuple[int, ...]], bool]] = {}
    for part in plan["parts"]:
        if part["material"] not in slots:
            slots.append(part["material"])
        slot = slots.index(part["material"])
        segments = _SEGMENTS["scatter" if part["kind"] == "scatter" else "part"]
        key = (part["shape"], segments)
        if key not in cache:
            cache[key] = unit_primitive(part["shape"], segments)
        unit_verts, unit_faces, smooth = cache[key]
        for centre, ax, ay, az in part_placements(part, variant):
            offset = len(verts)
            for x, y, z in unit_verts:
                verts.append(
                    (
                        centre[0] + ax[0] * x + ay[0] * y + az[0] * z,
                        centre[1] + ax[1] * x + ay[1] * y + az[1] * z,
                        centre[2] + ax[2] * x + ay[2] * y + az[2] * z,
                    )
                )
            faces.extend(tuple(offset + i for i in face) for face in unit_faces)
            face_slots.extend([slot] * len(unit_faces))
            face_smooth.extend([smooth] * len(unit_faces))
    return verts, faces, face_slots, face_smooth, slots


def make_material(name: str, srgb: Sequence[float], *, vary_by_scale: bool = False) -> Any:
    """A matte Principled material (and the same colour for Workbench renders).

    With ``vary_by_scale`` the colour's brightness follows each plant's
    ``scale`` instance attribute (vigorous plants a little lighter), so a
    field of identical proxies does not look stamped.
    """
    material = bpy.data.materials.new(name)
    colour = srgb_to_linear(srgb)
    material.diffuse_color = colour  # what Workbench and the viewport show
    material["agrirecipe_srgb"] = [float(c) for c in srgb]
    if material.node_tree is None:  # Blender 4.x creates materials without nodes
        material.use_nodes = True
    nodes, links = material.node_tree.nodes, material.node_tree.links
    principled = next(
        (node for node in nodes if node.bl_idname == "ShaderNodeBsdfPrincipled"), None
    )
    if principled is None:
        return material
    principled.inputs["Roughness"].default_value = 0.85
    base = principled.inputs["Base Color"]
    base.default_value = colour
    if vary_by_scale:
        scale = nodes.new("ShaderNodeAttribute")
        scale.attribute_type = "INSTANCER"
        scale.attribute_name = "scale"
        brightness = nodes.new("ShaderNodeMapRange")
        for socket, value in (
            ("From Min", 0.8), ("From Max", 1.2), ("To Min", 0.85), ("To Max", 1.12)
        ):  # fmt: skip
            brightness.inputs[socket].default_value = value
        tone = nodes.new("ShaderNodeHueSaturation")
        tone.inputs["Color"].default_value = colour
        links.new(scale.outputs["Fac"], brightness.inputs["Value"])
        links.new(brightness.outputs["Result"], tone.inputs["Value"])
        links.new(tone.outputs["Color"], base)
    return material


def plant_variant(index: int, variants: int) -> int:
    """The shape variant of a field's ``index``-th plant (``plants.csv``'s ``variant``)."""
    return (((index * _FIBONACCI) & 0xFFFFFFFF) >> 16) % variants


def assets_root(settings: dict[str, Any]) -> str:
    """The folder holding ``assets/``: the setting, else this script's folder, else the cwd."""
    configured = settings.get("assets_root")
    if configured:
        return str(configured)
    script = globals().get("__file__")
    return str(Path(script).resolve().parent if script else Path.cwd())


def read_glb(path: str) -> list[dict[str, Any]]:
    """The primitives of the first mesh of a glTF binary: Z-up positions, triangles, UVs
    and material (name, linear base colour, roughness, double sided).

    agrirecipe's plant meshes are read directly rather than through Blender's glTF
    importer: it is the same data, and several times faster to load (the importer
    add-on alone takes most of a second to start).
    """
    import array
    import json
    import struct

    data = Path(path).read_bytes()
    magic, version, _ = struct.unpack_from("<III", data)
    if magic != 0x46546C67 or version != 2:
        raise RuntimeError(f"agrirecipe: {path} is not a glTF 2.0 binary")
    length, _ = struct.unpack_from("<II", data, 12)
    document = json.loads(data[20 : 20 + length])
    binary = data[20 + length + 8 :]

    def values(index: int, code: str) -> Any:
        accessor = document["accessors"][index]
        view = document["bufferViews"][accessor["bufferView"]]
        width = {"SCALAR": 1, "VEC2": 2, "VEC3": 3}[accessor["type"]]
        start = view.get("byteOffset", 0) + accessor.get("byteOffset", 0)
        out = array.array(code)
        out.frombytes(binary[start : start + accessor["count"] * width * out.itemsize])
        return out

    primitives = []
    for primitive in document["meshes"][0]["primitives"]:
        attributes = primitive["attributes"]
        up = values(attributes["POSITION"], "f")
        # glTF is Y up: the file holds (x, z, -y)
        points = array.array("f", [0.0]) * len(up)
        points[0::3], points[1::3], points[2::3] = (
            up[0::3],
            array.array("f", (-v for v in up[2::3])),
            up[1::3],
        )
        kind = document["accessors"][primitive["indices"]]["componentType"]
        material = document["materials"][primitive["material"]]
        pbr = material["pbrMetallicRoughness"]
        primitives.append(
            {
                "points": points,
                "triangles": values(primitive["indices"], "H" if kind == 5123 else "I"),
                "uvs": values(attributes["TEXCOORD_0"], "f")
                if "TEXCOORD_0" in attributes
                else None,
                "material": material["name"],
                "rgb": pbr["baseColorFactor"][:3],
                "roughness": float(pbr.get("roughnessFactor", 0.8)),
            }
        )
    return primitives


def import_glb(path: str, name: str, collection: Any, scale: Sequence[float]) -> Any:
    """One plant mesh (glTF binary) as an object named ``name`` in ``collection``: one
    material slot per primitive, smooth shaded, scaled per axis by ``scale``."""
    import array

    mesh = bpy.data.meshes.new(name)
    points = array.array("f")
    triangles = array.array("i")
    slots = array.array("i")
    uvs = array.array("f")
    for slot, primitive in enumerate(read_glb(path)):
        offset = len(points) // 3
        points.extend(primitive["points"])
        triangles.extend(i + offset for i in primitive["triangles"])
        slots.extend([slot] * (len(primitive["triangles"]) // 3))
        if primitive["uvs"] is not None:
            flat = primitive["uvs"]
            for i in primitive["triangles"]:
                uvs.extend((flat[2 * i], 1.0 - flat[2 * i + 1]))  # glTF's v runs down
        mesh.materials.append(_plant_material(primitive))
    if tuple(scale) != (1.0, 1.0, 1.0):
        for axis in range(3):
            points[axis::3] = array.array("f", (v * float(scale[axis]) for v in points[axis::3]))
    count = len(triangles) // 3
    mesh.vertices.add(len(points) // 3)
    mesh.vertices.foreach_set("co", points)
    mesh.loops.add(len(triangles))
    mesh.loops.foreach_set("vertex_index", triangles)
    mesh.polygons.add(count)
    mesh.polygons.foreach_set("loop_start", array.array("i", range(0, len(triangles), 3)))
    mesh.polygons.foreach_set("material_index", slots)
    mesh.polygons.foreach_set("use_smooth", array.array("b", [1]) * count)
    if len(uvs) == 2 * len(triangles):
        mesh.uv_layers.new(name="UVMap").data.foreach_set("uv", uvs)
    mesh.update(calc_edges=True)
    plant = bpy.data.objects.new(name, mesh)
    collection.objects.link(plant)
    return plant


def _plant_material(primitive: dict[str, Any]) -> Any:
    """A Principled material of a glTF primitive (shared by name and colour)."""
    rgb = [float(c) for c in primitive["rgb"]]
    key = f"agrirecipe_{primitive['material']}_{'_'.join(f'{c:.4f}' for c in rgb)}"
    material = bpy.data.materials.get(key)
    if material is not None:
        return material
    material = bpy.data.materials.new(key)
    material.use_nodes = True
    material.diffuse_color = (*rgb, 1.0)
    bsdf = material.node_tree.nodes.get("Principled BSDF")
    if bsdf is not None:
        bsdf.inputs["Base Color"].default_value = (*rgb, 1.0)
        bsdf.inputs["Roughness"].default_value = primitive["roughness"]
    material["agrirecipe_srgb"] = [round(_to_srgb(c), 4) for c in rgb]
    return material


def _to_srgb(linear: float) -> float:
    if linear <= 0.0031308:
        return 12.92 * linear
    return float(1.055 * linear ** (1.0 / 2.4) - 0.055)


def build_meshes(field: dict[str, Any], parent: Any, root: str) -> Any:
    """The plant library's shape variants of one field, or None when a file is missing."""
    assets = field.get("assets")
    if not assets:
        return None
    paths = [str(Path(root).joinpath(*relative.split("/"))) for relative in assets["files"]]
    missing = [path for path in paths if not Path(path).is_file()]
    if missing:
        print(f"agrirecipe: {field['id']}: plant mesh {missing[0]} is missing; drawing proxies")
        return None
    collection = bpy.data.collections.new(f"{field['id']}_proxies")
    parent.children.link(collection)
    for variant, path in enumerate(paths):
        plant = import_glb(path, f"{field['id']}_plant_{variant}", collection, assets["scale"])
        plant["agrirecipe_role"] = "plant"
        plant["agrirecipe_mesh_file"] = assets["files"][variant]
    return collection


def build_proxies(field: dict[str, Any], parent: Any) -> Any:
    """The proxy variants of one field, in a collection of their own under ``parent``."""
    field_id = field["id"]
    plan = field["proxy"]
    collection = bpy.data.collections.new(f"{field_id}_proxies")
    parent.children.link(collection)
    materials = {
        name: make_material(f"{field_id}_{name}", rgb, vary_by_scale=name in _VARIED_MATERIALS)
        for name, rgb in plan["materials"].items()
    }
    for variant in range(int(plan["variants"])):
        verts, faces, face_slots, face_smooth, slots = proxy_geometry(plan, variant)
        mesh = bpy.data.meshes.new(f"{field_id}_proxy_{variant}")
        mesh.from_pydata(verts, [], faces)
        for name in slots:
            mesh.materials.append(materials[name])
        mesh.polygons.foreach_set("material_index", face_slots)
        mesh.polygons.foreach_set("use_smooth", face_smooth)
        mesh.update()
        proxy = bpy.data.objects.new(f"{field_id}_proxy_{variant}", mesh)
        proxy["agrirecipe_role"] = "proxy"
        proxy["agrirecipe_parts"] = sorted({part["role"] for part in plan["parts"]})
        collection.objects.link(proxy)
    return collection


# --- plants: one point cloud per field, instanced by one shared node group ---


def _socket(sockets: Any, name: str, kind: str | None = None) -> Any:
    for socket in sockets:
        if socket.name == name and (kind is None or socket.type == kind):
            return socket
    raise KeyError(f"no socket {name!r}" + (f" of type {kind}" if kind else ""))


def plants_node_group() -> Any:
    """The Geometry Nodes group that puts a proxy on every point of a field.

    Inputs: the field's points (with ``yaw``, ``scale`` and ``variant``
    attributes) and its collection of shape variants (plant meshes or proxies).
    Each point gets the variant its ``variant`` attribute names (the
    ``variant`` column of ``plants.csv``), turned by ``yaw`` about Z and scaled
    uniformly by ``scale``.
    """
    group = bpy.data.node_groups.get(NODE_GROUP)
    if group is not None:
        return group
    group = bpy.data.node_groups.new(NODE_GROUP, "GeometryNodeTree")
    if hasattr(group, "is_modifier"):
        group.is_modifier = True
    interface = group.interface
    interface.new_socket("Geometry", in_out="INPUT", socket_type="NodeSocketGeometry")
    interface.new_socket("Proxies", in_out="INPUT", socket_type="NodeSocketCollection")
    interface.new_socket("Geometry", in_out="OUTPUT", socket_type="NodeSocketGeometry")

    nodes, links = group.nodes, group.links
    group_in = nodes.new("NodeGroupInput")
    group_out = nodes.new("NodeGroupOutput")
    proxies = nodes.new("GeometryNodeCollectionInfo")
    proxies.transform_space = "ORIGINAL"
    _socket(proxies.inputs, "Separate Children").default_value = True
    _socket(proxies.inputs, "Reset Children").default_value = True
    instancer = nodes.new("GeometryNodeInstanceOnPoints")
    _socket(instancer.inputs, "Pick Instance").default_value = True
    pick = nodes.new("GeometryNodeInputNamedAttribute")
    pick.data_type = "INT"
    _socket(pick.inputs, "Name").default_value = "variant"
    yaw = nodes.new("GeometryNodeInputNamedAttribute")
    yaw.data_type = "FLOAT"
    _socket(yaw.inputs, "Name").default_value = "yaw"
    scale = nodes.new("GeometryNodeInputNamedAttribute")
    scale.data_type = "FLOAT"
    _socket(scale.inputs, "Name").default_value = "scale"
    euler = nodes.new("ShaderNodeCombineXYZ")
    rotation = nodes.new("FunctionNodeEulerToRotation")

    links.new(_socket(group_in.outputs, "Geometry"), _socket(instancer.inputs, "Points"))
    links.new(_socket(group_in.outputs, "Proxies"), _socket(proxies.inputs, "Collection"))
    links.new(_socket(proxies.outputs, "Instances"), _socket(instancer.inputs, "Instance"))
    links.new(_socket(pick.outputs, "Attribute"), _socket(instancer.inputs, "Instance Index"))
    links.new(_socket(yaw.outputs, "Attribute"), _socket(euler.inputs, "Z"))
    links.new(euler.outputs[0], rotation.inputs[0])
    links.new(rotation.outputs[0], _socket(instancer.inputs, "Rotation"))
    links.new(_socket(scale.outputs, "Attribute"), _socket(instancer.inputs, "Scale"))
    links.new(_socket(instancer.outputs, "Instances"), _socket(group_out.inputs, "Geometry"))
    for column, node in enumerate(
        (group_in, proxies, pick, yaw, scale, euler, rotation, instancer, group_out)
    ):
        node.location = (column * 200.0, 0.0)
    return group


def _float_buffer(values: Any) -> Any:
    # foreach_set copies a typed buffer directly; a list would be converted item by item.
    import array

    return array.array("f", values)


def build_plants(
    field: dict[str, Any],
    place_field: PlaceField,
    collection: Any,
    proxies: Any,
    timings: dict[str, float],
) -> tuple[Any, int]:
    """The points object of one field (named by its id) and its plant count.

    Adds the seconds spent in the placement kernel and in filling the point
    cloud to ``timings["kernel"]`` and ``timings["points"]``.
    """
    started = time.perf_counter()
    plants = place_field(field["params"])
    placed = time.perf_counter()
    timings["kernel"] = timings.get("kernel", 0.0) + placed - started
    count = len(plants)
    mesh = bpy.data.meshes.new(f"{field['id']}_points")
    mesh.vertices.add(count)
    mesh.vertices.foreach_set("co", _float_buffer(c for plant in plants for c in plant[:3]))
    for index, name in enumerate(PLANT_ATTRIBUTES, start=3):
        attribute = mesh.attributes.new(name, "FLOAT", "POINT")
        attribute.data.foreach_set("value", _float_buffer(plant[index] for plant in plants))
    variants = len(proxies.objects)
    chosen = mesh.attributes.new("variant", "INT", "POINT")
    chosen.data.foreach_set("value", [plant_variant(i, variants) for i in range(count)])
    mesh.update()
    del plants
    timings["points"] = timings.get("points", 0.0) + time.perf_counter() - placed
    obj = bpy.data.objects.new(field["id"], mesh)
    collection.objects.link(obj)
    modifier = obj.modifiers.new("agrirecipe_plants", "NODES")
    group = plants_node_group()
    modifier.node_group = group
    values = {"Proxies": proxies}
    for item in group.interface.items_tree:
        if getattr(item, "in_out", None) == "INPUT" and item.name in values:
            modifier[item.identifier] = values[item.name]
    for key in ("label", "crop", "variety", "stage", "season", "health", "asset_path"):
        obj[f"agrirecipe_{key}"] = field[key]
    obj["agrirecipe_field_id"] = field["id"]
    obj["agrirecipe_plant_count"] = count
    obj["agrirecipe_plants"] = "meshes" if proxies.get("agrirecipe_meshes") else "proxies"
    return obj, count


# --- ground, light, camera, sky ---


def _quad(name: str, corners: Sequence[Sequence[float]], z: float, material: Any) -> Any:
    mesh = bpy.data.meshes.new(name)
    mesh.from_pydata([(x, y, z) for x, y in corners], [], [(0, 1, 2, 3)])
    mesh.materials.append(material)
    mesh.update()
    return bpy.data.objects.new(name, mesh)


def scene_bounds(fields: Sequence[dict[str, Any]]) -> tuple[float, float, float, float, float]:
    """``(min_x, min_y, max_x, max_y, top_z)`` of every field and its tallest plant."""
    xs = [corner[0] for field in fields for corner in field["corners_m"]]
    ys = [corner[1] for field in fields for corner in field["corners_m"]]
    top = max(field["max_plant_height_m"] for field in fields)
    return min(xs), min(ys), max(xs), max(ys), top


def _surface_object(name: str, part: dict[str, Any], material: Any) -> Any:
    """A mesh object of one surface part (flat lists of points and triangle indices)."""
    import array

    triangles = part["triangles"]
    mesh = bpy.data.meshes.new(name)
    mesh.vertices.add(len(part["points"]) // 3)
    mesh.vertices.foreach_set("co", array.array("f", part["points"]))
    mesh.loops.add(len(triangles))
    mesh.loops.foreach_set("vertex_index", array.array("i", triangles))
    mesh.polygons.add(len(triangles) // 3)
    mesh.polygons.foreach_set("loop_start", array.array("i", range(0, len(triangles), 3)))
    mesh.materials.append(material)
    mesh.update(calc_edges=True)
    return bpy.data.objects.new(name, mesh)


def build_ground(scene_data: dict[str, Any], root: Any) -> None:
    """The soil of every field (ridges, beds, mulch and tracks where its pattern has
    them, else a flat quad) and a larger grass and earth base under the scene."""
    colours = scene_data["style"]["colours"]
    soil = make_material("agrirecipe_soil", colours["soil"])
    # agrirecipe.layout._ground, inlined into the script after the kernel
    surface = globals().get("ground_parts")
    materials = {"soil": soil}
    for part, rgb in scene_data.get("ground_colours", {}).items():
        if part != "soil":
            materials[part] = make_material(f"agrirecipe_{part}", rgb)
    for field in scene_data["fields"]:
        if surface is None or "ground" not in field:
            parts: list[dict[str, Any]] = [{"part": "soil", "points": None}]
        else:
            parts = surface(field["params"], field["ground"])
        for part in parts:
            name = f"{field['id']}_{part['part']}"
            if part["points"] is None:
                ground = _quad(name, field["corners_m"], 0.0, soil)
            else:
                ground = _surface_object(name, part, materials[part["part"]])
            ground["agrirecipe_field_id"] = field["id"]
            bpy.data.collections[field["id"]].objects.link(ground)
    min_x, min_y, max_x, max_y, _ = scene_bounds(scene_data["fields"])
    margin = max(10.0, 0.15 * max(max_x - min_x, max_y - min_y))
    corners = (
        (min_x - margin, min_y - margin),
        (max_x + margin, min_y - margin),
        (max_x + margin, max_y + margin),
        (min_x - margin, max_y + margin),
    )
    # A few centimetres below the fields so the soil never fights with it for a pixel,
    # and below every field's furrows (the fields' banks reach down to it).
    depth = max(
        [0.03]
        + [
            float(field["ground"]["depth_m"]) + 0.03
            for field in scene_data["fields"]
            if field.get("ground", {}).get("relief", "flat") != "flat"
        ]
    )
    base = _quad(
        "agrirecipe_ground", corners, -depth, make_material("agrirecipe_ground", colours["ground"])
    )
    root.objects.link(base)


def look_rotation(bearing_deg: float, elevation_deg: float) -> Vec3:
    """Euler XYZ of a camera or lamp looking toward compass ``bearing_deg``, ``elevation_deg`` up.

    Both look along their local -Z. Bearings are clockwise from north (+Y), so
    east (+X) is 90 degrees.
    """
    return (math.radians(90.0 + elevation_deg), 0.0, -math.radians(bearing_deg))


def build_sun(scene_data: dict[str, Any], root: Any) -> Any:
    """A sun lamp shining from ``environment.sun`` (raised to the style's minimum elevation)."""
    style = scene_data["style"]["sun"]
    sun = scene_data["environment"]["sun"]
    elevation = max(float(sun["elevation_deg"]), float(style["min_elevation_deg"]))
    light = bpy.data.lights.new("agrirecipe_sun", "SUN")
    light.energy = float(style["strength"])
    light.angle = math.radians(float(style["angle_deg"]))
    lamp = bpy.data.objects.new("agrirecipe_sun", light)
    # The light travels away from the sun: toward the opposite bearing, downward.
    lamp.rotation_euler = look_rotation(float(sun["azimuth_deg"]) + 180.0, -elevation)
    lamp.location = (0.0, 0.0, 100.0)
    lamp["agrirecipe_sun_elevation_deg"] = float(sun["elevation_deg"])
    lamp["agrirecipe_sun_azimuth_deg"] = float(sun["azimuth_deg"])
    root.objects.link(lamp)
    return lamp


def fit_view(
    points: Sequence[Vec3],
    target: Vec3,
    backward: Vec3,
    tan_x: float,
    tan_y: float,
) -> tuple[float, float, float]:
    """The distance along ``backward`` from ``target`` and the lens shift that frame ``points``.

    ``tan_x``/``tan_y`` are the tangents of the half field of view (already
    shrunk by any margin). Lens shift (in units of the wider image side)
    centres the points' projection, so an oblique view of a flat field wastes
    no frame; the distance is the smallest that fits (bisection: the
    projection shrinks as the camera backs away).
    """
    forward = _mul(backward, -1.0)
    right = _unit(_cross(forward, (0.0, 0.0, 1.0)))
    up = _cross(right, forward)
    offsets = [_sub(point, target) for point in points]
    along = [sum(f * o for f, o in zip(forward, offset, strict=True)) for offset in offsets]
    across = [sum(r * o for r, o in zip(right, offset, strict=True)) for offset in offsets]
    upward = [sum(u * o for u, o in zip(up, offset, strict=True)) for offset in offsets]
    wide = max(tan_x, tan_y)

    def projection(distance: float) -> tuple[float, float, float, float]:
        us = [a / (distance + d) for a, d in zip(across, along, strict=True)]
        vs = [b / (distance + d) for b, d in zip(upward, along, strict=True)]
        return min(us), max(us), min(vs), max(vs)

    def fits(distance: float) -> bool:
        u_min, u_max, v_min, v_max = projection(distance)
        return u_max - u_min <= 2 * tan_x and v_max - v_min <= 2 * tan_y

    # Start beyond the nearest point; grow until the projection fits, then bisect.
    near = max(1e-3, -min(along) + 1e-3)
    low, high = near, near + 1.0
    while not fits(high):
        low, high = high, high * 2.0
    for _ in range(60):
        middle = (low + high) / 2
        if fits(middle):
            high = middle
        else:
            low = middle
    u_min, u_max, v_min, v_max = projection(high)
    return high, (u_min + u_max) / 2 / (2 * wide), (v_min + v_max) / 2 / (2 * wide)


def build_camera(scene_data: dict[str, Any], scene: Any, root: Any, aspect: float) -> Any:
    """An oblique camera whose view holds every field and its tallest plants."""
    style = scene_data["style"]["camera"]
    min_x, min_y, max_x, max_y, top = scene_bounds(scene_data["fields"])
    corners = [(x, y, z) for x in (min_x, max_x) for y in (min_y, max_y) for z in (0.0, top)]
    target = ((min_x + max_x) / 2, (min_y + max_y) / 2, 0.0)
    bearing = math.radians(float(style["bearing_deg"]))
    elevation = math.radians(float(style["elevation_deg"]))
    backward = (
        math.sin(bearing) * math.cos(elevation),
        math.cos(bearing) * math.cos(elevation),
        math.sin(elevation),
    )
    lens = float(style["lens_mm"])
    # Sensor fit AUTO: the 36 mm sensor spans the wider image side.
    half_wide = 18.0 / lens / float(style["margin"])
    tan_x, tan_y = (
        (half_wide, half_wide / aspect) if aspect >= 1 else (half_wide * aspect, half_wide)
    )
    distance, shift_x, shift_y = fit_view(corners, target, backward, tan_x, tan_y)
    data = bpy.data.cameras.new("agrirecipe_camera")
    data.lens = lens
    data.sensor_width = 36.0
    data.sensor_fit = "AUTO"
    data.shift_x, data.shift_y = shift_x, shift_y
    extent = math.hypot(max_x - min_x, max_y - min_y) + top
    data.clip_start = max(0.05, distance / 5000.0)
    data.clip_end = distance + 2.0 * extent + 100.0
    camera = bpy.data.objects.new("agrirecipe_camera", data)
    camera.location = _add(target, _mul(backward, distance))
    camera.rotation_euler = look_rotation(math.degrees(bearing) + 180.0, -math.degrees(elevation))
    root.objects.link(camera)
    scene.camera = camera
    return camera


#: Where the render camera stands: above the whole scene, or in the first field's rows.
CAMERA_VIEWS = ("overview", "ground")
# How far a robot's camera looks down, in degrees.
_GROUND_PITCH_DEG = -6.0


def build_ground_camera(field: dict[str, Any], scene: Any, root: Any) -> Any:
    """A robot's-eye camera at the start of the first field, between its first two rows,
    looking along them (``field["ground_view"]``: location and compass bearing)."""
    view = field["ground_view"]
    data = bpy.data.cameras.new("agrirecipe_camera")
    data.lens = 24.0
    data.clip_start = 0.05
    data.clip_end = 2000.0
    camera = bpy.data.objects.new("agrirecipe_camera", data)
    camera.location = tuple(view["location_m"])
    camera.rotation_euler = look_rotation(float(view["bearing_deg"]), _GROUND_PITCH_DEG)
    root.objects.link(camera)
    scene.camera = camera
    return camera


def build_world(scene_data: dict[str, Any], scene: Any) -> None:
    """A plain sky colour lighting the scene from every side."""
    world = bpy.data.worlds.new("agrirecipe_sky")
    colour = srgb_to_linear(scene_data["style"]["colours"]["sky"])
    world.color = colour[:3]
    if world.node_tree is None:  # Blender 4.x creates worlds without nodes
        world.use_nodes = True
    background = next(
        (node for node in world.node_tree.nodes if node.bl_idname == "ShaderNodeBackground"), None
    )
    if background is not None:
        background.inputs["Color"].default_value = colour
        background.inputs["Strength"].default_value = float(
            scene_data["style"]["world"]["strength"]
        )
    scene.world = world


# --- render settings and the command line ---


def configure_render(scene: Any, settings: dict[str, Any]) -> None:
    """Resolution, engine (CPU Cycles, Workbench or EEVEE) and samples."""
    render = scene.render
    render.resolution_x, render.resolution_y = (int(v) for v in settings["resolution"])
    render.resolution_percentage = 100
    render.image_settings.file_format = "PNG"
    render.image_settings.color_mode = "RGB"
    name = str(settings["engine"])
    engine = ENGINES.get(name.lower(), name.upper())
    try:
        render.engine = engine
    except TypeError:
        if engine != "BLENDER_EEVEE":
            raise
        render.engine = "BLENDER_EEVEE_NEXT"  # its name in Blender 4.2-4.5
    samples = int(settings["samples"])
    if render.engine == "CYCLES":
        cycles = scene.cycles
        cycles.device = "CPU"  # headless machines have no GPU; CPU always works
        cycles.samples = samples
        cycles.preview_samples = samples
        cycles.max_bounces = 4  # outdoor daylight: more bounces cost time, not realism
        cycles.use_denoising = bool(settings.get("denoise", True))
    elif render.engine == "BLENDER_WORKBENCH":
        shading = scene.display.shading
        shading.light = "STUDIO"
        shading.color_type = "MATERIAL"
        shading.show_shadows = True
        scene.display.render_aa = "8" if samples >= 8 else "FXAA"
    else:
        scene.eevee.taa_render_samples = samples


def command_line_settings(settings: dict[str, Any], argv: Sequence[str]) -> dict[str, Any]:
    """``settings`` updated from the command line.

    Arguments are read after ``--`` (``blender -b -P blender_build.py -- --render
    out.png``), or after the script when it is run by ``python`` itself.
    """
    if "--" in argv:
        args = list(argv[list(argv).index("--") + 1 :])
    elif argv and str(argv[0]).endswith(".py"):
        args = list(argv[1:])
    else:
        args = []
    parser = argparse.ArgumentParser(
        prog="blender -b -P blender_build.py --",
        description="Build the agrirecipe scene; optionally render it or save a .blend file.",
    )
    parser.add_argument("--render", metavar="PNG", help="render to this PNG file")
    parser.add_argument("--save", metavar="BLEND", help="save the scene to this .blend file")
    parser.add_argument("--resolution", metavar="WxH", help="e.g. 1920x1080")
    parser.add_argument("--samples", type=int, help="render samples")
    parser.add_argument("--engine", choices=sorted(ENGINES), help="render engine")
    parser.add_argument("--plants", choices=PLANT_MODES, help="plant meshes or proxies")
    parser.add_argument("--view", choices=CAMERA_VIEWS, help="overview or ground camera")
    parser.add_argument("--assets", metavar="DIR", help="the folder holding assets/")
    parsed = parser.parse_args(args)
    updated = dict(settings)
    if parsed.render:
        updated["render_png"] = parsed.render
    if parsed.save:
        updated["save_blend"] = parsed.save
    if parsed.resolution:
        width, _, height = parsed.resolution.lower().partition("x")
        updated["resolution"] = (int(width), int(height))
    if parsed.samples:
        updated["samples"] = parsed.samples
    if parsed.engine:
        updated["engine"] = parsed.engine
    if parsed.plants:
        updated["plants"] = parsed.plants
    if parsed.view:
        updated["view"] = parsed.view
    if parsed.assets:
        updated["assets_root"] = parsed.assets
    return updated


# The kinds of data in Blender's default start-up scene (cube, camera, light, their
# data, the collection, world and material), by their bpy.data attribute names.
_STARTUP_DATA = (
    "objects",
    "meshes",
    "materials",
    "cameras",
    "lights",
    "collections",
    "worlds",
    "node_groups",
    "images",
)


def fresh_scene() -> Any:
    """An empty scene: Blender's empty factory state when headless, else a new scene.

    Resetting to factory settings inside the user interface would discard the
    open file (and the running script's own text), so there a new scene is
    added and shown instead.
    """
    if bpy.app.background:
        scene = bpy.context.scene
        if len(bpy.data.scenes) == 1 and not scene.get("agrirecipe_builder_version"):
            # A fresh Blender holds only its default start-up scene: removing what is in
            # it is as clean as a factory reset, and takes a millisecond instead of a
            # tenth of a second.
            bpy.data.batch_remove(
                [block for kind in _STARTUP_DATA for block in getattr(bpy.data, kind)]
            )
            return scene
        bpy.ops.wm.read_factory_settings(use_empty=True)  # an earlier build's state
        return bpy.context.scene
    scene = bpy.data.scenes.new("agrirecipe")
    window = getattr(bpy.context, "window", None)
    if window is not None:
        window.scene = scene
    return scene


def build_scene(
    scene_data: dict[str, Any], place_field: PlaceField, settings: dict[str, Any]
) -> dict[str, Any]:
    """Build the whole scene.

    Returns ``{"scene", "plants": {field id: count}, "seconds", "timings"}``;
    ``timings`` splits the seconds into ``kernel`` (placing plants), ``points``
    (filling point clouds), ``proxies`` and ``rest``.
    """
    started = time.perf_counter()
    verbose = bool(settings.get("verbose", True))
    scene = fresh_scene()
    scene["agrirecipe_builder_version"] = BUILDER_VERSION
    root = bpy.data.collections.new(ROOT_COLLECTION)
    scene.collection.children.link(root)
    proxy_root = bpy.data.collections.new(PROXY_COLLECTION)
    scene.collection.children.link(proxy_root)
    # Proxies are only drawn through the instancers: keep the originals out of renders.
    scene.view_layers[0].layer_collection.children[PROXY_COLLECTION].exclude = True
    counts: dict[str, int] = {}
    timings: dict[str, float] = {"kernel": 0.0, "points": 0.0, "proxies": 0.0}
    for field in scene_data["fields"]:
        collection = bpy.data.collections.new(field["id"])
        root.children.link(collection)
        proxy_started = time.perf_counter()
        proxies = None
        if settings.get("plants", "meshes") == "meshes":
            proxies = build_meshes(field, proxy_root, assets_root(settings))
            if proxies is not None:
                proxies["agrirecipe_meshes"] = True
        if proxies is None:
            proxies = build_proxies(field, proxy_root)
        timings["proxies"] += time.perf_counter() - proxy_started
        _, counts[field["id"]] = build_plants(field, place_field, collection, proxies, timings)
        if verbose:
            print(f"agrirecipe: {field['id']}: {counts[field['id']]:,} plants", flush=True)
    build_ground(scene_data, root)
    build_sun(scene_data, root)
    configure_render(scene, settings)
    width, height = scene.render.resolution_x, scene.render.resolution_y
    if settings.get("view", "overview") == "ground" and scene_data["fields"]:
        build_ground_camera(scene_data["fields"][0], scene, root)
    else:
        build_camera(scene_data, scene, root, width / height)
    build_world(scene_data, scene)
    seconds = time.perf_counter() - started
    timings["rest"] = seconds - sum(timings.values())
    if verbose:
        print(f"agrirecipe: built {sum(counts.values()):,} plants in {seconds:.1f} s", flush=True)
    return {"scene": scene, "plants": counts, "seconds": seconds, "timings": timings}


def render_png(scene: Any, path: str) -> None:
    """Render ``scene`` with its camera and write a PNG to ``path``."""
    scene.render.filepath = path
    bpy.ops.render.render(write_still=True, scene=scene.name)


def main(
    scene_data: dict[str, Any],
    place_field: PlaceField,
    settings: dict[str, Any],
    argv: Sequence[str] = (),
) -> dict[str, Any]:
    """Build the scene, then render and/or save it if the settings ask to."""
    settings = command_line_settings(settings, argv)
    report = build_scene(scene_data, place_field, settings)
    if settings.get("render_png"):
        render_png(report["scene"], str(settings["render_png"]))
    if settings.get("save_blend"):
        bpy.ops.wm.save_as_mainfile(filepath=str(settings["save_blend"]))
    return report
