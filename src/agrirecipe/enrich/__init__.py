"""Enrichment: complete recipe parts from resolved attributes and crop knowledge."""

from agrirecipe.enrich._build import DEFAULT_LATITUDE_DEG, build_environment, build_field, sun_for
from agrirecipe.enrich._rows import RowPlan, plan_rows

__all__ = [
    "DEFAULT_LATITUDE_DEG",
    "RowPlan",
    "build_environment",
    "build_field",
    "plan_rows",
    "sun_for",
]
