"""Enrichment: complete recipe parts from resolved attributes and crop knowledge."""

from agrirecipe.enrich._build import DEFAULT_LATITUDE_DEG, build_environment, build_field, sun_for

__all__ = ["DEFAULT_LATITUDE_DEG", "build_environment", "build_field", "sun_for"]
