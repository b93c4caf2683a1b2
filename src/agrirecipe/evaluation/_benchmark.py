"""The benchmark files: prompts with ground truth, and knowledge-retrieval queries.

The prompt files (``benchmarks/prompts.yaml``, ``prompts_heldout.yaml`` and
``heldout/*.yaml``) and ``benchmarks/knowledge_queries.yaml`` (format in
``benchmarks/README.md``) are validated here with pydantic and then against a
hierarchy: every name in the truth must be a canonical name of it, a variety
must belong to its crop, and a category must contain its crops. A truth field
may also state the field's geometry (rows, spacings, density, direction). A
malformed file raises :class:`BenchmarkError` naming the offending entry.
"""

from __future__ import annotations

from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import Annotated, Any, Literal, TypeVar, get_args

import yaml
from pydantic import BaseModel, ConfigDict, Field, ValidationError, field_validator, model_validator

from agrirecipe._errors import UserInputError
from agrirecipe._resources import data_path
from agrirecipe.hierarchy import AssetKey, Hierarchy, default_hierarchy
from agrirecipe.recipe import RelationKind

__all__ = [
    "ATTRIBUTES",
    "GENRE_TAGS",
    "GEOMETRY_KEYS",
    "PROMPT_TYPES",
    "SHIPPED_PROMPT_FILES",
    "TAGS",
    "Benchmark",
    "BenchmarkError",
    "BenchmarkPrompt",
    "FieldCount",
    "GeometryKey",
    "KnowledgeQuery",
    "PromptType",
    "Split",
    "Tag",
    "TruthField",
    "TruthRelation",
    "load_benchmark",
    "load_knowledge_queries",
    "round_robin",
    "shipped_prompt_files",
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
    "photo",
    "engineering",
    "casual",
    "farm",
    "geometry",
    "scenery",
    "cue",
]
TAGS: tuple[Tag, ...] = get_args(Tag)
#: The genre tags (one per prompt of the genre sets): how the request is written.
GENRE_TAGS: tuple[Tag, ...] = ("photo", "engineering", "casual", "farm")
#: "dev": prompts the resolvers were developed against; "heldout": written after.
Split = Literal["dev", "heldout"]
Attribute = Literal["category", "crop", "variety", "stage", "season", "health"]
#: The attributes a truth field can state, in display order.
ATTRIBUTES: tuple[Attribute, ...] = ("category", "crop", "variety", "stage", "season", "health")
GeometryKey = Literal[
    "rows",
    "beds",
    "rows_per_bed",
    "row_length_m",
    "row_spacing_m",
    "bed_width_m",
    "in_row_spacing_m",
    "plants_per_ha",
    "plant_count",
    "headland_m",
    "row_bearing_deg",
]
#: The stated-geometry keys a truth field can give, in display order (each checked when set).
GEOMETRY_KEYS: tuple[GeometryKey, ...] = get_args(GeometryKey)
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


def _no_bool(value: object) -> object:
    """YAML ``yes``/``true`` is not a number of rows or metres."""
    if isinstance(value, bool):
        raise ValueError("must be a number, not a boolean")
    return value


#: A count of the stated geometry: a positive integer (YAML ``10``, not ``10.5``).
_Count = Annotated[int, Field(gt=0, strict=True)]
#: A length, spacing or density of the stated geometry: a positive finite number.
_Positive = Annotated[float, Field(gt=0, allow_inf_nan=False)]


class TruthField(_Strict):
    """What one field of the recipe must be; an omitted attribute is left open by the prompt.

    Each attribute holds the accepted canonical names (one, or several when the
    prompt allows any of them, e.g. an "orchard" is any tree fruit). The
    geometry keys (:data:`GEOMETRY_KEYS`, meanings in ``benchmarks/README.md``)
    are checked only when set: counts exactly, lengths and densities within
    1 %, the row bearing within a degree.
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
    rows: _Count | None = Field(
        default=None, description="Plant rows in the field, each row of a bed."
    )
    beds: _Count | None = Field(default=None, description="Beds or ridges.")
    rows_per_bed: _Count | None = Field(
        default=None, description="Plant rows on each bed or ridge."
    )
    row_length_m: _Positive | None = Field(default=None, description="Length of the rows, metres.")
    row_spacing_m: _Positive | None = Field(
        default=None, description="Distance between neighbouring rows (single rows), metres."
    )
    bed_width_m: _Positive | None = Field(
        default=None, description="Centre-to-centre distance of beds or ridges, metres."
    )
    in_row_spacing_m: _Positive | None = Field(
        default=None, description="Distance between plants along a row, metres."
    )
    plants_per_ha: _Positive | None = Field(
        default=None, description="Planting density, plants/ha."
    )
    plant_count: _Count | None = Field(default=None, description="Plants (or trees) in the field.")
    headland_m: float | None = Field(
        default=None,
        ge=0,
        allow_inf_nan=False,
        description="Width of the unplanted headland around the rows, metres.",
    )
    row_bearing_deg: float | None = Field(
        default=None,
        ge=0,
        lt=180,
        allow_inf_nan=False,
        description="Direction of the rows, degrees clockwise from north in [0, 180).",
    )
    inferred: tuple[Attribute, ...] = Field(
        default=(), description="Attributes filled from the file's defaults, not the prompt."
    )

    _normalise = field_validator(
        "category", "crop", "variety", "stage", "season", "health", mode="before"
    )(_any_of)
    _numbers = field_validator(*GEOMETRY_KEYS, "area_m2", mode="before")(_no_bool)

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

    @model_validator(mode="after")
    def _rows_add_up(self) -> TruthField:
        rows, beds, per_bed = self.rows, self.beds, self.rows_per_bed
        if rows is not None and beds is not None and per_bed is not None:
            if rows != beds * per_bed:
                raise ValueError(
                    f"rows {rows} is not beds {beds} x rows_per_bed {per_bed} ({beds * per_bed})"
                )
        elif rows is not None and per_bed is not None and rows % per_bed:
            raise ValueError(f"rows {rows} is not a whole number of beds of {per_bed} rows")
        elif rows is not None and beds is not None and rows % beds:
            raise ValueError(f"rows {rows} do not divide evenly over {beds} beds")
        return self

    def geometry(self) -> dict[GeometryKey, float]:
        """The stated geometry keys and their values (empty when the prompt states none)."""
        values: dict[GeometryKey, float] = {}
        for key in GEOMETRY_KEYS:
            value = getattr(self, key)
            if value is not None:
                values[key] = value
        return values

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
        parts.extend(_describe_geometry(self))
        return ", ".join(parts)


def _describe_geometry(field: TruthField) -> list[str]:
    """The stated geometry in words, e.g. ``["10 rows", "rows 80 m", "0.76 m apart"]``."""
    parts: list[str] = []
    if field.rows is not None:
        parts.append(f"{field.rows} row{'s' if field.rows != 1 else ''}")
    if field.beds is not None:
        parts.append(f"{field.beds} bed{'s' if field.beds != 1 else ''}")
    if field.rows_per_bed is not None:
        parts.append(f"{field.rows_per_bed} per bed")
    if field.row_length_m is not None:
        parts.append(f"rows {field.row_length_m:g} m")
    if field.row_spacing_m is not None:
        parts.append(f"{field.row_spacing_m:g} m apart")
    if field.bed_width_m is not None:
        parts.append(f"beds on {field.bed_width_m:g} m")
    if field.in_row_spacing_m is not None:
        parts.append(f"a plant every {field.in_row_spacing_m:g} m")
    if field.plants_per_ha is not None:
        parts.append(f"{field.plants_per_ha:g} plants/ha")
    if field.plant_count is not None:
        parts.append(f"{field.plant_count} plants")
    if field.headland_m is not None:
        parts.append(f"{field.headland_m:g} m headland")
    if field.row_bearing_deg is not None:
        parts.append(f"rows at {field.row_bearing_deg:g} deg")
    return parts


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


#: The shipped prompt files, relative to ``benchmarks/``, in loading order: the
#: development set, the held-out set written after the resolvers were finished,
#: then every blind genre set ``heldout/<set>.yaml`` (a glob, expanded sorted by
#: file name). Each entry is loaded when present; an empty glob adds nothing.
SHIPPED_PROMPT_FILES: tuple[str, ...] = ("prompts.yaml", "prompts_heldout.yaml", "heldout/*.yaml")


def shipped_prompt_files(folder: str | Path | None = None) -> tuple[Path, ...]:
    """The shipped prompt files that exist in ``folder`` (default: the shipped ``benchmarks/``).

    :data:`SHIPPED_PROMPT_FILES` in order; a glob entry expands to its matches
    sorted by name. Only the names are looked at here, not the contents.
    """
    base = Path(folder) if folder is not None else data_path("benchmarks")
    found: list[Path] = []
    for pattern in SHIPPED_PROMPT_FILES:
        if any(char in pattern for char in "*?["):
            found.extend(
                sorted((p for p in base.glob(pattern) if p.is_file()), key=lambda p: p.name)
            )
        elif (base / pattern).is_file():
            found.append(base / pattern)
    return tuple(found)


def load_benchmark(
    path: str | Path | Sequence[str | Path] | None = None,
    *,
    hierarchy: Hierarchy | None = None,
) -> Benchmark:
    """Load and check prompt files into one benchmark.

    ``path`` is one file or several; None loads the shipped files
    (:func:`shipped_prompt_files`: ``benchmarks/prompts.yaml`` and, when
    present, ``prompts_heldout.yaml`` and every ``heldout/*.yaml``). Each prompt
    takes its file's ``split`` ("dev" unless the file says otherwise); prompt
    ids must be unique across all the files.
    """
    hierarchy = hierarchy or default_hierarchy()
    if path is None:
        sources = list(shipped_prompt_files())
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
