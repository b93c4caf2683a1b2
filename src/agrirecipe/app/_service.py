"""What the app does, over the public API: make, edit and compile scenes, and describe them.

:class:`AppService` is the app without the web: every method is an ordinary
blocking call (the server runs them on worker threads) over ``generate``,
``agrirecipe.edit``, the recipe validator, ``Scene.write`` and the Blender
renderer. A new scene gets its own folder with ``recipe.json``, the field map
(``preview.png``) and the plant meshes (``assets/``) at once, so the page can
show it; every backend's outputs are written when they are first downloaded (on
the app's writer thread, one scene at a time), so making and editing scenes stays
fast and a scene nobody downloads costs nothing more.
"""

from __future__ import annotations

import io
import os
import shutil
import threading
import zipfile
from collections import Counter, OrderedDict
from collections.abc import Mapping, Sequence
from concurrent.futures import Future, ThreadPoolExecutor
from dataclasses import dataclass
from pathlib import Path
from typing import TYPE_CHECKING, Any, cast

from agrirecipe._errors import ConfigurationError, PromptError, RecipeValidationError
from agrirecipe._files import write_atomic
from agrirecipe.app._history import SceneRecord, SceneStore
from agrirecipe.app._render import RenderJobs
from agrirecipe.app._view import scene_view, view_plants
from agrirecipe.recipe import (
    DEFAULT_MAX_PLANTS,
    GEOMETRY_ATTRIBUTES,
    FieldGeometry,
    FieldSpec,
    Relation,
    SceneRecipe,
    check_recipe_data,
    dump_recipe,
    parse_recipe,
)

if TYPE_CHECKING:
    from agrirecipe._scene import ResolverName, Scene
    from agrirecipe.hierarchy import Hierarchy
    from agrirecipe.knowledge import KnowledgeBase

__all__ = ["AppConfig", "AppService"]

_ATTRIBUTES = ("crop", "variety", "stage", "season", "health")
_OUTPUTS_DONE = ".outputs-complete"
_SPACING_KEYS = ("row_spacing_m", "in_row_spacing_m", "rows_per_bed", "bed_row_spacing_m")
_SCENES_IN_MEMORY = 12


@dataclass(frozen=True)
class AppConfig:
    """Settings of one app: where it keeps scenes, how it resolves, its limits."""

    #: Folder of the history and the scene folders (None: ``cache_dir()/app``).
    root: Path | None = None
    resolver: ResolverName = "auto"
    seed: int = 0
    max_prompt_chars: int = 2_000
    #: Largest request body accepted (a recipe upload is the largest), bytes.
    max_body_bytes: int = 2_000_000
    max_plants: int = DEFAULT_MAX_PLANTS
    #: Plants the 3D view draws at most; above, a seeded sample (said on screen).
    view_plants: int = 100_000
    map_size_px: int = 900
    render_timeout_s: float = 1800.0


class AppService:
    """The app's scenes: made from prompts, edits, words or files; described for the page."""

    def __init__(self, config: AppConfig | None = None) -> None:
        from agrirecipe.hierarchy import default_hierarchy
        from agrirecipe.knowledge import default_knowledge_base
        from agrirecipe.localmodels import cache_dir

        self.config = config or AppConfig()
        self.store = SceneStore(self.config.root or cache_dir() / "app")
        self.hierarchy: Hierarchy = default_hierarchy()
        self.knowledge: KnowledgeBase = default_knowledge_base()
        self.renders = RenderJobs(timeout_s=self.config.render_timeout_s)
        # The local models hold one context each: requests that resolve words take turns.
        self._resolve_lock = threading.Lock()
        self._scenes: OrderedDict[str, Scene] = OrderedDict()
        self._scenes_lock = threading.Lock()
        self._outputs: dict[str, Future[None]] = {}
        self._outputs_lock = threading.Lock()
        self._writer = ThreadPoolExecutor(max_workers=1, thread_name_prefix="agrirecipe-outputs")

    def close(self) -> None:
        """Stop renders and the background writer (waits for the folder being written)."""
        self.renders.close()
        self._writer.shutdown(wait=True, cancel_futures=True)

    # --- making scenes ---

    def check_prompt(self, text: str, what: str = "prompt") -> str:
        """``text`` stripped, or a :class:`PromptError` when it is empty or too long."""
        limit = self.config.max_prompt_chars
        if len(text) > limit:
            raise PromptError(
                f"the {what} has {len(text):,} characters; the app takes at most {limit:,}",
                stage="app",
                hint=f"shorten the {what}, or use `agrirecipe generate` for longer requests",
            )
        if not text.strip():
            raise PromptError(f"the {what} is empty", stage="app", hint="describe a farm scene")
        return text.strip()

    def interpret(
        self, prompt: str, *, seed: int | None = None, resolver: ResolverName | None = None
    ) -> SceneRecord:
        """A new scene from a prompt (``generate`` with the explanation of every stage)."""
        from agrirecipe import generate

        text = self.check_prompt(prompt)
        with self._resolve_lock:
            scene = generate(
                text,
                seed=self.config.seed if seed is None else seed,
                resolver=resolver or self.config.resolver,
                hierarchy=self.hierarchy,
                knowledge=self.knowledge,
                explain=True,
                max_plants=self.config.max_plants,
            )
        explanation = scene.explanation.render() if scene.explanation is not None else None
        return self._create(scene, action="prompt", text=text, explanation=explanation)

    def refine(self, scene_id: str, instruction: str) -> SceneRecord:
        """A new scene: the scene's recipe changed by an instruction in words."""
        from agrirecipe.edit import edit_recipe

        text = self.check_prompt(instruction, "instruction")
        parent = self.store.get(scene_id)
        recipe = self.scene(scene_id).recipe
        with self._resolve_lock:
            result = edit_recipe(recipe, text)
        changed = self._validated(result.recipe.model_dump(mode="json"))
        return self._child(parent, changed, action="refine", text=text, changes=result.changes)

    def edit_field(self, scene_id: str, field_id: str, updates: Mapping[str, Any]) -> SceneRecord:
        """A new scene with one field's attributes or size changed (from the field table).

        Changed attributes become stated. A new crop without a variety takes the
        crop's default variety. Agronomy is recomputed for the new asset; a
        spacing the prompt stated is kept. A size that makes fields overlap
        re-packs the farm with its relations.
        """
        parent = self.store.get(scene_id)
        recipe = self.scene(scene_id).recipe
        spec = recipe.field(field_id)
        unknown = sorted(set(updates) - {*_ATTRIBUTES, "size_m"})
        if unknown:
            raise ConfigurationError(
                f"cannot edit {', '.join(unknown)} from the field table",
                stage="app",
                hint="editable: crop, variety, stage, season, health, size_m",
            )
        new_spec, changes = self._edited_field(spec, updates)
        if not changes:
            raise ConfigurationError(f"nothing changed in field {field_id!r}", stage="app")
        fields = [new_spec if f.id == field_id else f for f in recipe.fields]
        data = self._recipe_data(recipe, fields, recipe.relations)
        changed = self._validated_or_repacked(data, repack="size_m" in updates)
        return self._child(
            parent, changed, action="edit", text="; ".join(changes), changes=tuple(changes)
        )

    def edit_relations(self, scene_id: str, relations: Sequence[Mapping[str, Any]]) -> SceneRecord:
        """A new scene with these relations between fields; the farm is packed again."""
        from agrirecipe.layout import describe_relation

        parent = self.store.get(scene_id)
        recipe = self.scene(scene_id).recipe
        data = self._recipe_data(recipe, recipe.fields, ())
        data["relations"] = [dict(relation) for relation in relations]
        try:
            parsed = tuple(Relation.model_validate(r) for r in data["relations"])
        except ValueError as exc:
            raise RecipeValidationError(
                f"a relation is not valid: {exc}", stage="app", hint="kind, subject, objects"
            ) from exc
        before = {describe_relation(r) for r in recipe.relations}
        after = {describe_relation(r) for r in parsed}
        changes = [f"- {r}" for r in sorted(before - after)] + [
            f"+ {r}" for r in sorted(after - before)
        ]
        if not changes:
            raise ConfigurationError("the relations did not change", stage="app")
        changed = self._validated(self._repacked(data))
        return self._child(
            parent, changed, action="edit", text="; ".join(changes), changes=tuple(changes)
        )

    def upload(self, text: str) -> SceneRecord:
        """A new scene from recipe JSON, validated like ``agrirecipe validate``."""
        from agrirecipe._scene import Scene

        recipe = parse_recipe(
            text,
            hierarchy=self.hierarchy,
            max_plants=self.config.max_plants,
            source="the uploaded recipe",
        )
        scene = Scene(recipe, knowledge=self.knowledge)
        return self._create(scene, action="upload", text=recipe.prompt or "uploaded recipe")

    # --- reading scenes ---

    def scene(self, scene_id: str) -> Scene:
        """The scene of a history entry (kept in memory for the latest few)."""
        from agrirecipe._scene import Scene

        with self._scenes_lock:
            scene = self._scenes.get(scene_id)
            if scene is not None:
                self._scenes.move_to_end(scene_id)
                return scene
        self.store.get(scene_id)
        scene = Scene.from_file(
            self.store.folder(scene_id) / "recipe.json",
            hierarchy=self.hierarchy,
            knowledge=self.knowledge,
        )
        self._remember(scene_id, scene)
        return scene

    def describe(self, scene_id: str) -> dict[str, Any]:
        """Everything the page shows of a scene: record, field table, stages, warnings."""
        from agrirecipe.backends.annotations import field_colours

        record = self.store.get(scene_id)
        recipe = self.scene(scene_id).recipe
        colours = field_colours(len(recipe.fields))
        return {
            "scene": record.public(),
            "recipe": {
                "seed": recipe.seed,
                "resolver": recipe.resolver,
                "prompt": recipe.prompt,
                "season": recipe.environment.season,
                "latitude_deg": recipe.environment.latitude_deg,
                "nominal_plant_count": recipe.nominal_plant_count,
            },
            "fields": [_field_row(f, c) for f, c in zip(recipe.fields, colours, strict=True)],
            "relations": [r.model_dump(mode="json") for r in recipe.relations],
            "warnings": list(recipe.warnings),
            "explanation": explanation_stages(record.explanation),
            "map": "preview.png",
            "outputs": self.outputs_state(scene_id),
        }

    def view(self, scene_id: str, max_plants: int | None = None) -> dict[str, Any]:
        """The 3D view's description of a scene (fields, meshes, sample size, walk path)."""
        limit = self._view_limit(max_plants)
        return scene_view(self.scene(scene_id), self.knowledge, limit)

    def plants(self, scene_id: str, max_plants: int | None = None) -> bytes:
        """The plants the 3D view draws, as little-endian float32 records (see ``_view``)."""
        return view_plants(self.scene(scene_id), self._view_limit(max_plants))

    def _view_limit(self, max_plants: int | None) -> int:
        limit = self.config.view_plants if max_plants is None else max_plants
        return max(1, min(limit, 2_000_000))

    def choices(self) -> dict[str, Any]:
        """What the field table may choose: the hierarchy's crops, varieties and states."""
        tree = self.hierarchy
        return {
            "categories": {name: list(c.crops) for name, c in tree.categories.items()},
            "crops": {
                name: {
                    "category": crop.category,
                    "varieties": [v.name for v in crop.varieties],
                    "default_variety": self.knowledge.default_variety(name),
                }
                for name, crop in tree.crops.items()
            },
            "stages": list(tree.stages),
            "seasons": list(tree.seasons),
            "health": list(tree.health),
            "relation_kinds": ["north_of", "south_of", "east_of", "west_of", "next_to", "between"],
        }

    # --- outputs ---

    def outputs_state(self, scene_id: str) -> str:
        """``ready``, ``building``, ``failed: ...`` or ``pending`` (not written yet)."""
        if (self.store.folder(scene_id) / _OUTPUTS_DONE).is_file():
            return "ready"
        with self._outputs_lock:
            future = self._outputs.get(scene_id)
        if future is None:
            return "pending"
        if not future.done():
            return "building"
        error = future.exception()
        return "ready" if error is None else f"failed: {error}"

    def ensure_outputs(self, scene_id: str) -> None:
        """Wait until every backend's outputs of the scene are written (writing them if needed)."""
        self.store.get(scene_id)
        if self.outputs_state(scene_id) == "ready":
            return
        with self._outputs_lock:
            future = self._outputs.get(scene_id)
            if future is None or (future.done() and future.exception() is not None):
                future = self._writer.submit(self._write_outputs, scene_id)
                self._outputs[scene_id] = future
        future.result()

    def zip_outputs(self, scene_id: str) -> Path:
        """A zip of the scene's folder (every output, the meshes and any render)."""
        self.ensure_outputs(scene_id)
        folder = self.store.folder(scene_id)
        buffer = io.BytesIO()
        with zipfile.ZipFile(buffer, "w", compression=zipfile.ZIP_DEFLATED) as archive:
            for path in sorted(folder.rglob("*")):
                relative = path.relative_to(folder)
                if path.is_file() and not any(p.startswith(".") for p in relative.parts):
                    archive.write(path, f"agrirecipe-{scene_id}/{relative.as_posix()}")
        return write_atomic(self.store.zip_path(scene_id), buffer.getvalue())

    def _write_outputs(self, scene_id: str) -> None:
        folder = self.store.folder(scene_id)
        self.scene(scene_id).write(folder)
        write_atomic(folder / _OUTPUTS_DONE, "")

    # --- internals ---

    def _remember(self, scene_id: str, scene: Scene) -> None:
        with self._scenes_lock:
            self._scenes[scene_id] = scene
            self._scenes.move_to_end(scene_id)
            while len(self._scenes) > _SCENES_IN_MEMORY:
                self._scenes.popitem(last=False)

    def _create(
        self,
        scene: Scene,
        *,
        action: str,
        text: str,
        parent: str | None = None,
        changes: Sequence[str] = (),
        explanation: str | None = None,
    ) -> SceneRecord:
        """Write the scene's recipe, map and meshes into a new folder; record it."""
        from agrirecipe.backends.annotations import render_preview

        scene_id = self.store.new_id()
        folder = self.store.folder(scene_id)
        folder.mkdir(parents=True)
        recipe = scene.recipe
        self._link_assets(recipe, folder)
        png = io.BytesIO()
        render_preview(scene.layout, map_size_px=self.config.map_size_px).save(
            png, format="PNG", compress_level=1
        )
        write_atomic(folder / "preview.png", png.getvalue())
        # recipe.json last: a folder without it is not a scene (SceneStore.get).
        write_atomic(folder / "recipe.json", dump_recipe(recipe))
        record = self.store.add(
            scene_id=scene_id,
            action=action,
            text=text,
            parent=parent,
            changes=changes,
            summary=", ".join(f"{f.variety} {f.crop}" for f in recipe.fields),
            field_count=len(recipe.fields),
            plant_count=scene.layout.plant_count,
            explanation=explanation,
        )
        self._remember(scene_id, scene)
        return record

    def _link_assets(self, recipe: SceneRecipe, folder: Path) -> None:
        """Put the scene's plant meshes in ``folder/assets``, hard-linked from the app's
        library folder, where each mesh is drawn once (the plant library's files)."""
        from agrirecipe.plants import field_assets, write_scene_assets

        library = self.store.root / "library"
        assets = field_assets(recipe, knowledge=self.knowledge)
        files = sorted({name for asset in assets.values() if asset for name in asset.files})
        if any(not (library / name).is_file() for name in files):
            write_scene_assets(recipe, library, knowledge=self.knowledge)
        for name in files:
            target = folder / name
            target.parent.mkdir(parents=True, exist_ok=True)
            try:
                os.link(library / name, target)
            except OSError:  # another file system, or no hard links there
                shutil.copyfile(library / name, target)

    def _child(
        self,
        parent: SceneRecord,
        recipe: SceneRecipe,
        *,
        action: str,
        text: str,
        changes: Sequence[str],
    ) -> SceneRecord:
        from agrirecipe._scene import Scene

        lines = "\n".join(f"  {line}" for line in changes) or "  (no change)"
        explanation = f"[{action}]\n  from scene {parent.id}: {text}\n{lines}"
        if parent.explanation:
            explanation += "\n" + parent.explanation
        return self._create(
            Scene(recipe, knowledge=self.knowledge),
            action=action,
            text=text,
            parent=parent.id,
            changes=changes,
            explanation=explanation,
        )

    def _edited_field(
        self, spec: FieldSpec, updates: Mapping[str, Any]
    ) -> tuple[FieldSpec, list[str]]:
        from agrirecipe.enrich import build_field

        values = {name: str(getattr(spec, name)) for name in _ATTRIBUTES}
        stated = [a for a in spec.stated]
        inferred = [a for a in spec.inferred]
        changes: list[str] = []

        def mark(name: Any, how: list[Any], other: list[Any]) -> None:
            if name in other:
                other.remove(name)
            if name not in how:
                how.append(name)

        for name in _ATTRIBUTES:
            if name in updates and str(updates[name]) != values[name]:
                changes.append(f"~ {spec.id}: {name} {values[name]} -> {updates[name]}")
                values[name] = str(updates[name])
                mark(name, stated, inferred)
        crop = self.hierarchy.crop(values["crop"])  # unknown crop: HierarchyError
        values["crop"] = crop.name
        if values["variety"] not in {v.name for v in crop.varieties}:
            default = self.knowledge.default_variety(crop.name)
            changes.append(f"~ {spec.id}: variety {values['variety']} -> {default} (default)")
            values["variety"] = default
            mark("variety", inferred, stated)
        geometry = spec.geometry
        if "size_m" in updates:
            size = tuple(float(v) for v in updates["size_m"])
            if len(size) != 2 or size != tuple(geometry.size_m):
                changes.append(
                    f"~ {spec.id}: size {geometry.size_m[0]:g} x {geometry.size_m[1]:g} m -> "
                    + " x ".join(f"{v:g}" for v in size)
                    + " m"
                )
                geometry = FieldGeometry.model_validate(
                    {**geometry.model_dump(), "size_m": list(size)}
                )
                mark("size", stated, inferred)
        if not changes:
            return spec, changes
        if all(values[name] == str(getattr(spec, name)) for name in _ATTRIBUTES):
            data = {**spec.model_dump(mode="json"), "geometry": geometry.model_dump(mode="json")}
            data["stated"], data["inferred"] = stated, inferred
            return FieldSpec.model_validate(data), changes
        for name, allowed in (
            ("stage", self.hierarchy.stages),
            ("season", self.hierarchy.seasons),
            ("health", self.hierarchy.health),
        ):
            if values[name] not in allowed:
                raise ConfigurationError(
                    f"{values[name]!r} is not a {name} of the hierarchy",
                    stage="app",
                    path=f"{spec.id}.{name}",
                    hint="accepted: " + ", ".join(allowed),
                )
        keeps_spacing = any(a in GEOMETRY_ATTRIBUTES for a in spec.stated)
        agronomy = spec.agronomy.model_dump()
        new_spec = build_field(
            hierarchy=self.hierarchy,
            knowledge=self.knowledge,
            field_id=spec.id,
            label=spec.label,
            crop=values["crop"],
            variety=values["variety"],
            stage=cast(Any, values["stage"]),
            season=cast(Any, values["season"]),
            health=cast(Any, values["health"]),
            geometry=geometry,
            placement=spec.placement,
            stated=stated,
            inferred=inferred,
            agronomy_update={k: agronomy[k] for k in _SPACING_KEYS} if keeps_spacing else None,
        )
        return new_spec, changes

    def _recipe_data(
        self, recipe: SceneRecipe, fields: Sequence[FieldSpec], relations: Sequence[Relation]
    ) -> dict[str, Any]:
        from agrirecipe.enrich import build_environment

        data = recipe.model_dump(mode="json")
        data["fields"] = [f.model_dump(mode="json") for f in fields]
        data["relations"] = [r.model_dump(mode="json") for r in relations]
        # The scene's season (and so its sun) is the one most of its fields are in.
        counts = Counter(f.season for f in fields)
        current = recipe.environment.season
        season = current if counts[current] == max(counts.values()) else counts.most_common(1)[0][0]
        if season != current:
            data["environment"] = build_environment(
                season, recipe.environment.latitude_deg
            ).model_dump(mode="json")
        return data

    def _repacked(self, data: dict[str, Any]) -> dict[str, Any]:
        """``data`` with every field placed again by the field packer (relations honoured)."""
        from agrirecipe.layout import FieldRequest, pack_fields

        fields = [FieldSpec.model_validate(f) for f in data["fields"]]
        relations = [Relation.model_validate(r) for r in data["relations"]]
        requests = [
            FieldRequest(
                id=f.id,
                width_m=f.geometry.size_m[0],
                length_m=f.geometry.size_m[1],
                headland_m=f.geometry.headland_m,
                rotation_deg=f.geometry.rotation_deg,
            )
            for f in fields
        ]
        placed = pack_fields(requests, relations)
        for entry in data["fields"]:
            entry["geometry"] = placed[entry["id"]].model_dump(mode="json")
        return data

    def _validated_or_repacked(self, data: dict[str, Any], *, repack: bool) -> SceneRecipe:
        if repack:
            _, problems = check_recipe_data(
                data, hierarchy=self.hierarchy, max_plants=self.config.max_plants
            )
            if any("overlaps" in message for _, message in problems):
                data = self._repacked(data)
        return self._validated(data)

    def _validated(self, data: dict[str, Any]) -> SceneRecipe:
        """The recipe of ``data``, checked as ``agrirecipe validate`` checks a file."""
        recipe, problems = check_recipe_data(
            data, hierarchy=self.hierarchy, max_plants=self.config.max_plants
        )
        if recipe is None:
            listing = "; ".join(f"{path}: {message}" for path, message in problems)
            raise RecipeValidationError(
                f"the edited recipe is not valid: {listing}",
                problems=problems,
                stage="app",
                hint="undo the edit, or change another value",
            )
        return recipe


def _field_row(spec: FieldSpec, colour: tuple[int, int, int]) -> dict[str, Any]:
    agronomy = spec.agronomy
    return {
        "id": spec.id,
        "label": spec.label,
        "category": spec.category,
        "crop": spec.crop,
        "variety": spec.variety,
        "stage": spec.stage,
        "season": spec.season,
        "health": spec.health,
        "size_m": list(spec.geometry.size_m),
        "area_ha": round(spec.geometry.area_m2 / 10_000, 4),
        "rows": spec.row_count,
        "nominal_plant_count": spec.nominal_plant_count,
        "plants_per_instance": spec.placement.plants_per_instance,
        "row_spacing_m": agronomy.row_spacing_m,
        "in_row_spacing_m": agronomy.in_row_spacing_m,
        "plant_height_m": agronomy.plant_height_m,
        "asset_path": spec.asset_path,
        "stated": list(spec.stated),
        "inferred": list(spec.inferred),
        "colour": "#{:02x}{:02x}{:02x}".format(*colour),
    }


def explanation_stages(text: str | None) -> list[dict[str, Any]]:
    """An explanation's report (``Explanation.render()``) as ``[{stage, lines}]`` blocks."""
    stages: list[dict[str, Any]] = []
    for line in (text or "").splitlines():
        if line.startswith("[") and line.endswith("]"):
            stages.append({"stage": line[1:-1], "lines": []})
        elif stages:
            stages[-1]["lines"].append(line.strip())
        else:
            stages.append({"stage": "request", "lines": [line.strip()]})
    return stages
