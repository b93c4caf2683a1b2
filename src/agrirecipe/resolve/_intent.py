"""The intermediate form between a prompt and a recipe: what the user asked for.

Every resolver strategy ("rules", "embedding", "llm", "hybrid") turns a prompt
into the same :class:`SceneIntent`; the shared pipeline in
:mod:`agrirecipe.resolve._pipeline` then validates it, chooses crops for
generic requests (seeded), fills unstated attributes from the knowledge base,
lays the fields out and builds the :class:`~agrirecipe.recipe.SceneRecipe`.

The intent says only what the prompt said, in canonical hierarchy names:

- a :class:`FieldIntent` per field (a request for "two carrot fields" is two
  ``FieldIntent`` objects), every attribute ``None`` unless the prompt stated
  it (directly or "for all": see :attr:`SceneIntent.season`);
- a generic field ("some vegetable", "an orchard") has ``crop=None`` and
  ``generic=True``, optionally narrowed by ``category`` and ``crop_options``;
  fields sharing a ``distinct_group`` must get pairwise different crops;
- :class:`RelationIntent` links fields by their index in
  :attr:`SceneIntent.fields`;
- :class:`TraceStep` records what the strategy considered (candidates and
  scores) for ``explain=True``.

A resolver raises :class:`~agrirecipe.PromptError` (empty, non-agricultural or
contradictory prompt) or :class:`~agrirecipe.UnknownCropError` (a crop not in
the hierarchy, listing the nearest known ones) rather than guessing.
"""

from __future__ import annotations

from abc import ABC, abstractmethod
from dataclasses import dataclass
from typing import TYPE_CHECKING, ClassVar, Literal

from pydantic import BaseModel, ConfigDict, Field, model_validator

from agrirecipe.recipe import DEFAULT_MAX_PLANTS, HealthState, RelationKind, Season, Stage

if TYPE_CHECKING:
    from agrirecipe.hierarchy import Hierarchy
    from agrirecipe.knowledge import KnowledgeBase

__all__ = [
    "Candidate",
    "FieldIntent",
    "Hemisphere",
    "RelationIntent",
    "ResolveContext",
    "Resolver",
    "RowSpec",
    "SceneIntent",
    "SizeIntent",
    "TraceStep",
]

Hemisphere = Literal["north", "south"]


class _Frozen(BaseModel):
    model_config = ConfigDict(frozen=True, extra="forbid", allow_inf_nan=False)


class SizeIntent(_Frozen):
    """A stated field size: both sides ("50 by 100 m"), or an area ("2 ha", "1 acre").

    ``width_m`` runs east-west (local X), ``length_m`` north-south (local Y,
    the row direction). An area alone keeps the crop's default aspect ratio.
    """

    width_m: float | None = Field(default=None, gt=0.0)
    length_m: float | None = Field(default=None, gt=0.0)
    area_m2: float | None = Field(default=None, gt=0.0)
    text: str = Field(default="", description="The words the size was read from.")

    @model_validator(mode="after")
    def _something_stated(self) -> SizeIntent:
        sides = (self.width_m is None, self.length_m is None)
        if sides[0] != sides[1]:
            raise ValueError("width_m and length_m are stated together or not at all")
        if self.width_m is None and self.area_m2 is None:
            raise ValueError("a size needs width_m and length_m, or area_m2")
        return self


class RowSpec(_Frozen):
    """Field geometry the prompt stated in rows ("10 rows, 80 m long, 76 cm apart").

    Every value is ``None`` unless stated; lengths in metres, ``row_bearing_deg``
    clockwise from north in [0, 180) (0: rows run north-south, 90: east-west).
    The pipeline turns it into the field's spacing, size and rotation, checked
    against the crop's sourced ranges.
    """

    rows: int | None = Field(default=None, gt=0)
    beds: int | None = Field(default=None, gt=0)
    rows_per_bed: int | None = Field(default=None, gt=0)
    row_length_m: float | None = Field(default=None, gt=0.0)
    row_spacing_m: float | None = Field(default=None, gt=0.0)
    bed_width_m: float | None = Field(default=None, gt=0.0)
    #: The open alley between single rows, or between the pairs of double rows.
    alley_m: float | None = Field(default=None, gt=0.0)
    in_row_spacing_m: float | None = Field(default=None, gt=0.0)
    plants_per_ha: float | None = Field(default=None, gt=0.0)
    plant_count: int | None = Field(default=None, gt=0)
    plants_per_row: int | None = Field(default=None, gt=0)
    headland_m: float | None = Field(default=None, ge=0.0)
    row_bearing_deg: float | None = Field(default=None, ge=0.0, lt=180.0)
    text: str = Field(default="", description="The words the geometry was read from.")

    def stated(self) -> dict[str, float]:
        """The stated values by name (``text`` left out)."""
        return {k: v for k, v in self.model_dump(exclude={"text"}).items() if v is not None}


class FieldIntent(_Frozen):
    """One requested field; every attribute is ``None`` unless the prompt stated it.

    Names are canonical hierarchy names (``crop="Tomato"``,
    ``variety="Cherry"``), never the words the user typed; those go in
    ``text`` and ``mention``.
    """

    text: str = Field(description="The part of the prompt (subquery) this field came from.")
    mention: str | None = Field(
        default=None, description="The words that named the crop or variety, as typed."
    )
    noun: str | None = Field(
        default=None,
        description="The kind of plot the user named ('orchard', 'field', 'vineyard'); "
        "used in labels and ids.",
    )
    category: str | None = None
    crop: str | None = None
    variety: str | None = None
    stage: Stage | None = None
    season: Season | None = None
    health: HealthState | None = None
    size: SizeIntent | None = None
    rows: RowSpec | None = Field(
        default=None, description="Rows, spacings, density and direction the prompt stated."
    )
    generic: bool = Field(
        default=False, description="No crop named: the pipeline chooses one (seeded)."
    )
    crop_options: tuple[str, ...] = Field(
        default=(),
        description="For a generic field, the crops it may become ('an orchard' -> tree "
        "fruits); empty means any crop of ``category`` (or any crop at all).",
    )
    distinct_group: int | None = Field(
        default=None,
        description="Fields with the same group number must have pairwise different crops "
        "('three different vegetables').",
    )

    @model_validator(mode="after")
    def _consistent(self) -> FieldIntent:
        if self.variety is not None and self.crop is None:
            raise ValueError("a variety needs its crop")
        if self.generic and self.crop is not None:
            raise ValueError("a generic field names no crop")
        if not self.generic and self.crop is None:
            raise ValueError("a field names a crop or is generic")
        return self


class RelationIntent(_Frozen):
    """A spatial relation between fields, by index into :attr:`SceneIntent.fields`.

    ``between`` has two objects ("the wheat between the apples and the pears");
    every other kind has one.
    """

    kind: RelationKind
    subject: int = Field(ge=0)
    objects: tuple[int, ...] = Field(min_length=1, max_length=2)
    text: str = ""

    @model_validator(mode="after")
    def _arity(self) -> RelationIntent:
        expected = 2 if self.kind == "between" else 1
        if len(self.objects) != expected:
            raise ValueError(f"{self.kind!r} takes {expected} object field(s)")
        if self.subject in self.objects:
            raise ValueError(f"a field cannot be {self.kind} itself")
        return self


class Candidate(_Frozen):
    """A value a strategy considered for a mention, with its score (0-100 or cosine x 100)."""

    value: str
    score: float
    source: str = Field(description="What produced it: 'lexicon', 'fuzzy', 'embedding', 'llm'.")


class TraceStep(_Frozen):
    """One thing a stage did, for ``explain=True``."""

    stage: str = Field(description="'decompose', 'normalise', 'retrieve', 'validate', 'enrich'...")
    subject: str = Field(description="What it was about: a subquery, a mention, a field.")
    detail: str = Field(description="What was decided, in words.")
    candidates: tuple[Candidate, ...] = ()


class SceneIntent(_Frozen):
    """Everything a prompt asked for, before knowledge fills the gaps."""

    prompt: str
    fields: tuple[FieldIntent, ...] = Field(min_length=1, max_length=64)
    relations: tuple[RelationIntent, ...] = ()
    season: Season | None = Field(
        default=None, description="Scene-wide season ('..., all in autumn') for fields without one."
    )
    hemisphere: Hemisphere | None = Field(
        default=None, description="Stated or implied ('in Chile') hemisphere."
    )
    latitude_deg: float | None = Field(default=None, ge=-90.0, le=90.0)
    place: str | None = Field(default=None, description="A place named in the prompt.")
    warnings: tuple[str, ...] = ()
    trace: tuple[TraceStep, ...] = ()
    resolver: str = Field(default="", description="The strategy that produced this intent.")

    @model_validator(mode="after")
    def _relations_point_at_fields(self) -> SceneIntent:
        for relation in self.relations:
            for index in (relation.subject, *relation.objects):
                if index >= len(self.fields):
                    raise ValueError(
                        f"relation {relation.kind} refers to field {index}, "
                        f"but there are {len(self.fields)}"
                    )
        return self


@dataclass(frozen=True, slots=True)
class ResolveContext:
    """What a resolver may use: the hierarchy, the knowledge base, and the request's settings."""

    hierarchy: Hierarchy
    knowledge: KnowledgeBase
    seed: int = 0
    latitude_deg: float | None = None
    explain: bool = False
    #: The most planting positions the recipe may hold (SceneRecipe's ``max_plants``).
    max_plants: int = DEFAULT_MAX_PLANTS


class Resolver(ABC):
    """A strategy that turns a prompt into a :class:`SceneIntent`.

    Implementations load heavy models lazily on the first call and keep them
    for later calls; they must be deterministic for a given prompt and
    context. Raise :class:`~agrirecipe.PromptError` /
    :class:`~agrirecipe.UnknownCropError` for prompts that cannot be honoured.
    """

    #: The strategy's registry name ("rules", "embedding", "llm", "hybrid").
    name: ClassVar[str]

    @abstractmethod
    def resolve_intent(self, prompt: str, context: ResolveContext) -> SceneIntent:
        """What ``prompt`` asks for, in canonical hierarchy names."""

    def __repr__(self) -> str:
        return f"{type(self).__name__}(name={self.name!r})"
