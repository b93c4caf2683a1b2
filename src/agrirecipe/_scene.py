"""``generate()`` and :class:`Scene`: a recipe plus everything compiled from it."""

from __future__ import annotations

import functools
from collections.abc import Sequence
from pathlib import Path
from typing import TYPE_CHECKING, Literal

from agrirecipe._errors import ConfigurationError
from agrirecipe._files import remove_stale_temporaries, write_atomic
from agrirecipe.recipe import DEFAULT_MAX_PLANTS, SceneRecipe, dump_recipe, load_recipe

if TYPE_CHECKING:
    from agrirecipe.hierarchy import Hierarchy
    from agrirecipe.knowledge import KnowledgeBase
    from agrirecipe.layout import Layout
    from agrirecipe.resolve import Explanation, Resolver

__all__ = ["DEFAULT_BACKENDS", "ResolverName", "Scene", "generate"]

ResolverName = Literal["auto", "rules", "embedding", "llm", "hybrid"]
#: Backends ``Scene.write`` runs when none are named.
DEFAULT_BACKENDS: tuple[str, ...] = ("unreal", "blender", "usd", "annotations")


class Scene:
    """A validated :class:`SceneRecipe` and its compiled outputs (computed on demand)."""

    def __init__(
        self,
        recipe: SceneRecipe,
        *,
        explanation: Explanation | None = None,
        knowledge: KnowledgeBase | None = None,
        changes: Sequence[str] = (),
    ) -> None:
        self.recipe = recipe
        self.explanation = explanation
        #: The knowledge base the plant meshes are drawn from (None: the shipped one).
        self.knowledge = knowledge
        #: What :meth:`edit` changed to make this scene from the one before (one line each).
        self.changes = tuple(changes)

    @classmethod
    def from_file(
        cls,
        path: str | Path,
        *,
        hierarchy: Hierarchy | None = None,
        knowledge: KnowledgeBase | None = None,
    ) -> Scene:
        """A scene from a recipe file (validated; see :func:`agrirecipe.recipe.load_recipe`)."""
        if hierarchy is None and knowledge is not None:
            hierarchy = knowledge.hierarchy
        return cls(load_recipe(path, hierarchy=hierarchy), knowledge=knowledge)

    @functools.cached_property
    def layout(self) -> Layout:
        """Every plant of every field, placed by the seeded layout kernel."""
        from agrirecipe.layout import layout_scene

        return layout_scene(self.recipe)

    def edit(self, instruction: str, *, resolver: ResolverName = "auto") -> Scene:
        """A new scene with one change said in words ("make the pears ill", "remove the
        carrots", "add a wheat field south of the orchard", "rows 50 cm apart").

        Fields the instruction does not touch keep their ids, attributes, geometry and
        every plant position; ``changes`` of the result lists what changed. Raises
        :class:`~agrirecipe.PromptError` for an instruction that names nothing in the
        scene or is ambiguous, with the scene's fields in its hint.
        """
        from agrirecipe.edit import edit_recipe

        result = edit_recipe(self.recipe, instruction, knowledge=self.knowledge, resolver=resolver)
        return Scene(result.recipe, knowledge=self.knowledge, changes=result.changes)

    def script(self, backend: str) -> str:
        """The generated script of a script backend (``"unreal"`` or ``"blender"``)."""
        from agrirecipe.backends import get_backend

        return get_backend(backend).script(self)

    def write(
        self,
        directory: str | Path,
        *,
        backends: Sequence[str] | None = None,
    ) -> list[Path]:
        """Write ``recipe.json`` and every backend's outputs into ``directory``.

        Each file is written atomically; the folder is created if needed. Temporary
        files that an earlier, killed write left in the folder are removed first.
        """
        from agrirecipe.backends import get_backend

        names = tuple(DEFAULT_BACKENDS if backends is None else backends)
        resolved = [get_backend(name) for name in names]  # unknown names fail before writing
        folder = Path(directory)
        if folder.exists() and not folder.is_dir():
            raise ConfigurationError(
                f"output path {str(folder)!r} exists and is not a folder", stage="write"
            )
        remove_stale_temporaries(folder)
        written = [write_atomic(folder / "recipe.json", dump_recipe(self.recipe))]
        for backend in resolved:
            written.extend(backend.write(self, folder))
        return written

    def __repr__(self) -> str:
        crops = ", ".join(f"{f.variety} {f.crop}" for f in self.recipe.fields)
        return f"Scene({len(self.recipe.fields)} field(s): {crops})"


def generate(
    prompt: str,
    *,
    seed: int = 0,
    resolver: ResolverName | Resolver = "auto",
    hierarchy: Hierarchy | str | Path | None = None,
    knowledge: KnowledgeBase | str | Path | None = None,
    latitude_deg: float | None = None,
    explain: bool = False,
    max_plants: int = DEFAULT_MAX_PLANTS,
) -> Scene:
    """Turn a natural-language request into a :class:`Scene`.

    ``resolver`` names the strategy ("rules", "embedding", "llm", "hybrid";
    "auto" picks the best available offline) or is a resolver object.
    ``hierarchy``/``knowledge`` default to the shipped files; a path loads a
    user's own. ``latitude_deg`` places the scene (default: Belgium, 50.9 N)
    unless the prompt says otherwise. With ``explain=True`` the scene's
    ``explanation`` shows what each stage produced. ``max_plants`` caps the
    scene's planting positions (default 10 million; a 5 ha wheat field holds
    about 7.6 million).
    """
    from agrirecipe.resolve import resolve

    resolution = resolve(
        prompt,
        seed=seed,
        resolver=resolver,
        hierarchy=hierarchy,
        knowledge=knowledge,
        latitude_deg=latitude_deg,
        explain=explain,
        max_plants=max_plants,
    )
    return Scene(
        resolution.recipe, explanation=resolution.explanation, knowledge=resolution.knowledge
    )
