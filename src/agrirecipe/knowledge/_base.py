"""The crop knowledge base: exact structured lookup and domain defaults.

One ``crops/<crop>.yaml`` per crop of the hierarchy. :meth:`KnowledgeBase.lookup`
answers any catalogue asset exactly with its :class:`KnowledgeEntry`: the
agronomic parameters a field of that asset is laid out and drawn with (stage,
season and health modifiers applied), whether the combination is plausible,
and the sources of every number.
"""

from __future__ import annotations

import copy
import functools
import hashlib
from collections.abc import Iterator, Mapping
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import yaml
from pydantic import ValidationError

from agrirecipe._errors import KnowledgeBaseError
from agrirecipe._resources import data_path
from agrirecipe.hierarchy import AssetKey, Hierarchy, default_hierarchy, pascal_case
from agrirecipe.knowledge._files import CropFile
from agrirecipe.recipe import Agronomy, FoliageState, Placement, Season, Stage

__all__ = [
    "KnowledgeBase",
    "KnowledgeEntry",
    "default_knowledge_base",
    "load_knowledge_base",
]

_BARK_RGB = (0.36, 0.27, 0.20)
_CHLOROTIC_RGB = (0.80, 0.74, 0.24)
_NECROTIC_RGB = (0.45, 0.31, 0.15)
#: How far an ill plant's foliage moves toward the chlorotic/necrotic colour (est.).
_ILL_BLEND = 0.55
#: Height of an ill plant relative to a healthy one (est.).
_ILL_HEIGHT = 0.85
_STAGE_WORDS = {
    "Vegetative": "in vegetative growth",
    "Reproductive": "flowering or setting fruit",
    "Maturation": "mature and ready for harvest",
}


@dataclass(frozen=True, slots=True)
class KnowledgeEntry:
    """What the knowledge base knows about one catalogue asset."""

    key: AssetKey
    agronomy: Agronomy
    implausibility: str | None

    @property
    def plausible(self) -> bool:
        """False when the stage is unusual for the crop in that season."""
        return self.implausibility is None

    @property
    def descriptor(self) -> str:
        """The text embedded for retrieval (the seed paper's asset descriptor)."""
        key, agronomy = self.key, self.agronomy
        return (
            f"{key.crop} {key.variety} ({key.category}), {key.stage} stage in {key.season}, "
            f"{key.health}. {agronomy.growth_form.replace('_', ' ')} planted in "
            f"{agronomy.planting_pattern.replace('_', ' ')}, rows {agronomy.row_spacing_m:g} m "
            f"apart, {agronomy.in_row_spacing_m:g} m in the row, {agronomy.plant_height_m:.2g} m "
            f"tall, foliage {agronomy.foliage}"
            + (f", {agronomy.disease}" if agronomy.disease else "")
            + "."
        )


def _deep_merge(base: dict[str, Any], override: Mapping[str, Any]) -> dict[str, Any]:
    merged = copy.deepcopy(base)
    for name, value in override.items():
        if (
            isinstance(value, Mapping)
            and isinstance(merged.get(name), dict)
            and "value" not in value
        ):
            merged[name] = _deep_merge(merged[name], value)
        else:
            merged[name] = copy.deepcopy(value)
    return merged


def _blend(
    a: tuple[float, float, float], b: tuple[float, float, float], t: float
) -> tuple[float, float, float]:
    return (
        round(a[0] + (b[0] - a[0]) * t, 4),
        round(a[1] + (b[1] - a[1]) * t, 4),
        round(a[2] + (b[2] - a[2]) * t, 4),
    )


class KnowledgeBase:
    """Crop knowledge for every crop of a hierarchy."""

    def __init__(
        self, raw_files: Mapping[str, dict[str, Any]], hierarchy: Hierarchy, *, source: str
    ) -> None:
        self.hierarchy = hierarchy
        self.source = source
        self._raw = dict(raw_files)
        missing = [crop for crop in hierarchy.crops if crop not in self._raw]
        if missing:
            raise KnowledgeBaseError(
                f"no knowledge file for crop(s) {', '.join(missing)} in {source}",
                stage="knowledge",
                hint="add crops/<crop>.yaml for every crop of the hierarchy "
                "(copy the shipped crops/apple.yaml)",
            )
        self._files: dict[tuple[str, str], CropFile] = {}
        for crop in hierarchy.crops.values():
            raw = self._raw[crop.name]
            overrides = raw.get("varieties") or {}
            if not isinstance(overrides, dict):
                raise KnowledgeBaseError(
                    f"{crop.name}: 'varieties' must map variety names to overrides",
                    stage="knowledge",
                    path=f"{source}/{crop.name.lower()}.yaml",
                )
            known = {v.name for v in crop.varieties}
            unknown = sorted(set(overrides) - known)
            if unknown:
                raise KnowledgeBaseError(
                    f"{crop.name}: overrides for unknown varieties {', '.join(unknown)}",
                    stage="knowledge",
                    path=f"{source}/{crop.name.lower()}.yaml",
                    hint="varieties of the hierarchy: " + ", ".join(sorted(known)),
                )
            base = {name: value for name, value in raw.items() if name != "varieties"}
            for variety in crop.varieties:
                merged = _deep_merge(base, overrides.get(variety.name) or {})
                try:
                    parsed = CropFile.model_validate(merged)
                except ValidationError as exc:
                    error = exc.errors()[0]
                    location = ".".join(str(p) for p in error["loc"])
                    raise KnowledgeBaseError(
                        f"{crop.name} ({variety.name}): {location}: {error['msg']}",
                        stage="knowledge",
                        path=f"{source}/{crop.name.lower()}.yaml",
                        hint=f"{len(exc.errors())} problem(s); see crops/apple.yaml for the format",
                    ) from exc
                if parsed.crop != crop.name:
                    raise KnowledgeBaseError(
                        f"file for {crop.name} says crop: {parsed.crop}",
                        stage="knowledge",
                        path=f"{source}/{crop.name.lower()}.yaml",
                    )
                if parsed.default_variety.value not in known:
                    raise KnowledgeBaseError(
                        f"{crop.name}: default_variety {parsed.default_variety.value!r} is not a "
                        "variety of the hierarchy",
                        stage="knowledge",
                        hint="varieties: " + ", ".join(sorted(known)),
                    )
                self._files[(crop.name, variety.name)] = parsed

    # --- raw access ---

    def crop_file(self, crop: str, variety: str | None = None) -> CropFile:
        """The crop's knowledge with ``variety``'s overrides (default variety when None)."""
        if variety is None:
            variety = self.default_variety(crop)
        try:
            return self._files[(crop, variety)]
        except KeyError:
            known = self.hierarchy.crop(crop)
            known.variety(variety)  # raises HierarchyError naming the valid varieties
            raise  # pragma: no cover - every hierarchy variety has an entry

    # --- domain defaults the resolver needs ---

    def default_variety(self, crop: str) -> str:
        """The variety assumed when a prompt names only the crop."""
        first = self.hierarchy.crop(crop).varieties[0].name
        return self._files[(crop, first)].default_variety.value

    def plausible_stages(
        self, crop: str, season: str, variety: str | None = None
    ) -> tuple[Stage, ...]:
        """Stages the crop is plausibly in during ``season`` (typical first); may be empty."""
        entry = self.crop_file(crop, variety)
        return entry.seasons[_season(season)].stages

    def typical_stage(self, crop: str, season: str, variety: str | None = None) -> Stage:
        """The stage assumed for the crop in ``season`` when the prompt does not say."""
        stages = self.plausible_stages(crop, season, variety)
        if stages:
            return stages[0]
        # Not grown in that season: fall back to the stage it has in most seasons.
        entry = self.crop_file(crop, variety)
        counts: dict[Stage, int] = {}
        for info in entry.seasons.values():
            for stage in info.stages[:1]:
                counts[stage] = counts.get(stage, 0) + 1
        return max(counts, key=lambda s: counts[s]) if counts else "Vegetative"

    def typical_season(self, crop: str, stage: str, variety: str | None = None) -> Season:
        """The season a crop is most typically in ``stage`` (for prompts that give only a stage)."""
        entry = self.crop_file(crop, variety)
        for position in range(3):
            for season, info in entry.seasons.items():
                if len(info.stages) > position and info.stages[position] == stage:
                    return season
        return "Summer"

    def implausibility(
        self, crop: str, variety: str, stage: str, season: str, health: str = "Healthy"
    ) -> str | None:
        """Why this combination is implausible, or None when it is plausible."""
        entry = self.crop_file(crop, variety)
        info = entry.seasons[_season(season)]
        note = f" ({info.note})" if info.note else ""
        if not info.stages:
            return f"{crop} is not normally grown in the field in {season}{note}"
        if stage not in info.stages:
            return (
                f"{crop} ({variety}) is not normally {_STAGE_WORDS.get(stage, stage)} in "
                f"{season}{note}; plausible: {', '.join(info.stages)}"
            )
        return None

    def default_field_size_m(self, crop: str, variety: str | None = None) -> tuple[float, float]:
        """Width and length of a field of this crop when the prompt gives no size."""
        return self.crop_file(crop, variety).field.default_size_m.value

    def default_headland_m(self, crop: str, variety: str | None = None) -> float:
        """Headland (unplanted border) width for this crop."""
        return self.crop_file(crop, variety).field.headland_m.value

    def default_placement(self, crop: str, variety: str | None = None) -> Placement:
        """Seeded placement variation typical of a commercial field of this crop."""
        field = self.crop_file(crop, variety).field
        return Placement(
            jitter_m=field.jitter_m.value,
            missing_rate=field.missing_rate.value,
            size_variation=field.size_variation.value,
            yaw_variation_deg=(
                field.yaw_variation_deg.value if field.yaw_variation_deg is not None else 180.0
            ),
        )

    # --- the structured lookup ---

    def lookup(self, key: AssetKey) -> KnowledgeEntry:
        """The exact entry for a catalogue asset."""
        self.hierarchy.check_key(key)
        return self._entry(key)

    @functools.lru_cache(maxsize=4096)  # noqa: B019 - bounded; lives with the knowledge base
    def _entry(self, key: AssetKey) -> KnowledgeEntry:
        return KnowledgeEntry(
            key=key,
            agronomy=self._agronomy(key),
            implausibility=self.implausibility(
                key.crop, key.variety, key.stage, key.season, key.health
            ),
        )

    def agronomy(self, key: AssetKey) -> Agronomy:
        """The agronomic parameters of an asset (stage, season and health applied)."""
        return self.lookup(key).agronomy

    def entries(self) -> Iterator[KnowledgeEntry]:
        """An entry for every catalogue asset, in catalogue order."""
        for key in self.hierarchy.assets():
            yield self._entry(key)

    def _agronomy(self, key: AssetKey) -> Agronomy:
        entry = self.crop_file(key.crop, key.variety)
        colours = entry.colours
        foliage: FoliageState
        foliage_rgb = colours.foliage_rgb.value
        deciduous = entry.leaf_habit == "deciduous"
        if deciduous and key.season == "Winter":
            foliage, foliage_rgb = "leafless", _BARK_RGB
        elif (
            deciduous
            and key.season == "Fall"
            and key.stage != "Reproductive"
            and colours.autumn_rgb
        ):
            foliage, foliage_rgb = "autumn", colours.autumn_rgb.value
        elif key.stage == "Reproductive" and colours.flower_rgb and _in_flower(entry, key.season):
            foliage = "flowering"
        elif key.stage == "Reproductive" and colours.fruit_rgb:
            # Reproductive outside the flowering season: fruit is setting or growing
            # (an apple orchard in July).
            foliage = "fruiting"
        elif key.stage == "Maturation" and colours.mature_rgb:
            foliage, foliage_rgb = "senescent", colours.mature_rgb.value
        elif key.stage == "Maturation" and colours.fruit_rgb:
            foliage = "fruiting"
        elif key.stage == "Vegetative" and deciduous and key.season == "Spring":
            foliage = "budding"
        else:
            foliage = "leafy"
        height = entry.max_height_m.value * entry.stage_height_fraction[_stage(key.stage)].value
        disease = sign = None
        if key.health == "Ill":
            tint = _CHLOROTIC_RGB if entry.disease.ill_tint == "chlorotic" else _NECROTIC_RGB
            if foliage != "leafless":
                foliage_rgb = _blend(foliage_rgb, tint, _ILL_BLEND)
            height *= _ILL_HEIGHT
            disease, sign = entry.disease.name, entry.disease.sign
        planting = entry.planting
        sources = sorted(
            {
                part.strip()
                for value in (
                    planting.row_spacing_m,
                    planting.in_row_spacing_m,
                    entry.max_height_m,
                    entry.canopy_width_m,
                    entry.kc_mid,
                    entry.stage_height_fraction[_stage(key.stage)],
                )
                for part in value.source.split(",")
            }
            | ({entry.disease.source} if key.health == "Ill" else set())
        )
        return Agronomy(
            planting_pattern=planting.pattern,
            growth_form=entry.growth_form,
            row_spacing_m=planting.row_spacing_m.value,
            rows_per_bed=planting.rows_per_bed,
            bed_row_spacing_m=planting.bed_row_spacing_m.value,
            in_row_spacing_m=planting.in_row_spacing_m.value,
            plant_height_m=round(height, 4),
            max_height_m=entry.max_height_m.value,
            canopy_width_m=entry.canopy_width_m.value,
            kc_mid=entry.kc_mid.value,
            leaf_habit=entry.leaf_habit,
            foliage=foliage,
            foliage_rgb=foliage_rgb,
            fruit_rgb=colours.fruit_rgb.value if colours.fruit_rgb else None,
            disease=disease,
            disease_sign=sign,
            sources=tuple(sources),
        )

    def digest(self) -> str:
        """A content hash of the knowledge files and hierarchy (keys on-disk caches)."""
        text = yaml.safe_dump(self._raw, sort_keys=True) + self.hierarchy.digest()
        return hashlib.sha256(text.encode()).hexdigest()[:16]

    def __repr__(self) -> str:
        return f"KnowledgeBase({self.source!r}, {len(self.hierarchy.crops)} crops)"


def _stage(value: str) -> Stage:
    if value not in ("Vegetative", "Reproductive", "Maturation"):
        raise KnowledgeBaseError(
            f"{value!r} is not a growth stage",
            stage="knowledge",
            hint="Vegetative, Reproductive, Maturation",
        )
    return value  # type: ignore[return-value]


def _in_flower(entry: CropFile, season: str) -> bool:
    """Whether a reproductive plant of this crop shows flowers in ``season``."""
    if entry.flowering is not None:
        return season in entry.flowering.seasons
    # Without data: deciduous crops flower in spring and summer; evergreen,
    # perennial and annual crops whenever they are reproductive.
    return season in ("Spring", "Summer") or entry.leaf_habit != "deciduous"


def _season(value: str) -> Season:
    if value not in ("Spring", "Summer", "Fall", "Winter"):
        raise KnowledgeBaseError(
            f"{value!r} is not a season", stage="knowledge", hint="Spring, Summer, Fall, Winter"
        )
    return value  # type: ignore[return-value]


def load_knowledge_base(
    crops_dir: str | Path | None = None, hierarchy: Hierarchy | None = None
) -> KnowledgeBase:
    """Load ``crops/*.yaml`` (the shipped folder when None) for ``hierarchy``."""
    hierarchy = hierarchy or default_hierarchy()
    folder = Path(crops_dir) if crops_dir is not None else data_path("crops")
    if not folder.is_dir():
        raise KnowledgeBaseError(
            f"crop knowledge folder {str(folder)!r} does not exist", stage="knowledge"
        )
    raw_files: dict[str, dict[str, Any]] = {}
    for file in sorted(folder.glob("*.yaml")):
        try:
            raw = yaml.safe_load(file.read_text(encoding="utf-8"))
        except yaml.YAMLError as exc:
            raise KnowledgeBaseError(f"{file} is not valid YAML: {exc}", stage="knowledge") from exc
        if not isinstance(raw, dict) or not isinstance(raw.get("crop"), str):
            raise KnowledgeBaseError(
                f"{file} must be a mapping with a 'crop' name", stage="knowledge", path=str(file)
            )
        if pascal_case(raw["crop"]).lower() != file.stem.replace("_", "").lower():
            raise KnowledgeBaseError(
                f"{file.name} describes crop {raw['crop']!r}; name the file after its crop",
                stage="knowledge",
                path=str(file),
            )
        raw_files[raw["crop"]] = raw
    return KnowledgeBase(raw_files, hierarchy, source=str(folder))


@functools.lru_cache(maxsize=1)
def default_knowledge_base() -> KnowledgeBase:
    """The shipped knowledge base for the shipped hierarchy, loaded once."""
    return load_knowledge_base()
