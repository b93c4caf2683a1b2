"""The benchmark files: prompts with ground truth, and knowledge-retrieval queries.

``benchmarks/prompts.yaml`` and ``benchmarks/knowledge_queries.yaml`` (format in
``benchmarks/README.md``) are validated here with pydantic and then against a
hierarchy: every name in the truth must be a canonical name of it, a variety
must belong to its crop, and a category must contain its crops. A malformed file
raises :class:`BenchmarkError` naming the offending entry.
"""

from __future__ import annotations

from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import Any, Literal, TypeVar, get_args

import yaml
from pydantic import BaseModel, ConfigDict, Field, ValidationError, field_validator, model_validator

from agrirecipe._errors import UserInputError
from agrirecipe._resources import data_path
from agrirecipe.hierarchy import AssetKey, Hierarchy, default_hierarchy
from agrirecipe.recipe import RelationKind

__all__ = [
    "ATTRIBUTES",
    "PROMPT_TYPES",
    "SHIPPED_PROMPT_FILES",
    "TAGS",
    "Benchmark",
    "BenchmarkError",
    "BenchmarkPrompt",
    "FieldCount",
    "KnowledgeQuery",
    "PromptType",
    "Split",
    "Tag",
    "TruthField",
    "TruthRelation",
    "load_benchmark",
    "load_knowledge_queries",
    "round_robin",
]

#: Prompt types, in the order tables show them (the paper's three first).
PromptType = Literal[
    "single_detailed", "single_generic", "multi_generic", "multi_detailed", "invalid"
]
PROMPT_TYPES: tuple[PromptType, ...] = get_args(PromptType)
Tag = Literal[
    "paper",
    "paraphrase",
    "alias",
    "typo",
    "ambiguous",
    "size_relation",
    "month_season",
    "implausible",
]
TAGS: tuple[Tag, ...] = get_args(Tag)
#: "dev": prompts the resolvers were developed against; "heldout": written after.
Split = Literal["dev", "heldout"]
Attribute = Literal["category", "crop", "variety", "stage", "season", "health"]
#: The attributes a truth field can state, in display order.
ATTRIBUTES: tuple[Attribute, ...] = ("category", "crop", "variety", "stage", "season", "health")
_ERROR_NAMES = frozenset(
    {
        "AgrirecipeError",
        "UserInputError",
        "PromptError",
        "UnknownCropError",
        "RecipeValidationError",
        "ConfigurationError",
    }
)


class BenchmarkError(UserInputError):
    """A benchmark or knowledge-query file that is malformed or names unknown crops."""


class _Strict(BaseModel):
    model_config = ConfigDict(extra="forbid", frozen=True)


def _any_of(value: object) -> object:
    """A single name or a list of names (any of them is right) -> a tuple of names."""
    if value is None or isinstance(value, tuple):
        return value
    if isinstance(value, str):
        return (value,)
    if isinstance(value, list):
        return tuple(value)
    return value


class TruthField(_Strict):
    """What one field of the recipe must be; an omitted attribute is left open by the prompt.

    Each attribute holds the accepted canonical names (one, or several when the
    prompt allows any of them, e.g. an "orchard" is any tree fruit).
    """

    ref: str | None = Field(default=None, pattern=r"^[a-z][a-z0-9_]*$")
    category: tuple[str, ...] | None = None
    crop: tuple[str, ...] | None = None
    variety: tuple[str, ...] | None = None
    stage: tuple[Literal["Vegetative", "Reproductive", "Maturation"], ...] | None = None
    season: tuple[Literal["Spring", "Summer", "Fall", "Winter"], ...] | None = None
    health: tuple[Literal["Healthy", "Ill"], ...] | None = None
    size_m: tuple[float, float] | None = Field(
        default=None, description="Width and length in metres, in either order."
    )
    area_m2: float | None = Field(default=None, gt=0)
    inferred: tuple[Attribute, ...] = Field(
        default=(), description="Attributes filled from the file's defaults, not the prompt."
    )

    _normalise = field_validator(
        "category", "crop", "variety", "stage", "season", "health", mode="before"
    )(_any_of)

    @field_validator("category", "crop", "variety", "stage", "season", "health")
    @classmethod
    def _non_empty(cls, value: tuple[str, ...] | None) -> tuple[str, ...] | None:
        if value is not None and not value:
            raise ValueError("an empty list accepts nothing; omit the attribute to leave it open")
        return value

    @field_validator("size_m")
    @classmethod
    def _positive(cls, value: tuple[float, float] | None) -> tuple[float, float] | None:
        if value is not None and min(value) <= 0:
            raise ValueError("sizes must be positive")
        return value

    def allowed(self, attribute: Attribute) -> tuple[str, ...] | None:
        """The accepted values of ``attribute``, or None when the prompt leaves it open."""
        value: tuple[str, ...] | None = getattr(self, attribute)
        return value

    def describe(self) -> str:
        """A compact human-readable form, e.g. ``Apple/Gala, Reproductive, Spring, Healthy``."""
        parts: list[str] = []
        crop = "|".join(self.crop) if self.crop else None
        if crop and self.variety:
            parts.append(f"{crop}/{'|'.join(self.variety)}")
        elif crop:
            parts.append(crop)
        elif self.category:
            parts.append("|".join(self.category))
        else:
            parts.append("any crop")
        for attribute in ("stage", "season", "health"):
            values = self.allowed(attribute)
            if values:
                parts.append("|".join(values))
        if self.area_m2 is not None:
            parts.append(f"{self.area_m2:g} m2")
        if self.size_m is not None:
            parts.append(f"{self.size_m[0]:g}x{self.size_m[1]:g} m")
        return ", ".join(parts)


class TruthRelation(_Strict):
    """A spatial relation the recipe must carry, between truth fields named by ``ref``."""

    kind: RelationKind
    subject: str
    objects: tuple[str, ...] = Field(min_length=1, max_length=2)

    @model_validator(mode="after")
    def _arity(self) -> TruthRelation:
        expected = 2 if self.kind == "between" else 1
        if len(self.objects) != expected:
            raise ValueError(f"{self.kind!r} takes {expected} object(s)")
        return self


class FieldCount(_Strict):
    """An open field count ("some fruit and vegetable fields"): any count in [min, max]."""

    min: int = Field(ge=1)
    max: int = Field(ge=1, le=64)

    @model_validator(mode="after")
    def _ordered(self) -> FieldCount:
        if self.min > self.max:
            raise ValueError("min must not exceed max")
        return self


class BenchmarkPrompt(_Strict):
    """One prompt and the recipe it must give (or the error it must raise)."""

    id: str = Field(pattern=r"^[a-z0-9][a-z0-9-]*$")
    type: PromptType
    tags: tuple[Tag, ...] = ()
    prompt: str
    fields: tuple[TruthField, ...] = ()
    relations: tuple[TruthRelation, ...] = ()
    field_count: FieldCount | None = None
    extra_field: TruthField | None = None
    distinct_crops: bool = False
    hemisphere: Literal["north", "south"] | None = None
    expect_warning: bool = False
    error: str | None = None
    split: Split = Field(default="dev", description="Set from the file's 'split'.")

    @property
    def invalid(self) -> bool:
        """True when the prompt must be rejected with an error."""
        return self.type == "invalid"

    @property
    def count_range(self) -> tuple[int, int]:
        """The accepted number of recipe fields."""
        if self.field_count is not None:
            return self.field_count.min, self.field_count.max
        return len(self.fields), len(self.fields)

    @model_validator(mode="after")
    def _consistent(self) -> BenchmarkPrompt:
        if self.invalid:
            if self.error is None:
                raise ValueError("an invalid prompt needs 'error': the expected error class")
            if self.fields or self.relations or self.field_count or self.extra_field:
                raise ValueError("an invalid prompt has no truth fields or relations")
        else:
            if self.error is not None:
                raise ValueError("'error' is only for prompts of type invalid")
            if not self.fields:
                raise ValueError("a valid prompt needs at least one truth field")
            single = self.type.startswith("single")
            if single and (len(self.fields) != 1 or self.field_count is not None):
                raise ValueError(f"a {self.type} prompt has exactly one field")
            if not single and self.count_range[1] < 2:
                raise ValueError(f"a {self.type} prompt has at least two fields")
        if self.error is not None and self.error not in _ERROR_NAMES:
            raise ValueError(
                f"error {self.error!r} is not one of {', '.join(sorted(_ERROR_NAMES))}"
            )
        if self.field_count is not None:
            if self.field_count.min < len(self.fields):
                raise ValueError("field_count.min is below the number of truth fields")
            if self.field_count.max > len(self.fields) and self.extra_field is None:
                raise ValueError("an open count needs 'extra_field': what the extra fields may be")
        elif self.extra_field is not None:
            raise ValueError("'extra_field' needs an open 'field_count'")
        refs = [f.ref for f in self.fields if f.ref is not None]
        if len(set(refs)) != len(refs):
            raise ValueError("duplicate field refs")
        for relation in self.relations:
            for name in (relation.subject, *relation.objects):
                if name not in refs:
                    raise ValueError(
                        f"relation names unknown ref {name!r} (refs: {', '.join(refs)})"
                    )
        if len(set(self.tags)) != len(self.tags):
            raise ValueError("duplicate tags")
        return self


class _BenchmarkFile(_Strict):
    version: Literal[1]
    split: Split = "dev"
    defaults: dict[Literal["stage", "season", "health"], str] = {}
    sets: dict[str, Any] = {}
    prompts: tuple[BenchmarkPrompt, ...] = Field(min_length=1)


class Benchmark(_Strict):
    """The validated prompt benchmark (defaults applied, categories filled in)."""

    source: str = Field(description="The file(s) it was loaded from.")
    prompts: tuple[BenchmarkPrompt, ...]

    def select(
        self,
        *,
        types: Sequence[str] | None = None,
        tags: Sequence[str] | None = None,
        ids: Sequence[str] | None = None,
        splits: Sequence[str] | None = None,
        limit: int | None = None,
    ) -> Benchmark:
        """Prompts of any of ``types`` with any of ``tags``/``ids``/``splits``, at most ``limit``.

        ``limit`` keeps the first prompts of each type in turn (round robin), so a
        small subset still covers every type.
        """
        chosen = [
            p
            for p in self.prompts
            if (not types or p.type in types)
            and (not tags or set(tags) & set(p.tags))
            and (not ids or p.id in ids)
            and (not splits or p.split in splits)
        ]
        if limit is not None:
            keep = {p.id for p in round_robin(chosen, lambda p: p.type, limit)}
            chosen = [p for p in chosen if p.id in keep]
        return Benchmark(source=self.source, prompts=tuple(chosen))

    def __len__(self) -> int:
        return len(self.prompts)


_Item = TypeVar("_Item")


def round_robin(items: Sequence[_Item], group: Callable[[_Item], str], limit: int) -> list[_Item]:
    """At most ``limit`` items, the first of each group in turn, so a subset covers every group."""
    groups: dict[str, list[_Item]] = {}
    for item in items:
        groups.setdefault(group(item), []).append(item)
    chosen: list[_Item] = []
    depth = 0
    while len(chosen) < min(limit, len(items)):
        for members in groups.values():
            if depth < len(members) and len(chosen) < limit:
                chosen.append(members[depth])
        depth += 1
    return chosen


class _KeyFile(_Strict):
    crop: str
    variety: str
    stage: str
    season: str
    health: str


@dataclass(frozen=True, slots=True)
class KnowledgeQuery:
    """A description of one catalogue asset in words, and the asset it names."""

    query: str
    key: AssetKey


class _QueryFile(_Strict):
    version: Literal[1]
    queries: tuple[dict[str, Any], ...] = Field(min_length=1)


# --- loading ---


def _read_yaml(path: Path, what: str) -> object:
    try:
        return yaml.safe_load(path.read_text(encoding="utf-8"))
    except FileNotFoundError:
        raise BenchmarkError(f"{what} file {str(path)!r} does not exist", stage="eval") from None
    except yaml.YAMLError as exc:
        raise BenchmarkError(
            f"{what} file {str(path)!r} is not valid YAML: {exc}", stage="eval"
        ) from exc


def _validation_message(exc: ValidationError, raw: object) -> str:
    error = exc.errors()[0]
    location = list(error["loc"])
    # Name the prompt by its id rather than its index: that is what a person searches for.
    if (
        len(location) >= 2
        and location[0] in ("prompts", "queries")
        and isinstance(location[1], int)
    ):
        items = raw.get(str(location[0])) if isinstance(raw, dict) else None
        if (
            isinstance(items, list)
            and location[1] < len(items)
            and isinstance(items[location[1]], dict)
        ):
            ident = items[location[1]].get("id") or items[location[1]].get("query")
            location[1] = f"{location[1]} ({ident})"
    where = ".".join(str(part) for part in location)
    return f"{where}: {error['msg']} ({len(exc.errors())} problem(s))"


_FileModel = TypeVar("_FileModel", bound=BaseModel)


def _parse_file(model: type[_FileModel], source: Path, what: str) -> _FileModel:
    """Read a YAML file and validate it with ``model``; errors name the entry at fault."""
    raw = _read_yaml(source, what)
    try:
        return model.model_validate(raw)
    except ValidationError as exc:
        raise BenchmarkError(
            f"{what} file {str(source)!r} is malformed: {_validation_message(exc, raw)}",
            stage="eval",
            hint="see benchmarks/README.md for the format",
        ) from exc


def _check_names(field: TruthField, hierarchy: Hierarchy, where: str) -> TruthField:
    """Check every name against the hierarchy and fill ``category`` from the crops."""
    crops = field.crop or ()
    for crop in crops:
        if crop not in hierarchy.crops:
            raise BenchmarkError(
                f"{where}: {crop!r} is not a crop of the hierarchy",
                stage="eval",
                hint="canonical crops: " + ", ".join(hierarchy.crops),
            )
    for category in field.category or ():
        if category not in hierarchy.categories:
            raise BenchmarkError(
                f"{where}: {category!r} is not a category",
                stage="eval",
                hint="categories: " + ", ".join(hierarchy.categories),
            )
        for crop in crops:
            if hierarchy.crops[crop].category not in (field.category or ()):
                raise BenchmarkError(
                    f"{where}: crop {crop} is not in category {'|'.join(field.category or ())}",
                    stage="eval",
                )
    for variety in field.variety or ():
        owners = [c for c in hierarchy.crops.values() if variety in {v.name for v in c.varieties}]
        if not owners:
            raise BenchmarkError(
                f"{where}: {variety!r} is not a canonical variety name",
                stage="eval",
                hint="use the canonical name, not an alias (reference/crops.md)",
            )
        if crops and not any(owner.name in crops for owner in owners):
            raise BenchmarkError(
                f"{where}: {variety!r} is not a variety of {'|'.join(crops)}", stage="eval"
            )
    if field.category is None and crops:
        categories = tuple(dict.fromkeys(hierarchy.crops[c].category for c in crops))
        field = field.model_copy(update={"category": categories})
    return field


def _apply_defaults(
    field: TruthField, defaults: Mapping[Literal["stage", "season", "health"], str]
) -> TruthField:
    update: dict[str, Any] = {}
    inferred = list(field.inferred)
    for attribute, value in defaults.items():
        if getattr(field, attribute) is None:
            update[attribute] = (value,)
            inferred.append(attribute)
    if not update:
        return field
    update["inferred"] = tuple(inferred)
    return TruthField.model_validate({**field.model_dump(), **update})


#: The shipped prompt files: the development set, then the held-out set written
#: after the resolvers were finished (loaded when present).
SHIPPED_PROMPT_FILES = ("prompts.yaml", "prompts_heldout.yaml")


def load_benchmark(
    path: str | Path | Sequence[str | Path] | None = None,
    *,
    hierarchy: Hierarchy | None = None,
) -> Benchmark:
    """Load and check prompt files into one benchmark.

    ``path`` is one file or several; None loads the shipped files
    (``benchmarks/prompts.yaml`` and, when present, ``prompts_heldout.yaml``).
    Each prompt takes its file's ``split`` ("dev" unless the file says otherwise).
    """
    hierarchy = hierarchy or default_hierarchy()
    if path is None:
        folder = data_path("benchmarks")
        sources = [folder / name for name in SHIPPED_PROMPT_FILES if (folder / name).exists()]
    elif isinstance(path, str | Path):
        sources = [Path(path)]
    else:
        sources = [Path(p) for p in path]
    if not sources:
        raise BenchmarkError("no benchmark file given", stage="eval")
    seen: dict[str, Path] = {}
    prompts: list[BenchmarkPrompt] = []
    for source in sources:
        for item in _load_prompt_file(source, hierarchy):
            if item.id in seen:
                raise BenchmarkError(
                    f"duplicate prompt id {item.id!r} in {source}"
                    + (f" (also in {seen[item.id]})" if seen[item.id] != source else ""),
                    stage="eval",
                )
            seen[item.id] = source
            prompts.append(item)
    return Benchmark(source=", ".join(str(s) for s in sources), prompts=tuple(prompts))


def _load_prompt_file(source: Path, hierarchy: Hierarchy) -> list[BenchmarkPrompt]:
    spec = _parse_file(_BenchmarkFile, source, "benchmark")
    prompts: list[BenchmarkPrompt] = []
    for item in spec.prompts:
        fields = tuple(
            _apply_defaults(_check_names(f, hierarchy, f"{item.id}.fields[{i}]"), spec.defaults)
            for i, f in enumerate(item.fields)
        )
        extra = item.extra_field
        if extra is not None:
            extra = _apply_defaults(
                _check_names(extra, hierarchy, f"{item.id}.extra_field"), spec.defaults
            )
        prompts.append(
            item.model_copy(update={"fields": fields, "extra_field": extra, "split": spec.split})
        )
    return prompts


def load_knowledge_queries(
    path: str | Path | None = None, *, hierarchy: Hierarchy | None = None
) -> tuple[KnowledgeQuery, ...]:
    """Load the knowledge-retrieval queries (the shipped ``knowledge_queries.yaml`` when None)."""
    hierarchy = hierarchy or default_hierarchy()
    source = Path(path) if path is not None else data_path("benchmarks") / "knowledge_queries.yaml"
    spec = _parse_file(_QueryFile, source, "knowledge-query")
    queries: list[KnowledgeQuery] = []
    for index, item in enumerate(spec.queries):
        try:
            text = item["query"]
            key = _KeyFile.model_validate(item["key"])
            if set(item) != {"query", "key"} or not isinstance(text, str) or not text.strip():
                raise ValueError("each query has exactly a non-empty 'query' and a 'key'")
        except (KeyError, ValueError) as exc:  # pydantic's ValidationError is a ValueError
            raise BenchmarkError(
                f"{source}: queries[{index}]: {exc}", stage="eval", hint="see benchmarks/README.md"
            ) from exc
        try:
            asset = hierarchy.key(key.crop, key.variety, key.stage, key.season, key.health)
        except UserInputError as exc:
            raise BenchmarkError(
                f"{source}: queries[{index}] ({text!r}): {exc}", stage="eval"
            ) from exc
        queries.append(KnowledgeQuery(query=text, key=asset))
    return tuple(queries)
