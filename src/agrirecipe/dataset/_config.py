"""Dataset defaults (``data/dataset.yaml``) as frozen values: camera rigs, weeds, conditions."""

from __future__ import annotations

import functools
import math
import re
from dataclasses import dataclass, fields, replace
from importlib import resources
from typing import Any, Literal

import yaml

from agrirecipe._errors import ConfigurationError

__all__ = [
    "CAMERA_KINDS",
    "CameraKind",
    "CameraRigs",
    "DroneRig",
    "OverviewRig",
    "RobotRig",
    "dataset_defaults",
    "parse_weed_density",
    "weeds_in_prompt",
]

CameraKind = Literal["robot", "drone", "overview", "random"]
#: Camera rigs a dataset view can use; ``random`` draws one of the first three per view.
CAMERA_KINDS: tuple[CameraKind, ...] = ("robot", "drone", "overview", "random")


def _check(name: str, value: float, low: float, high: float) -> None:
    if isinstance(value, bool) or not isinstance(value, int | float) or not low <= value <= high:
        raise ConfigurationError(
            f"camera setting {name}={value!r} is out of range",
            stage="dataset",
            hint=f"a number from {low:g} to {high:g}",
        )


@dataclass(frozen=True)
class RobotRig:
    """A ground robot's camera between two crop rows, looking along them."""

    height_m: float = 1.0
    pitch_deg: float = -25.0
    hfov_deg: float = 75.0
    heading_jitter_deg: float = 6.0
    row_margin_m: float = 1.0

    def __post_init__(self) -> None:
        _check("robot height_m", self.height_m, 0.05, 20.0)
        _check("robot pitch_deg", self.pitch_deg, -90.0, 30.0)
        _check("robot hfov_deg", self.hfov_deg, 5.0, 150.0)
        _check("robot heading_jitter_deg", self.heading_jitter_deg, 0.0, 180.0)
        _check("robot row_margin_m", self.row_margin_m, 0.0, 100.0)


@dataclass(frozen=True)
class DroneRig:
    """A drone camera at ``altitude_m`` above a field, nadir or oblique.

    With ``gsd_m`` (ground sampling distance: metres per pixel at nadir) the
    focal length follows from it: ``lens = altitude * sensor_width / (width_px * gsd)``;
    otherwise from ``hfov_deg``.
    """

    altitude_m: float = 10.0
    view: Literal["nadir", "oblique"] = "nadir"
    oblique_pitch_deg: float = -50.0
    hfov_deg: float = 70.0
    gsd_m: float | None = None

    def __post_init__(self) -> None:
        _check("drone altitude_m", self.altitude_m, 0.5, 2000.0)
        _check("drone oblique_pitch_deg", self.oblique_pitch_deg, -89.0, -5.0)
        _check("drone hfov_deg", self.hfov_deg, 5.0, 150.0)
        if self.gsd_m is not None:
            _check("drone gsd_m", self.gsd_m, 1e-5, 10.0)
        if self.view not in ("nadir", "oblique"):
            raise ConfigurationError(
                f"unknown drone view {self.view!r}", stage="dataset", hint="nadir or oblique"
            )


@dataclass(frozen=True)
class OverviewRig:
    """Every field framed from above at an angle; bearing and pitch jittered per view."""

    lens_mm: float = 35.0
    bearing_deg: float = 340.0
    pitch_deg: float = -32.0
    pitch_jitter_deg: float = 8.0
    bearing_jitter_deg: float = 45.0
    margin: float = 1.05

    def __post_init__(self) -> None:
        _check("overview lens_mm", self.lens_mm, 5.0, 500.0)
        _check("overview bearing_deg", self.bearing_deg, -360.0, 360.0)
        _check("overview pitch_deg", self.pitch_deg, -89.0, -5.0)
        _check("overview pitch_jitter_deg", self.pitch_jitter_deg, 0.0, 40.0)
        _check("overview bearing_jitter_deg", self.bearing_jitter_deg, 0.0, 180.0)
        _check("overview margin", self.margin, 1.0, 3.0)


@dataclass(frozen=True)
class CameraRigs:
    """The three camera rigs and the sensor they share (defaults from ``dataset.yaml``)."""

    robot: RobotRig = RobotRig()
    drone: DroneRig = DroneRig()
    overview: OverviewRig = OverviewRig()
    sensor_width_mm: float = 36.0
    clip_start_m: float = 0.05
    clip_end_m: float = 2000.0

    @classmethod
    def defaults(cls) -> CameraRigs:
        """The rigs as ``dataset.yaml`` sets them."""
        cameras = dataset_defaults()["cameras"]
        return cls(
            robot=RobotRig(**cameras["robot"]),
            drone=DroneRig(**cameras["drone"]),
            overview=OverviewRig(**cameras["overview"]),
            sensor_width_mm=float(cameras["sensor_width_mm"]),
            clip_start_m=float(cameras["clip_start_m"]),
            clip_end_m=float(cameras["clip_end_m"]),
        )

    def with_overrides(self, **overrides: Any) -> CameraRigs:
        """A copy with ``robot_height_m=...``, ``drone_gsd_m=...`` style overrides (None: kept)."""
        rigs: dict[str, Any] = {"robot": self.robot, "drone": self.drone, "overview": self.overview}
        for key, value in overrides.items():
            if value is None:
                continue
            rig_name, _, attribute = key.partition("_")
            rig = rigs.get(rig_name)
            if rig is None or attribute not in {f.name for f in fields(rig)}:
                raise ConfigurationError(f"unknown camera setting {key!r}", stage="dataset")
            rigs[rig_name] = replace(rig, **{attribute: value})
        return replace(self, **rigs)

    def as_dict(self) -> dict[str, Any]:
        """JSON-able settings (for the manifest)."""
        return {
            "robot": vars(self.robot).copy(),
            "drone": vars(self.drone).copy(),
            "overview": vars(self.overview).copy(),
            "sensor_width_mm": self.sensor_width_mm,
            "clip_start_m": self.clip_start_m,
            "clip_end_m": self.clip_end_m,
        }


@functools.cache
def _load_defaults() -> dict[str, Any]:
    text = resources.files("agrirecipe.dataset").joinpath("data/dataset.yaml").read_text("utf-8")
    data: dict[str, Any] = yaml.safe_load(text)
    return data


def dataset_defaults() -> dict[str, Any]:
    """The parsed ``dataset.yaml`` (a fresh copy each call)."""
    import copy

    return copy.deepcopy(_load_defaults())


_DENSITY = re.compile(r"^\s*([0-9]*\.?[0-9]+)\s*(?:/\s*m2|/\s*m\^2|/\s*m²|per\s+m2)?\s*$")


def parse_weed_density(value: float | str | None) -> float:
    """Weeds per m² from a number, ``"0.5/m2"`` or a word (``few``, ``some``, ``many``)."""
    if value is None:
        return 0.0
    words: dict[str, float] = dataset_defaults()["weeds"]["words"]
    if isinstance(value, str):
        text = value.strip().lower()
        if text in ("", "none", "no"):
            return 0.0
        if text in words:
            return float(words[text])
        match = _DENSITY.match(text)
        if match is None:
            raise ConfigurationError(
                f"weed density {value!r} is not understood",
                stage="dataset",
                hint="weeds per square metre such as 0.5 or 0.5/m2, or one of " + ", ".join(words),
            )
        density = float(match.group(1))
    elif isinstance(value, bool) or not isinstance(value, int | float):
        raise ConfigurationError(f"weed density {value!r} is not a number", stage="dataset")
    else:
        density = float(value)
    if not math.isfinite(density) or not 0.0 <= density <= 1000.0:
        raise ConfigurationError(
            f"weed density {density!r} per m² is out of range",
            stage="dataset",
            hint="0 to 1000 weeds per m²",
        )
    return density


def weeds_in_prompt(prompt: str) -> float | None:
    """The weed density a prompt asks for ("with some weeds", "a weedy field"), or None.

    The phrases and their densities are ``weeds.phrases`` in ``dataset.yaml``.
    """
    for phrase in dataset_defaults()["weeds"]["phrases"]:
        if re.search(phrase["pattern"], prompt, flags=re.IGNORECASE):
            return float(phrase["density"])
    return None
