"""Building recipe parts from resolved attributes and the knowledge base.

The resolver decides *what* each field is (crop, variety, stage, season,
health) and *where* (geometry, from the field packer); these functions fill in
everything else from domain knowledge: asset path, agronomy, placement, and
the environment's sun.
"""

from __future__ import annotations

import math
from collections.abc import Mapping, Sequence

from agrirecipe.hierarchy import Hierarchy
from agrirecipe.knowledge import KnowledgeBase
from agrirecipe.recipe import (
    Agronomy,
    AttributeName,
    Environment,
    FieldGeometry,
    FieldSpec,
    HealthState,
    Placement,
    Season,
    Stage,
    Sun,
)

__all__ = ["DEFAULT_LATITUDE_DEG", "build_environment", "build_field", "sun_for"]

#: Default scene latitude: Sint-Truiden, Belgium (the reference data's region).
DEFAULT_LATITUDE_DEG = 50.8

# Solar declination in the middle of each northern-hemisphere meteorological season
# (mid-April, mid-July, mid-October, mid-January), degrees.
_MID_SEASON_DECLINATION_DEG = {"Spring": 9.4, "Summer": 21.5, "Fall": -8.6, "Winter": -21.2}
# The light is set for mid-afternoon (15:00 solar time): long shadows show row structure.
_HOUR_ANGLE_DEG = 45.0


def sun_for(season: Season, latitude_deg: float) -> Sun:
    """Sun elevation and azimuth at 15:00 solar time in the middle of ``season``.

    Seasons are the local ones: in the southern hemisphere, Summer means
    January, so the declination's sign is flipped.
    """
    declination = _MID_SEASON_DECLINATION_DEG[season]
    if latitude_deg < 0:
        declination = -declination
    lat = math.radians(latitude_deg)
    dec = math.radians(declination)
    hour = math.radians(_HOUR_ANGLE_DEG)
    sin_elevation = math.sin(lat) * math.sin(dec) + math.cos(lat) * math.cos(dec) * math.cos(hour)
    elevation = math.asin(max(-1.0, min(1.0, sin_elevation)))
    # Azimuth clockwise from north (afternoon: the sun is in the west half).
    cos_azimuth = (math.sin(dec) - math.sin(elevation) * math.sin(lat)) / max(
        1e-9, math.cos(elevation) * math.cos(lat)
    )
    azimuth = math.degrees(math.acos(max(-1.0, min(1.0, cos_azimuth))))
    azimuth = 360.0 - azimuth  # afternoon
    return Sun(
        elevation_deg=round(math.degrees(elevation), 3), azimuth_deg=round(azimuth % 360.0, 3)
    )


def build_environment(season: Season, latitude_deg: float = DEFAULT_LATITUDE_DEG) -> Environment:
    """The scene environment for a dominant season at a latitude."""
    return Environment(
        season=season,
        latitude_deg=latitude_deg,
        hemisphere="north" if latitude_deg >= 0 else "south",
        sun=sun_for(season, latitude_deg),
    )


def build_field(
    *,
    hierarchy: Hierarchy,
    knowledge: KnowledgeBase,
    field_id: str,
    label: str,
    crop: str,
    variety: str,
    stage: Stage,
    season: Season,
    health: HealthState,
    geometry: FieldGeometry,
    placement: Placement | None = None,
    stated: Sequence[AttributeName] = (),
    inferred: Sequence[AttributeName] = (),
    agronomy_update: Mapping[str, float | int] | None = None,
) -> FieldSpec:
    """A complete :class:`FieldSpec`: asset path, agronomy and placement from the knowledge base.

    ``agronomy_update`` replaces knowledge-base values the prompt stated (row and
    in-row spacing, rows per bed); the result is validated again.
    """
    key = hierarchy.key(crop, variety, stage, season, health)
    agronomy = knowledge.agronomy(key)
    if agronomy_update:
        agronomy = Agronomy.model_validate({**agronomy.model_dump(), **agronomy_update})
    return FieldSpec(
        id=field_id,
        label=label,
        category=key.category,
        crop=crop,
        variety=variety,
        stage=stage,
        season=season,
        health=health,
        asset_path=hierarchy.asset_path(key),
        agronomy=agronomy,
        geometry=geometry,
        placement=placement or knowledge.default_placement(crop, variety),
        stated=tuple(stated),
        inferred=tuple(inferred),
    )
