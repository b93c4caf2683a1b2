"""Enrichment: complete recipe parts from resolved attributes and crop knowledge."""

from agrirecipe.enrich._build import DEFAULT_LATITUDE_DEG, build_environment, build_field, sun_for
from agrirecipe.enrich._rows import RowPlan, plan_rows
from agrirecipe.enrich._thinning import DENSE_PLANTS_PER_HA, thin_to_fit

__all__ = [
    "DEFAULT_LATITUDE_DEG",
    "DENSE_PLANTS_PER_HA",
    "RowPlan",
    "build_environment",
    "build_field",
    "plan_rows",
    "sun_for",
    "thin_to_fit",
]
