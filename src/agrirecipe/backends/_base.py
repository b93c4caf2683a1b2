"""The backend base class: a compiler from a laid-out scene to engine files."""

from __future__ import annotations

from abc import ABC, abstractmethod
from pathlib import Path
from typing import TYPE_CHECKING, ClassVar

from agrirecipe._errors import BackendError

if TYPE_CHECKING:
    from agrirecipe._scene import Scene

__all__ = ["Backend"]


class Backend(ABC):
    """Compiles a :class:`~agrirecipe.Scene` (recipe + seeded layout) into files.

    Subclasses set ``name`` and ``outputs`` (the file names :meth:`write`
    creates) and implement :meth:`write`; script backends also implement
    :meth:`script`. Backends never see the prompt except as data inside the
    recipe, and must embed any recipe text in generated code only as escaped
    literals.
    """

    name: ClassVar[str]
    outputs: ClassVar[tuple[str, ...]]

    def script(self, scene: Scene) -> str:
        """The generated engine script as text (script backends only)."""
        raise BackendError(
            f"the {self.name!r} backend writes files but produces no script",
            stage="compile",
            hint="script backends: unreal, blender",
        )

    @abstractmethod
    def write(self, scene: Scene, directory: Path) -> list[Path]:
        """Write this backend's outputs into ``directory`` (atomically); return their paths."""

    def __repr__(self) -> str:
        return f"<{type(self).__name__} {self.name!r}>"
