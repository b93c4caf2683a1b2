"""Layout: field rectangles packed without overlap, and every plant placed by a seeded kernel."""

from agrirecipe.layout._packing import DEFAULT_GAP_M, FieldRequest, describe_relation, pack_fields

__all__ = ["DEFAULT_GAP_M", "FieldRequest", "describe_relation", "pack_fields"]
