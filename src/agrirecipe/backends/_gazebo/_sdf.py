"""SDFormat 1.7 elements of the Gazebo world: sun, ground, field models, spawn frame.

SDFormat 1.7 is the newest version both simulators read: Gazebo Classic 11
(libsdformat 9) reads up to 1.7, gz-sim (Fortress and later) reads 1.7 and
converts it. 1.7 is also the first version with ``<frame>`` in a world, which
holds the robot's spawn pose. Elements the SDFormat schema marks required even
though parsers default them (gravity, magnetic field, atmosphere, physics,
scene) are written out, so the file validates against the published XSDs.
Text is built with :mod:`xml.etree.ElementTree`, which escapes every value.
"""

from __future__ import annotations

import math
import xml.etree.ElementTree as ET
from collections.abc import Sequence

__all__ = [
    "SDF_VERSION",
    "child",
    "mesh_visual",
    "pose_text",
    "sdf_text",
    "sun_light",
    "world_element",
]

#: The SDFormat version of every file the backend writes.
SDF_VERSION = "1.7"


def _number(value: float) -> str:
    text = f"{value:.6f}".rstrip("0").rstrip(".")
    return "0" if text in ("-0", "") else text


def pose_text(x: float, y: float, z: float, yaw: float = 0.0) -> str:
    """``x y z roll pitch yaw`` (metres, radians) as SDF writes a pose."""
    return " ".join(_number(v) for v in (x, y, z, 0.0, 0.0, yaw))


def child(parent: ET.Element, tag: str, text: str | None = None, **attributes: str) -> ET.Element:
    """Append ``<tag attributes>text</tag>`` to ``parent``."""
    element = ET.SubElement(parent, tag, attributes)
    if text is not None:
        element.text = text
    return element


def _colour(rgb: Sequence[float], factor: float = 1.0) -> str:
    return " ".join(_number(min(1.0, c * factor)) for c in rgb) + " 1"


def mesh_visual(
    link: ET.Element,
    name: str,
    uri: str,
    rgb: Sequence[float],
    *,
    shadows: bool = True,
    double_sided: bool = False,
) -> ET.Element:
    """A visual drawing the mesh at ``uri`` in a flat colour (ambient a little darker),
    both faces of its triangles with ``double_sided``."""
    visual = child(link, "visual", name=name)
    child(visual, "cast_shadows", "true" if shadows else "false")
    geometry = child(visual, "geometry")
    mesh = child(geometry, "mesh")
    child(mesh, "uri", uri)
    material = child(visual, "material")
    child(material, "ambient", _colour(rgb, 0.8))
    child(material, "diffuse", _colour(rgb))
    child(material, "specular", "0.05 0.05 0.05 1")
    child(material, "emissive", "0 0 0 1")
    if double_sided:
        child(material, "double_sided", "true")
    return visual


def sun_light(
    parent: ET.Element, elevation_deg: float, azimuth_deg: float, centre: tuple[float, float]
) -> ET.Element:
    """A directional light shining from the recipe's sun (compass azimuth, clockwise from
    north = +Y; east = +X); below the horizon it is a dim night light from straight above."""
    elevation, azimuth = math.radians(elevation_deg), math.radians(azimuth_deg)
    if elevation_deg <= 0.0:
        toward = (0.0, 0.0, 1.0)
        diffuse, specular = "0.08 0.08 0.1 1", "0.01 0.01 0.01 1"
    else:
        toward = (
            math.sin(azimuth) * math.cos(elevation),
            math.cos(azimuth) * math.cos(elevation),
            math.sin(elevation),
        )
        diffuse, specular = "1 0.97 0.9 1", "0.3 0.3 0.3 1"
    light = child(parent, "light", name="sun", type="directional")
    child(light, "cast_shadows", "true")
    # Placed above the farm along its ray, for the editors' gizmo; only the direction lights.
    child(
        light,
        "pose",
        pose_text(centre[0] + 100 * toward[0], centre[1] + 100 * toward[1], 100 * toward[2]),
    )
    child(light, "diffuse", diffuse)
    child(light, "specular", specular)
    attenuation = child(light, "attenuation")
    child(attenuation, "range", "10000")
    child(attenuation, "constant", "0.9")
    child(attenuation, "linear", "0.01")
    child(attenuation, "quadratic", "0.001")
    child(light, "direction", " ".join(_number(-c) for c in toward))
    return light


def world_element(name: str) -> tuple[ET.Element, ET.Element]:
    """``<sdf><world>`` with the physics, scene and environment every world needs."""
    sdf = ET.Element("sdf", version=SDF_VERSION)
    world = child(sdf, "world", name=name)
    child(world, "gravity", "0 0 -9.8")
    child(world, "magnetic_field", "5.5645e-06 2.28758e-05 -4.23884e-05")
    child(world, "atmosphere", type="adiabatic")
    physics = child(world, "physics", name="default", default="true", type="ode")
    child(physics, "max_step_size", "0.001")
    child(physics, "real_time_factor", "1")
    child(physics, "real_time_update_rate", "1000")
    scene = child(world, "scene")
    child(scene, "ambient", "0.45 0.45 0.45 1")
    child(scene, "background", "0.7 0.8 0.95 1")
    child(scene, "shadows", "true")
    child(scene, "grid", "false")
    return sdf, world


def sdf_text(root: ET.Element, comment: str) -> str:
    """The document as indented UTF-8 text with an XML declaration and a leading comment."""
    ET.indent(root, space="  ")
    body = ET.tostring(root, encoding="unicode")
    safe = comment.replace("--", "- -")  # '--' may not appear inside an XML comment
    return f'<?xml version="1.0" encoding="UTF-8"?>\n<!-- {safe} -->\n{body}\n'
