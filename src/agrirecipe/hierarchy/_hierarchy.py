"""The crop asset hierarchy and its catalogue of Unreal object paths.

The catalogue is the product variety x stage x season x health. Every asset has
one object path in Unreal form::

    {root}/{Category}/{Crop}/{Variety}/{Stage}/{Season}/{Health}/SM_{Crop}_{Variety}_{Stage}_{Season}_{Health}.SM_...

with segments in PascalCase without spaces or punctuation. :meth:`Hierarchy.asset_path`
and :meth:`Hierarchy.parse_asset_path` are exact inverses over the catalogue.
"""

from __future__ import annotations

import functools
import re
import unicodedata
from collections.abc import Iterator, Mapping
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import yaml
from pydantic import BaseModel, ConfigDict, Field, ValidationError, field_validator

from agrirecipe._errors import HierarchyError
from agrirecipe._resources import data_path

__all__ = [
    "AssetKey",
    "Category",
    "Crop",
    "Hierarchy",
    "Variety",
    "default_hierarchy",
    "load_hierarchy",
    "pascal_case",
]

_ROOT_PATTERN = re.compile(r"^/[A-Za-z_][A-Za-z0-9_]*(/[A-Za-z_][A-Za-z0-9_]*)*$")


def pascal_case(name: str) -> str:
    """``"Doyenne du Comice"`` -> ``"DoyenneDuComice"``; accents are folded to ASCII."""
    ascii_name = unicodedata.normalize("NFKD", name).encode("ascii", "ignore").decode()
    words = re.split(r"[^A-Za-z0-9]+", ascii_name)
    return "".join(word[:1].upper() + word[1:] for word in words if word)


_CANONICAL_STATES = {
    "stages": ("Vegetative", "Reproductive", "Maturation"),
    "seasons": ("Spring", "Summer", "Fall", "Winter"),
    "health": ("Healthy", "Ill"),
}

# --- file format (validated with pydantic, then turned into plain dataclasses) ---


class _VarietyFile(BaseModel):
    model_config = ConfigDict(extra="forbid", frozen=True)
    name: str = Field(min_length=1)
    aliases: tuple[str, ...] = ()


class _CropFile(BaseModel):
    model_config = ConfigDict(extra="forbid", frozen=True)
    aliases: tuple[str, ...] = ()
    varieties: tuple[_VarietyFile, ...] = Field(min_length=1)


class _CategoryFile(BaseModel):
    model_config = ConfigDict(extra="forbid", frozen=True)
    aliases: tuple[str, ...] = ()
    crops: dict[str, _CropFile] = Field(min_length=1)


class _HierarchyFile(BaseModel):
    model_config = ConfigDict(extra="forbid", frozen=True)
    version: int = 1
    content_root: str = "/Game/Agriculture"
    stages: tuple[str, ...] = Field(min_length=1)
    seasons: tuple[str, ...] = Field(min_length=1)
    health: tuple[str, ...] = Field(min_length=1)
    categories: dict[str, _CategoryFile] = Field(min_length=1)

    @field_validator("stages", "seasons", "health")
    @classmethod
    def _canonical_states(cls, value: tuple[str, ...], info: Any) -> tuple[str, ...]:
        allowed = _CANONICAL_STATES[info.field_name]
        unknown = [name for name in value if name not in allowed]
        if unknown:
            raise ValueError(
                f"{', '.join(unknown)} not accepted; {info.field_name} must be among "
                f"{', '.join(allowed)} (the recipe schema's values)"
            )
        if len(set(value)) != len(value):
            raise ValueError("duplicate names")
        return value

    @field_validator("content_root")
    @classmethod
    def _root_is_unreal_package_path(cls, value: str) -> str:
        value = value.rstrip("/")
        if not _ROOT_PATTERN.match(value):
            raise ValueError(
                f"{value!r} is not an Unreal package path; expected e.g. '/Game/Agriculture'"
            )
        return value


# --- the in-memory hierarchy ---


@dataclass(frozen=True, slots=True)
class Variety:
    """A variety (cultivar) of a crop, with the aliases and trade names people use."""

    name: str
    crop: str
    category: str
    aliases: tuple[str, ...]


@dataclass(frozen=True, slots=True)
class Crop:
    """A crop, its category and its varieties (in file order)."""

    name: str
    category: str
    aliases: tuple[str, ...]
    varieties: tuple[Variety, ...]

    def variety(self, name: str) -> Variety:
        """The variety with this canonical name."""
        for variety in self.varieties:
            if variety.name == name:
                return variety
        raise HierarchyError(
            f"{name!r} is not a variety of {self.name}",
            stage="hierarchy",
            hint=_known_hint(name, [v.name for v in self.varieties], "varieties"),
        )


@dataclass(frozen=True, slots=True)
class Category:
    """A crop category (Fruits, Vegetables, Cereals)."""

    name: str
    aliases: tuple[str, ...]
    crops: tuple[str, ...]


@dataclass(frozen=True, slots=True)
class AssetKey:
    """The six attributes that identify one catalogue asset."""

    category: str
    crop: str
    variety: str
    stage: str
    season: str
    health: str


class Hierarchy:
    """Categories, crops, varieties, stages, seasons and health states, and their catalogue."""

    def __init__(self, spec: _HierarchyFile, *, source: str = "<memory>") -> None:
        self.source = source
        self.content_root = spec.content_root
        self.stages: tuple[str, ...] = spec.stages
        self.seasons: tuple[str, ...] = spec.seasons
        self.health: tuple[str, ...] = spec.health
        categories: dict[str, Category] = {}
        crops: dict[str, Crop] = {}
        for category_name, category in spec.categories.items():
            for crop_name, crop in category.crops.items():
                if crop_name in crops:
                    raise HierarchyError(
                        f"crop {crop_name!r} appears in both {crops[crop_name].category!r} "
                        f"and {category_name!r}",
                        stage="hierarchy",
                        path=f"{source}: categories.{category_name}.crops.{crop_name}",
                        hint="each crop belongs to exactly one category",
                    )
                varieties = tuple(
                    Variety(v.name, crop_name, category_name, v.aliases) for v in crop.varieties
                )
                crops[crop_name] = Crop(crop_name, category_name, crop.aliases, varieties)
            categories[category_name] = Category(
                category_name, category.aliases, tuple(category.crops)
            )
        self.categories: Mapping[str, Category] = categories
        self.crops: Mapping[str, Crop] = crops
        self._check_names_are_unambiguous()

    def _check_names_are_unambiguous(self) -> None:
        """Path segments must be unique where they meet, or parsing would be ambiguous."""
        groups: list[tuple[str, list[str]]] = [
            ("categories", list(self.categories)),
            ("crops", list(self.crops)),
            ("stages", list(self.stages)),
            ("seasons", list(self.seasons)),
            ("health", list(self.health)),
        ]
        groups += [
            (f"varieties of {c.name}", [v.name for v in c.varieties]) for c in self.crops.values()
        ]
        for label, names in groups:
            seen: dict[str, str] = {}
            for name in names:
                segment = pascal_case(name)
                if not segment or not segment[0].isalpha():
                    raise HierarchyError(
                        f"{name!r} in {label} gives the path segment {segment!r}",
                        stage="hierarchy",
                        path=self.source,
                        hint="names must start with a letter",
                    )
                if segment in seen:
                    raise HierarchyError(
                        f"{seen[segment]!r} and {name!r} in {label} both become {segment!r}",
                        stage="hierarchy",
                        path=self.source,
                        hint="names must differ by more than spaces, case or punctuation",
                    )
                seen[segment] = name

    # --- lookups ---

    @property
    def varieties(self) -> tuple[Variety, ...]:
        """Every variety of every crop, in file order."""
        return tuple(v for crop in self.crops.values() for v in crop.varieties)

    def crop(self, name: str) -> Crop:
        """The crop with this canonical name, or a :class:`HierarchyError` naming the closest."""
        try:
            return self.crops[name]
        except KeyError:
            raise HierarchyError(
                f"{name!r} is not a crop of this hierarchy",
                stage="hierarchy",
                hint=_known_hint(name, list(self.crops), "crops"),
            ) from None

    def __len__(self) -> int:
        return len(self.varieties) * len(self.stages) * len(self.seasons) * len(self.health)

    def assets(self) -> Iterator[AssetKey]:
        """Every catalogue asset, in a stable order."""
        for variety in self.varieties:
            for stage in self.stages:
                for season in self.seasons:
                    for health in self.health:
                        yield AssetKey(
                            variety.category, variety.crop, variety.name, stage, season, health
                        )

    def check_key(self, key: AssetKey) -> None:
        """Raise :class:`HierarchyError` unless ``key`` names a catalogue asset."""
        crop = self.crop(key.crop)
        if key.category != crop.category:
            raise HierarchyError(
                f"{key.crop} belongs to {crop.category}, not {key.category}", stage="hierarchy"
            )
        crop.variety(key.variety)
        for label, value, allowed in (
            ("stage", key.stage, self.stages),
            ("season", key.season, self.seasons),
            ("health", key.health, self.health),
        ):
            if value not in allowed:
                raise HierarchyError(
                    f"{value!r} is not a {label}",
                    stage="hierarchy",
                    hint=f"accepted: {', '.join(allowed)}",
                )

    def key(self, crop: str, variety: str, stage: str, season: str, health: str) -> AssetKey:
        """The :class:`AssetKey` of these attributes, checked against the catalogue."""
        key = AssetKey(self.crop(crop).category, crop, variety, stage, season, health)
        self.check_key(key)
        return key

    def asset_path(self, key: AssetKey) -> str:
        """The Unreal object path of a catalogue asset."""
        self.check_key(key)
        return _format_path(self.content_root, key)

    def parse_asset_path(self, path: str) -> AssetKey:
        """The attributes of an object path; exact inverse of :meth:`asset_path`."""
        key = self._paths.get(path)
        if key is None:
            raise HierarchyError(
                f"{path!r} is not an asset of this hierarchy",
                stage="hierarchy",
                hint=f"nearest valid path: {self.nearest_asset_path(path)}",
            )
        return key

    def nearest_asset_path(self, path: str) -> str:
        """The catalogue path closest to ``path`` (for error messages)."""
        from rapidfuzz import fuzz, process

        match = process.extractOne(path, list(self._paths), scorer=fuzz.ratio)
        assert match is not None  # the catalogue is never empty
        return str(match[0])

    def with_content_root(self, content_root: str) -> Hierarchy:
        """The same hierarchy with its assets under another Unreal content folder."""
        spec = self._spec.model_copy(update={"content_root": content_root})
        try:
            spec = _HierarchyFile.model_validate(spec.model_dump())
        except ValidationError as exc:
            raise HierarchyError(_first_error(exc), stage="hierarchy", path="content_root") from exc
        return Hierarchy(spec, source=self.source)

    @functools.cached_property
    def _spec(self) -> _HierarchyFile:
        categories: dict[str, Any] = {}
        for category in self.categories.values():
            crops: dict[str, Any] = {}
            for crop_name in category.crops:
                crop = self.crops[crop_name]
                crops[crop_name] = {
                    "aliases": crop.aliases,
                    "varieties": [{"name": v.name, "aliases": v.aliases} for v in crop.varieties],
                }
            categories[category.name] = {"aliases": category.aliases, "crops": crops}
        return _HierarchyFile.model_validate(
            {
                "content_root": self.content_root,
                "stages": self.stages,
                "seasons": self.seasons,
                "health": self.health,
                "categories": categories,
            }
        )

    @functools.cached_property
    def _paths(self) -> dict[str, AssetKey]:
        return {_format_path(self.content_root, key): key for key in self.assets()}

    def digest(self) -> str:
        """A content hash of the hierarchy (used to key caches such as the embedding index)."""
        import hashlib

        text = self._spec.model_dump_json()
        return hashlib.sha256(text.encode()).hexdigest()[:16]

    def __repr__(self) -> str:
        return (
            f"Hierarchy({self.source!r}, {len(self.categories)} categories, "
            f"{len(self.crops)} crops, {len(self.varieties)} varieties, {len(self)} assets)"
        )


def _known_hint(name: str, known: list[str], label: str) -> str:
    """``"nearest: Apple; known crops: Apple, Pear, ..."`` for an error's hint."""
    from rapidfuzz import fuzz, process, utils

    matches = process.extract(
        name, known, scorer=fuzz.WRatio, processor=utils.default_process, limit=3, score_cutoff=70
    )
    listing = f"known {label}: " + ", ".join(known)
    if not matches:
        return listing
    return "nearest: " + ", ".join(str(match[0]) for match in matches) + "; " + listing


def _format_path(root: str, key: AssetKey) -> str:
    segments = [
        pascal_case(name)
        for name in (key.category, key.crop, key.variety, key.stage, key.season, key.health)
    ]
    object_name = "SM_" + "_".join(segments[1:])
    return f"{root}/{'/'.join(segments)}/{object_name}.{object_name}"


def _first_error(exc: ValidationError) -> str:
    error = exc.errors()[0]
    location = ".".join(str(part) for part in error["loc"])
    return f"{location}: {error['msg']}"


def load_hierarchy(path: str | Path | None = None, *, content_root: str | None = None) -> Hierarchy:
    """Load a hierarchy file (the shipped ``hierarchy.yaml`` when ``path`` is None).

    A malformed file raises :class:`HierarchyError` naming the offending entry.
    """
    if path is None:
        hierarchy = default_hierarchy()
    else:
        source = Path(path)
        try:
            raw = yaml.safe_load(source.read_text(encoding="utf-8"))
        except FileNotFoundError:
            raise HierarchyError(
                f"hierarchy file {str(source)!r} does not exist", stage="hierarchy"
            ) from None
        except (OSError, UnicodeDecodeError) as exc:
            raise HierarchyError(
                f"hierarchy file {str(source)!r} cannot be read: {exc}", stage="hierarchy"
            ) from exc
        except yaml.YAMLError as exc:
            raise HierarchyError(
                f"hierarchy file {str(source)!r} is not valid YAML: {exc}", stage="hierarchy"
            ) from exc
        hierarchy = _from_mapping(raw, source=str(source))
    if content_root is not None:
        hierarchy = hierarchy.with_content_root(content_root)
    return hierarchy


def _from_mapping(raw: object, *, source: str) -> Hierarchy:
    if not isinstance(raw, dict):
        raise HierarchyError(
            f"hierarchy file {source!r} must hold a mapping with 'stages', 'seasons', "
            "'health' and 'categories'",
            stage="hierarchy",
        )
    try:
        spec = _HierarchyFile.model_validate(raw)
    except ValidationError as exc:
        problems = "; ".join(
            f"{'.'.join(str(p) for p in e['loc'])}: {e['msg']}" for e in exc.errors()
        )
        raise HierarchyError(
            f"hierarchy file {source!r} is malformed: {problems}",
            stage="hierarchy",
            path=source,
            hint="see the shipped hierarchy.yaml for the format",
        ) from exc
    return Hierarchy(spec, source=source)


@functools.lru_cache(maxsize=1)
def default_hierarchy() -> Hierarchy:
    """The shipped hierarchy (``hierarchy.yaml``), loaded once."""
    source = data_path("hierarchy.yaml")
    raw = yaml.safe_load(source.read_text(encoding="utf-8"))
    return _from_mapping(raw, source=str(source))
