"""Scoring one prompt's outcome against its ground truth.

A recipe is reduced to a :class:`PredictedScene` (what the scorer compares),
its fields are matched to the truth fields by an optimal assignment, and the
result is a :class:`PromptScore`: correct or not, why not, the field-level
counts behind precision / recall / F1, and the phantom fields (recipe fields
beyond what the prompt asked for, e.g. a "field" made of scenery words).
"""

from __future__ import annotations

import itertools
import math
from collections.abc import Sequence
from dataclasses import dataclass, replace
from typing import TYPE_CHECKING

from agrirecipe._errors import AgrirecipeError
from agrirecipe.evaluation._benchmark import (
    ATTRIBUTES,
    BenchmarkPrompt,
    GeometryKey,
    TruthField,
    TruthRelation,
)

if TYPE_CHECKING:
    from agrirecipe.recipe import SceneRecipe

__all__ = [
    "BEARING_TOLERANCE_DEG",
    "SIZE_TOLERANCE",
    "PredictedField",
    "PredictedRelation",
    "PredictedScene",
    "PromptScore",
    "optimal_assignment",
    "score_prompt",
]

#: Relative tolerance on stated sizes and areas (a resolver may round to centimetres),
#: and on the stated geometry's lengths, spacings and densities.
SIZE_TOLERANCE = 0.01
#: Tolerance on a stated row bearing, in degrees (compared modulo 180).
BEARING_TOLERANCE_DEG = 1.0
#: Attributes a resolver chooses when the prompt leaves them open (category follows the crop).
_CHOSEN = ATTRIBUTES[1:]


#: Truth geometry key -> the PredictedField attribute it is compared with
#: (``row_spacing_m`` depends on the rows per bed: see :meth:`PredictedField.geometry`).
_GEOMETRY_SOURCE: dict[GeometryKey, str] = {
    "rows": "row_count",
    "beds": "bed_count",
    "rows_per_bed": "rows_per_bed",
    "row_length_m": "row_length_m",
    "row_spacing_m": "row_spacing_m",
    "bed_width_m": "row_spacing_m",
    "in_row_spacing_m": "in_row_spacing_m",
    "plants_per_ha": "plants_per_ha",
    "plant_count": "nominal_plant_count",
    "headland_m": "headland_m",
    "row_bearing_deg": "row_bearing_deg",
}
#: How a geometry key reads in a mismatch note: (words, unit).
_GEOMETRY_WORDS: dict[GeometryKey, tuple[str, str]] = {
    "rows": ("rows", ""),
    "beds": ("beds", ""),
    "rows_per_bed": ("rows per bed", ""),
    "row_length_m": ("row length", " m"),
    "row_spacing_m": ("row spacing", " m"),
    "bed_width_m": ("bed width", " m"),
    "in_row_spacing_m": ("in-row spacing", " m"),
    "plants_per_ha": ("density", " plants/ha"),
    "plant_count": ("plants", ""),
    "headland_m": ("headland", " m"),
    "row_bearing_deg": ("row bearing", " deg"),
}
#: Geometry keys that are counts, compared exactly.
_COUNT_KEYS: frozenset[GeometryKey] = frozenset({"rows", "beds", "rows_per_bed", "plant_count"})


@dataclass(frozen=True, slots=True)
class PredictedField:
    """The parts of a recipe field the benchmark checks."""

    id: str
    category: str
    crop: str
    variety: str
    stage: str
    season: str
    health: str
    size_m: tuple[float, float] | None = None
    stated: tuple[str, ...] = ()
    inferred: tuple[str, ...] = ()
    # The geometry the recipe lays out (None: unknown, e.g. a field built by hand in a test).
    # Named as in the recipe's FieldSpec, so ``row_spacing_m`` is the centre distance of
    # rows, or of beds when ``rows_per_bed`` > 1 (then ``bed_row_spacing_m`` is the
    # distance of the rows on a bed).
    row_count: int | None = None
    bed_count: int | None = None
    rows_per_bed: int | None = None
    row_length_m: float | None = None
    row_spacing_m: float | None = None
    bed_row_spacing_m: float | None = None
    in_row_spacing_m: float | None = None
    plants_per_ha: float | None = None
    nominal_plant_count: int | None = None
    headland_m: float | None = None
    row_bearing_deg: float | None = None

    def geometry(self, key: GeometryKey) -> float | None:
        """The recipe's value for the truth's geometry ``key`` (None when unknown).

        ``row_spacing_m`` is the distance of neighbouring rows: the row (centre)
        spacing of single rows, the spacing of the rows on a bed otherwise;
        ``bed_width_m`` is the centre distance of beds (of rows, for single rows).
        """
        if key == "row_spacing_m":
            if self.rows_per_bed is None or self.rows_per_bed == 1:
                return self.row_spacing_m
            return self.bed_row_spacing_m
        value: float | None = getattr(self, _GEOMETRY_SOURCE[key])
        return value

    def describe(self) -> str:
        """E.g. ``Apple/Gala, Reproductive, Spring, Healthy, 60x100 m``."""
        text = f"{self.crop}/{self.variety}, {self.stage}, {self.season}, {self.health}"
        if self.size_m is not None:
            text += f", {self.size_m[0]:g}x{self.size_m[1]:g} m"
        return text


@dataclass(frozen=True, slots=True)
class PredictedRelation:
    """A relation of the recipe, between field ids."""

    kind: str
    subject: str
    objects: tuple[str, ...]


@dataclass(frozen=True, slots=True)
class PredictedScene:
    """What a resolver produced for a prompt, in the form the scorer compares."""

    fields: tuple[PredictedField, ...]
    relations: tuple[PredictedRelation, ...] = ()
    hemisphere: str | None = None
    warnings: tuple[str, ...] = ()

    @classmethod
    def from_recipe(cls, recipe: SceneRecipe) -> PredictedScene:
        """Reduce a :class:`~agrirecipe.recipe.SceneRecipe` to what the benchmark checks."""
        return cls(
            fields=tuple(
                PredictedField(
                    id=spec.id,
                    category=spec.category,
                    crop=spec.crop,
                    variety=spec.variety,
                    stage=spec.stage,
                    season=spec.season,
                    health=spec.health,
                    size_m=(float(spec.geometry.size_m[0]), float(spec.geometry.size_m[1])),
                    stated=tuple(spec.stated),
                    inferred=tuple(spec.inferred),
                    row_count=spec.row_count,
                    bed_count=spec.bed_count,
                    rows_per_bed=spec.agronomy.rows_per_bed,
                    row_length_m=float(spec.row_length_m),
                    row_spacing_m=float(spec.agronomy.row_spacing_m),
                    bed_row_spacing_m=float(spec.agronomy.bed_row_spacing_m),
                    in_row_spacing_m=float(spec.agronomy.in_row_spacing_m),
                    plants_per_ha=float(spec.plants_per_ha),
                    nominal_plant_count=spec.nominal_plant_count,
                    headland_m=float(spec.geometry.headland_m),
                    row_bearing_deg=float(spec.row_bearing_deg),
                )
                for spec in recipe.fields
            ),
            relations=tuple(
                PredictedRelation(r.kind, r.subject, tuple(r.objects)) for r in recipe.relations
            ),
            hemisphere=recipe.environment.hemisphere,
            warnings=tuple(recipe.warnings),
        )

    def describe(self) -> str:
        """All fields and relations on one line."""
        text = "; ".join(f.describe() for f in self.fields)
        if self.relations:
            text += " | " + ", ".join(
                f"{r.subject} {r.kind} {'+'.join(r.objects)}" for r in self.relations
            )
        return text


@dataclass(frozen=True, slots=True)
class PromptScore:
    """The verdict on one prompt for one strategy."""

    prompt_id: str
    type: str
    tags: tuple[str, ...]
    prompt: str
    correct: bool
    reasons: tuple[str, ...]
    expected: str
    got: str
    kinds: tuple[str, ...] = ()
    true_positives: int = 0
    predicted_fields: int = 0
    truth_fields: int = 0
    error_class_ok: bool | None = None
    phantom_fields: int = 0
    inferred_checked: int = 0
    inferred_ok: int = 0
    seconds: float | None = None
    split: str = "dev"


# --- field matching ---


def _mismatches(truth: TruthField, field: PredictedField) -> list[tuple[str, str]]:
    """(kind, note) for every stated attribute of ``truth`` that ``field`` gets wrong."""
    notes: list[tuple[str, str]] = []
    for attribute in ATTRIBUTES:
        allowed = truth.allowed(attribute)
        value = getattr(field, attribute)
        if allowed is not None and value not in allowed:
            notes.append((attribute, f"{attribute} {value} (expected {'|'.join(allowed)})"))
    if truth.size_m is not None and (
        field.size_m is None or not _sizes_match(truth.size_m, field.size_m)
    ):
        got = "none" if field.size_m is None else f"{field.size_m[0]:g}x{field.size_m[1]:g}"
        notes.append(("size", f"size {got} m (expected {truth.size_m[0]:g}x{truth.size_m[1]:g})"))
    if truth.area_m2 is not None:
        area = field.size_m[0] * field.size_m[1] if field.size_m is not None else 0.0
        if not math.isclose(area, truth.area_m2, rel_tol=SIZE_TOLERANCE):
            notes.append(("size", f"area {area:g} m2 (expected {truth.area_m2:g})"))
    for key, expected in truth.geometry().items():
        value = field.geometry(key)
        if value is None or not _geometry_matches(key, expected, value):
            words, unit = _GEOMETRY_WORDS[key]
            shown = "none" if value is None else f"{value:g}{unit}"
            notes.append(("geometry", f"geometry: {words} {shown} (expected {expected:g})"))
    return notes


def _geometry_matches(key: GeometryKey, expected: float, got: float) -> bool:
    """Counts exactly, the bearing within a degree modulo 180, the rest within 1 %."""
    if key in _COUNT_KEYS:
        return got == expected
    if key == "row_bearing_deg":
        difference = abs(got - expected) % 180.0
        return min(difference, 180.0 - difference) <= BEARING_TOLERANCE_DEG
    return math.isclose(got, expected, rel_tol=SIZE_TOLERANCE, abs_tol=1e-9)


def _sizes_match(expected: tuple[float, float], got: tuple[float, float]) -> bool:
    # Orientation is the layout's choice unless a relation pins it: compare as unordered pairs.
    return all(
        math.isclose(a, b, rel_tol=SIZE_TOLERANCE)
        for a, b in zip(sorted(expected), sorted(got), strict=True)
    )


def optimal_assignment(weights: Sequence[Sequence[float]]) -> list[int | None]:
    """Assign each row a distinct column maximising the total weight (Hungarian algorithm).

    Returns, per row, the column index or None when there are more rows than
    columns and the row is left out. Exact, O(n^2 m); matrices here are tiny.
    """
    rows = len(weights)
    cols = len(weights[0]) if rows else 0
    if rows == 0 or cols == 0:
        return [None] * rows
    transpose = rows > cols
    matrix = [list(r) for r in (zip(*weights, strict=True) if transpose else weights)]
    n, m = len(matrix), len(matrix[0])
    big = max(abs(w) for r in matrix for w in r) + 1.0
    cost = [[big - w for w in row] for row in matrix]  # minimise cost = maximise weight
    # Potentials u (rows), v (cols); p[j] = row matched to column j (1-based, 0 = none).
    u = [0.0] * (n + 1)
    v = [0.0] * (m + 1)
    p = [0] * (m + 1)
    way = [0] * (m + 1)
    for i in range(1, n + 1):
        p[0] = i
        j0 = 0
        minv = [math.inf] * (m + 1)
        used = [False] * (m + 1)
        while True:
            used[j0] = True
            i0, delta, j1 = p[j0], math.inf, 0
            for j in range(1, m + 1):
                if not used[j]:
                    cur = cost[i0 - 1][j - 1] - u[i0] - v[j]
                    if cur < minv[j]:
                        minv[j], way[j] = cur, j0
                    if minv[j] < delta:
                        delta, j1 = minv[j], j
            for j in range(m + 1):
                if used[j]:
                    u[p[j]] += delta
                    v[j] -= delta
                else:
                    minv[j] -= delta
            j0 = j1
            if p[j0] == 0:
                break
        while j0:
            j1 = way[j0]
            p[j0] = p[j1]
            j0 = j1
    row_to_col: list[int | None] = [None] * n
    for j in range(1, m + 1):
        if p[j]:
            row_to_col[p[j] - 1] = j - 1
    if not transpose:
        return row_to_col
    result: list[int | None] = [None] * rows
    for col, row in enumerate(row_to_col):
        if row is not None:
            result[row] = col
    return result


def _relation_form(kind: str, subject: str, objects: Sequence[str]) -> tuple[object, ...]:
    """A canonical form so that symmetric and inverse statements compare equal."""
    if kind == "next_to":
        return ("next_to", frozenset((subject, *objects)))
    if kind == "between":
        return ("between", subject, frozenset(objects))
    inverse = {"south_of": "north_of", "west_of": "east_of"}
    if kind in inverse:
        return (inverse[kind], objects[0], subject)
    return (kind, subject, objects[0])


def _describe_truth(item: BenchmarkPrompt) -> str:
    text = "; ".join(f.describe() for f in item.fields)
    low, high = item.count_range
    if high != low:
        text += f" (+ up to {high - len(item.fields)} more)"
    if item.distinct_crops:
        text += " [distinct crops]"
    if item.relations:
        text += " | " + ", ".join(_describe_relation(r) for r in item.relations)
    if item.hemisphere:
        text += f" [{item.hemisphere}ern hemisphere]"
    if item.expect_warning:
        text += " [with a warning]"
    return text


def _describe_relation(relation: TruthRelation) -> str:
    return f"{relation.subject} {relation.kind} {'+'.join(relation.objects)}"


# --- the verdict ---


def score_prompt(
    item: BenchmarkPrompt, outcome: PredictedScene | BaseException, *, seconds: float | None = None
) -> PromptScore:
    """Score one prompt's outcome: a predicted scene, or the exception the resolver raised."""
    if item.invalid:
        return _score_invalid(item, outcome, seconds)
    base = _blank_score(item, _describe_truth(item), seconds)
    base = replace(base, truth_fields=len(item.fields))
    if isinstance(outcome, BaseException):
        return replace(
            base,
            reasons=(f"raised {_error_text(outcome)}",),
            kinds=("rejected" if isinstance(outcome, AgrirecipeError) else "foreign_error",),
            got=_error_text(outcome),
        )
    scene = outcome
    truth, predicted = item.fields, scene.fields
    problems: list[tuple[str, str]] = []
    weights = [
        [(100.0 if not _mismatches(t, p) else 0.0) + _agreement(t, p) for p in predicted]
        for t in truth
    ]
    assignment = optimal_assignment(weights)
    matched: dict[int, int] = {}
    for t_index, p_index in enumerate(assignment):
        label = truth[t_index].ref or f"field {t_index + 1}"
        if p_index is None:
            problems.append(("count", f"{label} ({truth[t_index].describe()}) missing"))
            continue
        notes = _mismatches(truth[t_index], predicted[p_index])
        if notes:
            problems.extend((kind, f"{label}: {note}") for kind, note in notes)
        else:
            matched[t_index] = p_index
    low, high = item.count_range
    if not low <= len(predicted) <= high:
        wanted = str(low) if low == high else f"{low}-{high}"
        problems.append(("count", f"{len(predicted)} field(s), expected {wanted}"))
    used = set(assignment)
    extras = [p for index, p in enumerate(predicted) if index not in used]
    accepted_extras = 0
    for field in extras:
        if item.extra_field is not None and not _mismatches(item.extra_field, field):
            accepted_extras += 1
        else:
            problems.append(("count", f"unexpected field {field.describe()}"))
    accepted_extras = min(accepted_extras, max(0, high - len(truth)))
    # Phantom fields: recipe fields left without a truth field by the assignment and not
    # accepted as extras (a field assigned to a truth field but wrong is not a phantom).
    phantoms = len(extras) - accepted_extras
    if item.distinct_crops and len({p.crop for p in predicted}) != len(predicted):
        problems.append(("distinct", "crops are not all different"))
    matched = _best_for_relations(item, scene, matched, weights)
    problems.extend(("relation", text) for text in _relation_problems(item, scene, matched))
    if item.hemisphere is not None and scene.hemisphere != item.hemisphere:
        problems.append(
            ("hemisphere", f"hemisphere {scene.hemisphere} (expected {item.hemisphere})")
        )
    if item.expect_warning and not scene.warnings:
        problems.append(("warning", "no warning for an implausible combination"))
    checked = ok = 0
    for t_index, p_index in matched.items():
        checked += 1
        ok += _inference_marked(truth[t_index], predicted[p_index])
    return replace(
        base,
        correct=not problems,
        reasons=tuple(text for _, text in problems),
        kinds=tuple(dict.fromkeys(kind for kind, _ in problems)),
        got=scene.describe(),
        true_positives=len(matched) + accepted_extras,
        predicted_fields=len(predicted),
        phantom_fields=phantoms,
        inferred_checked=checked,
        inferred_ok=ok,
    )


def _blank_score(item: BenchmarkPrompt, expected: str, seconds: float | None) -> PromptScore:
    return PromptScore(
        prompt_id=item.id,
        type=item.type,
        tags=item.tags,
        prompt=item.prompt,
        correct=False,
        reasons=(),
        expected=expected,
        got="",
        seconds=seconds,
        split=item.split,
    )


def _agreement(truth: TruthField, field: PredictedField) -> float:
    """How many stated attributes agree (guides the assignment among partial matches)."""
    return float(
        sum(
            1
            for attribute in ATTRIBUTES
            if (allowed := truth.allowed(attribute)) is not None
            and getattr(field, attribute) in allowed
        )
    )


#: The most truth fields one group of interchangeable matches may hold (6! orders).
_MOST_INTERCHANGEABLE = 6


def _best_for_relations(
    item: BenchmarkPrompt,
    scene: PredictedScene,
    matched: dict[int, int],
    weights: Sequence[Sequence[float]],
) -> dict[int, int]:
    """The matching, among those as good as ``matched`` field by field, under which the
    most truth relations hold: truth fields that match each other's recipe fields
    equally well ("two veg plots, each 20 rows at 50 cm, one directly north of the other")
    are interchangeable, and the relations say which is which."""
    if not item.relations:
        return matched
    groups: list[list[int]] = []
    for t_index in sorted(matched):
        for group in groups:
            if all(
                weights[t_index][matched[other]] == weights[t_index][matched[t_index]]
                and weights[other][matched[t_index]] == weights[other][matched[other]]
                for other in group
            ):
                group.append(t_index)
                break
        else:
            groups.append([t_index])
    best, fewest = matched, len(_relation_problems(item, scene, matched))
    for group in groups:
        if len(group) < 2 or len(group) > _MOST_INTERCHANGEABLE or not fewest:
            continue
        columns = [best[t] for t in group]
        for order in itertools.permutations(columns):
            trial = {**best, **dict(zip(group, order, strict=True))}
            count = len(_relation_problems(item, scene, trial))
            if count < fewest:
                best, fewest = trial, count
    return best


def _relation_problems(
    item: BenchmarkPrompt, scene: PredictedScene, matched: dict[int, int]
) -> list[str]:
    if not item.relations:
        return []
    ref_to_id = {
        item.fields[t].ref: scene.fields[p].id for t, p in matched.items() if item.fields[t].ref
    }
    present = {_relation_form(r.kind, r.subject, r.objects) for r in scene.relations}
    problems: list[str] = []
    for relation in item.relations:
        names = (relation.subject, *relation.objects)
        if any(name not in ref_to_id for name in names):
            problems.append(f"relation {_describe_relation(relation)}: its fields are not matched")
            continue
        form = _relation_form(
            relation.kind, ref_to_id[relation.subject], [ref_to_id[o] for o in relation.objects]
        )
        if form not in present:
            problems.append(f"relation {_describe_relation(relation)} missing")
    return problems


def _inference_marked(truth: TruthField, field: PredictedField) -> bool:
    """Attributes the prompt did not state must be marked inferred, not stated."""
    for attribute in _CHOSEN:
        allowed = truth.allowed(attribute)
        open_choice = allowed is None or len(allowed) > 1 or attribute in truth.inferred
        if open_choice and attribute not in field.inferred:
            return False
    return True


def _error_text(error: BaseException) -> str:
    return f"{type(error).__name__}: {error}"


def _score_invalid(
    item: BenchmarkPrompt, outcome: PredictedScene | BaseException, seconds: float | None
) -> PromptScore:
    import agrirecipe

    expected_class = getattr(agrirecipe, item.error or "AgrirecipeError")
    base = _blank_score(item, f"rejected with {item.error}", seconds)
    if isinstance(outcome, AgrirecipeError):
        return replace(
            base,
            correct=True,
            got=_error_text(outcome),
            error_class_ok=isinstance(outcome, expected_class),
        )
    if isinstance(outcome, BaseException):
        return replace(
            base,
            reasons=(f"raised {type(outcome).__name__}, not an AgrirecipeError",),
            kinds=("foreign_error",),
            got=_error_text(outcome),
            error_class_ok=False,
        )
    return replace(
        base,
        reasons=("accepted: a recipe was returned instead of an error",),
        kinds=("accepted",),
        got=outcome.describe(),
        predicted_fields=len(outcome.fields),
        error_class_ok=False,
    )
