"""``resolve()``: prompt -> :class:`SceneIntent` (a strategy) -> validated :class:`SceneRecipe`.

After the strategy has read the prompt, the same stages run for every
strategy: *validate* the intent against the hierarchy (``_validate``), *choose*
crops for generic fields (``_choose``: seeded, honouring categories, distinctness
and season),
*enrich* unstated attributes from the knowledge base (recorded as inferred;
implausible stated combinations kept and reported as warnings), *lay out* the
fields (:func:`agrirecipe.layout.pack_fields`) and *build* the recipe.
"""

from __future__ import annotations

import functools
import math
import re
from collections import Counter
from collections.abc import Callable, Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import TYPE_CHECKING, TypeVar

from pydantic import ValidationError

from agrirecipe._errors import ConfigurationError, PromptError
from agrirecipe.enrich import (
    DEFAULT_LATITUDE_DEG,
    build_environment,
    build_field,
    plan_rows,
    thin_to_fit,
)
from agrirecipe.hierarchy import Hierarchy, default_hierarchy, load_hierarchy
from agrirecipe.knowledge import KnowledgeBase, default_knowledge_base, load_knowledge_base
from agrirecipe.recipe import (
    DEFAULT_MAX_PLANTS,
    AttributeName,
    FieldSpec,
    HealthState,
    Relation,
    SceneRecipe,
    Season,
    Stage,
)
from agrirecipe.resolve._choose import choose_crops, distinct_varieties, scene_season_of
from agrirecipe.resolve._explain import Explanation
from agrirecipe.resolve._intent import (
    FieldIntent,
    ResolveContext,
    Resolver,
    SceneIntent,
    TraceStep,
)
from agrirecipe.resolve._lexicon import vocabulary
from agrirecipe.resolve._registry import get_resolver
from agrirecipe.resolve._validate import validate_intent

if TYPE_CHECKING:
    from agrirecipe.recipe import FieldGeometry

__all__ = ["MAX_PROMPT_CHARS", "Resolution", "build_recipe", "resolve"]

#: The longest prompt read (characters); a longer one is a PromptError at once.
MAX_PROMPT_CHARS = 4000

_T = TypeVar("_T")
# Nouns that name a kind of planting; a generic field keeps them ("an orchard").
_KIND_NOUNS = frozenset({"orchard", "vineyard", "grove", "plantation", "garden"})
_NOUN_BY_FORM = {"tree": "orchard", "vine": "vineyard"}
# A stated size keeps a headland of at most this share of its shorter side, so a
# small plot ("a 10 by 10 m strawberry patch") still holds plants.
_MAX_HEADLAND_SHARE = 0.1


@dataclass(frozen=True, slots=True)
class Resolution:
    """What :func:`resolve` returns: the recipe, the strategy's intent and, if asked, why."""

    recipe: SceneRecipe
    intent: SceneIntent
    explanation: Explanation | None = None
    knowledge: KnowledgeBase | None = None


def resolve(
    prompt: str,
    *,
    seed: int = 0,
    resolver: str | Resolver = "auto",
    hierarchy: Hierarchy | str | Path | None = None,
    knowledge: KnowledgeBase | str | Path | None = None,
    latitude_deg: float | None = None,
    explain: bool = False,
    max_plants: int = DEFAULT_MAX_PLANTS,
) -> Resolution:
    """Turn a natural-language request into a validated :class:`SceneRecipe`.

    ``resolver`` is a strategy name ("rules", "embedding", "llm", "hybrid",
    "auto") or a :class:`Resolver`. ``hierarchy`` and ``knowledge`` are objects
    or paths (the shipped ones when None). ``latitude_deg`` overrides a place
    named in the prompt. ``max_plants`` caps the planting positions of the whole
    scene (default 10 million). Raises :class:`~agrirecipe.PromptError` (or its
    subclass :class:`~agrirecipe.UnknownCropError`) for requests that cannot
    be honoured, :class:`~agrirecipe.ConfigurationError` for bad arguments.
    """
    if isinstance(prompt, str) and len(prompt) > MAX_PROMPT_CHARS:
        raise PromptError(
            f"the prompt is {len(prompt):,} characters long; agrirecipe reads at most "
            f"{MAX_PROMPT_CHARS:,}",
            stage="resolve",
            hint="describe the scene in fewer words (a scene holds at most 64 fields), or "
            "build a larger scene from several recipes",
        )
    if isinstance(seed, bool) or not isinstance(seed, int) or not 0 <= seed < 2**63:
        raise ConfigurationError(
            f"seed must be a whole number from 0 to 2**63 - 1, got {seed!r}", stage="resolve"
        )
    if latitude_deg is not None and (
        isinstance(latitude_deg, bool)
        or not isinstance(latitude_deg, int | float)
        or not math.isfinite(latitude_deg)
        or not -90.0 <= latitude_deg <= 90.0
    ):
        raise ConfigurationError(
            f"latitude_deg must be between -90 and 90 degrees, got {latitude_deg!r}",
            stage="resolve",
        )
    if isinstance(max_plants, bool) or not isinstance(max_plants, int) or max_plants < 1:
        raise ConfigurationError(
            f"max_plants must be a positive whole number, got {max_plants!r}", stage="resolve"
        )
    if hierarchy is None and isinstance(knowledge, KnowledgeBase):
        hierarchy = knowledge.hierarchy  # a knowledge base brings its own hierarchy
    tree = _hierarchy(hierarchy)
    kb = _knowledge(knowledge, tree)
    if kb.hierarchy is not tree and kb.hierarchy.digest() != tree.digest():
        raise ConfigurationError(
            "the knowledge base was loaded for another hierarchy than the one given",
            stage="resolve",
            hint="load it with load_knowledge_base(folder, hierarchy) for this hierarchy, "
            "or pass only one of them",
        )
    strategy = get_resolver(resolver)
    context = ResolveContext(
        hierarchy=tree,
        knowledge=kb,
        seed=seed,
        latitude_deg=None if latitude_deg is None else float(latitude_deg),
        explain=explain,
        max_plants=max_plants,
    )
    intent = strategy.resolve_intent(prompt, context)
    recipe, steps = build_recipe(intent, context, resolver=strategy.name)
    explanation = None
    if explain:
        explanation = Explanation(
            prompt=prompt,
            resolver=strategy.name,
            seed=seed,
            steps=(*intent.trace, *steps),
            warnings=recipe.warnings,
        )
    return Resolution(recipe=recipe, intent=intent, explanation=explanation, knowledge=kb)


def _hierarchy(value: Hierarchy | str | Path | None) -> Hierarchy:
    if value is None:
        return default_hierarchy()
    if isinstance(value, Hierarchy):
        return value
    if isinstance(value, str | Path):
        return _load_hierarchy(str(value), _stamp(value))
    raise ConfigurationError(
        f"hierarchy must be a Hierarchy or a path, not {type(value).__name__}", stage="resolve"
    )


def _stamp(path: str | Path) -> float:
    """The file's modification time (a changed file is loaded again), or 0 if missing."""
    try:
        return Path(path).stat().st_mtime
    except OSError:
        return 0.0


@functools.lru_cache(maxsize=4)
def _load_hierarchy(path: str, stamp: float) -> Hierarchy:
    return load_hierarchy(path)


def _knowledge(value: KnowledgeBase | str | Path | None, hierarchy: Hierarchy) -> KnowledgeBase:
    if isinstance(value, KnowledgeBase):
        return value
    if value is None:
        if hierarchy is default_hierarchy():
            return default_knowledge_base()
        return _load_knowledge(None, hierarchy, 0.0)
    if isinstance(value, str | Path):
        folder = Path(value)
        stamp = max((f.stat().st_mtime for f in folder.glob("*.yaml")), default=_stamp(folder))
        return _load_knowledge(str(value), hierarchy, stamp)
    raise ConfigurationError(
        f"knowledge must be a KnowledgeBase or a folder path, not {type(value).__name__}",
        stage="resolve",
    )


@functools.lru_cache(maxsize=4)
def _load_knowledge(path: str | None, hierarchy: Hierarchy, stamp: float) -> KnowledgeBase:
    return load_knowledge_base(path, hierarchy)


# --- from intent to recipe ---


@dataclass
class _Plan:
    """One field's resolved attributes before it is built."""

    intent: FieldIntent
    crop: str
    variety: str
    stage: Stage
    season: Season
    health: HealthState
    stated: list[AttributeName]
    inferred: list[AttributeName]
    size_m: tuple[float, float]
    headland_m: float
    noun: str
    notes: list[str]
    rotation_deg: float = 0.0
    planted_m: tuple[float, float] | None = None
    plant_count: int | None = None
    agronomy_update: dict[str, float | int] | None = None
    warnings: tuple[str, ...] = ()


def build_recipe(
    intent: SceneIntent, context: ResolveContext, *, resolver: str
) -> tuple[SceneRecipe, list[TraceStep]]:
    """Validate, choose, enrich, lay out and build: the stages after a strategy."""
    steps: list[TraceStep] = []
    validate_intent(intent, context)
    crops = choose_crops(intent, context, steps)
    varieties = distinct_varieties(intent, crops, context, steps)
    scene_season = scene_season_of(intent, crops, context)
    plans = [
        _enrich(intent, index, crops[index], varieties[index], scene_season, context, steps)
        for index in range(len(intent.fields))
    ]
    warnings = list(intent.warnings)
    for plan in plans:
        warnings.extend(plan.warnings)
    ids = _field_ids(plans, context)
    labels = _labels(plans)
    for plan, field_id in zip(plans, ids, strict=True):
        if plan.notes:
            steps.append(
                TraceStep(
                    stage="enrich", subject=field_id, detail="inferred " + "; ".join(plan.notes)
                )
            )
    for plan, field_id in zip(plans, ids, strict=True):
        if {"stage", "season"} & set(plan.stated):
            reason = context.knowledge.implausibility(
                plan.crop, plan.variety, plan.stage, plan.season, plan.health
            )
            if reason is not None:
                warnings.append(f"{field_id}: {reason} (kept as asked)")
    relations = tuple(
        Relation(
            kind=relation.kind,
            subject=ids[relation.subject],
            objects=tuple(ids[o] for o in relation.objects),
        )
        for relation in intent.relations
    )
    geometry = _layout(plans, ids, relations)
    fields: list[FieldSpec] = []
    for plan, field_id, label in zip(plans, ids, labels, strict=True):
        try:
            spec = build_field(
                hierarchy=context.hierarchy,
                knowledge=context.knowledge,
                field_id=field_id,
                label=label,
                crop=plan.crop,
                variety=plan.variety,
                stage=plan.stage,
                season=plan.season,
                health=plan.health,
                geometry=geometry[field_id],
                stated=plan.stated,
                inferred=plan.inferred,
                agronomy_update=plan.agronomy_update,
            )
        except ValidationError as exc:
            width, length = plan.size_m
            hint = "ask for a larger field"
            if "size" in plan.stated and max(width, length) <= _SPACING_SIZED_M:
                # "both blocks 4 m x 2 m": said like a planting grid, read as a field
                hint += (
                    f"; if {width:g} x {length:g} m is the planting grid, say so: "
                    f"'planted at {width:g} m x {length:g} m' or '{width:g} x {length:g} m "
                    "spacing'"
                )
            raise PromptError(
                f"{label}: {_first_message(exc)}",
                stage="enrich",
                path=field_id,
                hint=hint,
            ) from exc
        fields.append(spec)
    latitude = context.latitude_deg
    if latitude is None:
        latitude = intent.latitude_deg if intent.latitude_deg is not None else DEFAULT_LATITUDE_DEG
    season = _dominant_season([f.season for f in fields])
    # (20 ha of wheat: the densest fields draw every N-th plant rather than be refused)
    fields, thinned = thin_to_fit(fields, context.max_plants)
    warnings.extend(thinned)
    try:
        recipe = SceneRecipe.model_validate(
            {
                "prompt": intent.prompt,
                "seed": context.seed,
                "resolver": resolver,
                "environment": build_environment(season, latitude),
                "fields": tuple(fields),
                "relations": relations,
                "warnings": tuple(warnings),
            },
            context={"max_plants": context.max_plants},
        )
    except ValidationError as exc:
        message = _first_message(exc)
        capped = "(make fields smaller or raise max_plants)" in message
        raise_cap = "; or raise the cap: generate(..., max_plants=N), --max-plants N"
        raise PromptError(
            message.replace(" (make fields smaller or raise max_plants)", ""),
            stage="validate",
            hint="ask for fewer or smaller fields" + (raise_cap if capped else ""),
        ) from exc
    for spec in fields:
        x, y = spec.geometry.origin_m
        width, length = spec.geometry.size_m
        steps.append(
            TraceStep(
                stage="layout",
                subject=spec.id,
                detail=f"{spec.variety} {spec.crop}, {spec.stage}, {spec.season}, {spec.health}; "
                f"{width:g} x {length:g} m at ({x:g}, {y:g})",
            )
        )
    steps.append(
        TraceStep(
            stage="layout",
            subject="scene",
            detail=f"{len(fields)} field(s), environment {season} at latitude {latitude:g}",
        )
    )
    return recipe, steps


#: A stated field no longer than this either way may have meant a planting grid.
_SPACING_SIZED_M = 12.0


def _first_message(exc: ValidationError) -> str:
    """The first problem in words, without pydantic's prefix or the model-internal path."""
    error = exc.errors()[0]
    message = str(error["msg"]).removeprefix("Value error, ")
    path, sep, rest = message.partition(": ")
    if sep and re.fullmatch(r"[\w\[\].]+", path):
        message = rest
    return message


def _enrich(
    intent: SceneIntent,
    index: int,
    crop: str,
    distinct_variety: str | None,
    scene_season: tuple[Season, str],
    context: ResolveContext,
    steps: list[TraceStep],
) -> _Plan:
    field = intent.fields[index]
    knowledge = context.knowledge
    stated: list[AttributeName] = []
    inferred: list[AttributeName] = []
    notes: list[str] = []
    if field.generic:
        if field.category is not None:
            stated.append("category")
        inferred.append("crop")
    else:
        stated.append("crop")

    def pick(name: AttributeName, value: _T | None, infer: Callable[[], tuple[_T, str]]) -> _T:
        if value is not None:
            stated.append(name)
            return value
        value, why = infer()
        inferred.append(name)
        notes.append(f"{name} {value} ({why})")
        return value

    variety = pick(
        "variety",
        field.variety,
        lambda: (
            (distinct_variety, "different from the other fields")
            if distinct_variety is not None
            else (knowledge.default_variety(crop), "default")
        ),
    )

    # A season said for one field and contradicted by none holds for the scene.
    said = {f.season for f in intent.fields if f.season is not None}
    only = next(iter(said)) if len(said) == 1 else None
    season: Season = pick("season", field.season or intent.season or only, lambda: scene_season)
    stage: Stage = pick(
        "stage",
        field.stage,
        lambda: (knowledge.typical_stage(crop, season, variety), f"typical in {season}"),
    )
    health: HealthState = pick("health", field.health, lambda: ("Healthy", "unless said otherwise"))
    width, length = knowledge.default_field_size_m(crop, variety)
    headland = knowledge.default_headland_m(crop, variety)
    rows = None
    if field.rows is not None:
        size = field.size
        rows = plan_rows(
            field.rows.stated(),
            knowledge.crop_file(crop, variety),
            label=field.mention or field.text or crop,
            size_m=(size.width_m, size.length_m)
            if size is not None and size.width_m is not None and size.length_m is not None
            else None,
            area_m2=size.area_m2 if size is not None else None,
            default_size_m=(width, length),
            default_headland_m=headland,
        )
        stated.extend(rows.stated)
        if size is not None:
            stated.append("size")
        width, length = rows.size_m
        headland = rows.headland_m
    elif field.size is not None:
        stated.append("size")
        if field.size.width_m is not None and field.size.length_m is not None:
            width, length = field.size.width_m, field.size.length_m
        elif field.size.area_m2 is not None:
            scale = math.sqrt(field.size.area_m2 / (width * length))
            width, length = width * scale, length * scale
        width, length = round(width, 2), round(length, 2)
        headland = min(headland, round(_MAX_HEADLAND_SHARE * min(width, length), 2))
    elif rows is None:
        inferred.append("size")
    noun = field.noun
    if noun is None or (field.generic and noun not in _KIND_NOUNS):
        # "four fields" that became an apple crop are orchards.
        noun = plot_noun(crop, knowledge)
    return _Plan(
        intent=field,
        crop=crop,
        variety=variety,
        stage=stage,
        season=season,
        health=health,
        stated=stated,
        inferred=inferred,
        size_m=(width, length),
        headland_m=headland,
        noun=noun,
        notes=notes,
        rotation_deg=rows.rotation_deg if rows is not None else 0.0,
        planted_m=rows.planted_m if rows is not None else None,
        plant_count=rows.plant_count if rows is not None else None,
        agronomy_update=rows.agronomy_update() if rows is not None else None,
        warnings=tuple(rows.warnings) if rows is not None else (),
    )


def plot_noun(crop: str, knowledge: KnowledgeBase) -> str:
    """What a plot of ``crop`` is called: "orchard", "vineyard", "plantation", "field"."""
    noun: str = vocabulary()["crop_plot_nouns"].get(crop) or _NOUN_BY_FORM.get(
        knowledge.crop_file(crop).growth_form, "field"
    )
    return noun


def _slug(text: str) -> str:
    return re.sub(r"[^a-z0-9]+", "_", text.lower()).strip("_")


def _field_ids(plans: Sequence[_Plan], context: ResolveContext) -> list[str]:
    """``apple_orchard_1``, ``carrot_field_1``, ``carrot_field_2``... (engine-safe)."""
    ids: list[str] = []
    counts: Counter[str] = Counter()
    for plan in plans:
        stem = f"{_slug(plan.crop)}_{_slug(plan.noun)}"[:56].strip("_") or "field"
        if not stem[0].isalpha():
            stem = f"field_{stem}"
        counts[stem] += 1
        ids.append(f"{stem}_{counts[stem]}")
    return ids


def _labels(plans: Sequence[_Plan]) -> list[str]:
    """Readable names: "Pink Lady apple orchard", "Nantes carrot field 2"."""
    base = [f"{plan.variety} {plan.crop.lower()} {plan.noun}" for plan in plans]
    totals = Counter(base)
    seen: Counter[str] = Counter()
    labels = []
    for label in base:
        seen[label] += 1
        labels.append(f"{label} {seen[label]}" if totals[label] > 1 else label)
    return labels


def _layout(
    plans: Sequence[_Plan], ids: Sequence[str], relations: Sequence[Relation]
) -> dict[str, FieldGeometry]:
    from agrirecipe.layout import FieldRequest, pack_fields

    requests = [
        FieldRequest(
            field_id,
            plan.size_m[0],
            plan.size_m[1],
            plan.headland_m,
            plan.rotation_deg,
            planted_m=plan.planted_m,
            plant_count=plan.plant_count,
        )
        for plan, field_id in zip(plans, ids, strict=True)
    ]
    return pack_fields(requests, relations)


def _dominant_season(seasons: Sequence[Season]) -> Season:
    """The most common field season; ties go to the first field's."""
    counts = Counter(seasons)
    best = max(counts.values())
    return next(season for season in seasons if counts[season] == best)
