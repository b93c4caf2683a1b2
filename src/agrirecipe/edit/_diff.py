"""What differs between two recipes, one readable line per change."""

from __future__ import annotations

from agrirecipe.layout import describe_relation
from agrirecipe.recipe import FieldSpec, SceneRecipe

__all__ = ["diff_recipes"]

_ATTRIBUTES = ("crop", "variety", "stage", "season", "health")
_AGRONOMY = (
    ("row_spacing_m", "row spacing"),
    ("in_row_spacing_m", "in-row spacing"),
    ("rows_per_bed", "rows per bed"),
    ("bed_row_spacing_m", "row spacing in the bed"),
)


def _summary(spec: FieldSpec) -> str:
    width, length = spec.geometry.size_m
    x, y = spec.geometry.origin_m
    return (
        f"{spec.variety} {spec.crop}, {spec.stage}, {spec.season}, {spec.health}; "
        f"{width:g} x {length:g} m at ({x:g}, {y:g})"
    )


def _number(value: float) -> str:
    return f"{value:g}"


def _field_changes(old: FieldSpec, new: FieldSpec) -> list[str]:
    parts = [
        f"{name} {getattr(old, name)} -> {getattr(new, name)}"
        for name in _ATTRIBUTES
        if getattr(old, name) != getattr(new, name)
    ]
    if old.label != new.label:
        parts.append(f"label {old.label!r} -> {new.label!r}")
    for name, words in _AGRONOMY:
        before, after = getattr(old.agronomy, name), getattr(new.agronomy, name)
        if before != after:
            unit = "" if name == "rows_per_bed" else " m"
            parts.append(f"{words} {_number(before)} -> {_number(after)}{unit}")
    geometry_old, geometry_new = old.geometry, new.geometry
    if geometry_old.size_m != geometry_new.size_m:
        (w0, l0), (w1, l1) = geometry_old.size_m, geometry_new.size_m
        parts.append(f"size {w0:g} x {l0:g} -> {w1:g} x {l1:g} m")
    if geometry_old.origin_m != geometry_new.origin_m:
        (x0, y0), (x1, y1) = geometry_old.origin_m, geometry_new.origin_m
        parts.append(f"origin ({x0:g}, {y0:g}) -> ({x1:g}, {y1:g})")
    if geometry_old.rotation_deg != geometry_new.rotation_deg:
        parts.append(f"rotation {geometry_old.rotation_deg:g} -> {geometry_new.rotation_deg:g} deg")
    if geometry_old.headland_m != geometry_new.headland_m:
        parts.append(f"headland {geometry_old.headland_m:g} -> {geometry_new.headland_m:g} m")
    if not parts and old.agronomy != new.agronomy:
        parts.append("agronomy recomputed")
    now_stated = [name for name in new.stated if name not in old.stated]
    if now_stated and not parts:
        parts.append("now stated: " + ", ".join(now_stated))
    return parts


def diff_recipes(old: SceneRecipe, new: SceneRecipe) -> tuple[str, ...]:
    """Lines such as ``"~ pear_orchard_1: health Healthy -> Ill"``, ``"+ wheat_field_1 ..."``,
    ``"- carrot_field_1 ..."`` and relation and environment changes; empty when equal."""
    lines: list[str] = []
    before = {f.id: f for f in old.fields}
    after = {f.id: f for f in new.fields}
    for field_id, spec in before.items():
        if field_id not in after:
            lines.append(f"- {field_id} ({spec.label}): {_summary(spec)}")
    for field_id, spec in after.items():
        if field_id not in before:
            lines.append(f"+ {field_id} ({spec.label}): {_summary(spec)}")
        elif spec != before[field_id]:
            lines.append(f"~ {field_id}: " + "; ".join(_field_changes(before[field_id], spec)))
    old_relations = {describe_relation(r) for r in old.relations}
    new_relations = {describe_relation(r) for r in new.relations}
    lines.extend(f"- relation {r}" for r in sorted(old_relations - new_relations))
    lines.extend(f"+ relation {r}" for r in sorted(new_relations - old_relations))
    if old.environment != new.environment:
        lines.append(f"~ environment: season {old.environment.season} -> {new.environment.season}")
    return tuple(lines)
