"""The agrirecipe error tree.

Every failure a user can cause is an :class:`AgrirecipeError`; programming
errors (bugs) are left as ordinary Python exceptions.

::

    AgrirecipeError                       root: catch this to catch everything we raise
    ├── UserInputError                    the caller asked for something we cannot do
    │   ├── PromptError                   empty, non-agricultural or contradictory prompt
    │   │   └── UnknownCropError          a crop/variety not in the hierarchy (lists nearest)
    │   ├── RecipeValidationError         a recipe (object or file) breaks the schema
    │   ├── HierarchyError                malformed hierarchy file, unknown asset path
    │   ├── KnowledgeBaseError            malformed crop knowledge file, missing entry
    │   └── ConfigurationError            bad argument: unknown resolver/backend, bad model path
    └── PipelineError                     a stage failed on valid input
        ├── ModelError                    a local model (embedding, GGUF) could not load or run
        └── BackendError                  an engine backend (bpy, pxr) failed

Each error carries the pipeline ``stage`` that raised it, the offending
``path`` (a dotted field path such as ``fields[1].geometry.size_m``) when there
is one, and a ``hint`` saying what is accepted.
"""

from __future__ import annotations

from collections.abc import Sequence

__all__ = [
    "AgrirecipeError",
    "BackendError",
    "ConfigurationError",
    "HierarchyError",
    "KnowledgeBaseError",
    "ModelError",
    "PipelineError",
    "PromptError",
    "RecipeValidationError",
    "UnknownCropError",
    "UserInputError",
]


class AgrirecipeError(Exception):
    """Root of every error agrirecipe raises on purpose."""

    def __init__(
        self,
        message: str,
        *,
        stage: str | None = None,
        path: str | None = None,
        hint: str | None = None,
    ) -> None:
        self.message = message
        self.stage = stage
        self.path = path
        self.hint = hint
        super().__init__(message)

    def __str__(self) -> str:
        parts = []
        if self.path:
            parts.append(f"{self.path}: ")
        parts.append(self.message)
        if self.hint:
            parts.append(f" ({self.hint})")
        return "".join(parts)


class UserInputError(AgrirecipeError):
    """The caller asked for something agrirecipe cannot do."""


class PromptError(UserInputError):
    """A prompt that is empty, not about agriculture, or self-contradictory."""


class UnknownCropError(PromptError):
    """A crop or variety that is not in the asset hierarchy."""

    def __init__(
        self,
        message: str,
        *,
        requested: str,
        nearest: Sequence[str] = (),
        stage: str | None = "resolve",
        path: str | None = None,
        hint: str | None = None,
    ) -> None:
        self.requested = requested
        self.nearest = tuple(nearest)
        if hint is None and self.nearest:
            hint = "nearest known: " + ", ".join(self.nearest)
        super().__init__(message, stage=stage, path=path, hint=hint)


class RecipeValidationError(UserInputError):
    """A recipe breaks the schema; ``problems`` lists every (path, message)."""

    def __init__(
        self,
        message: str,
        *,
        problems: Sequence[tuple[str, str]] = (),
        stage: str | None = "validate",
        path: str | None = None,
        hint: str | None = None,
    ) -> None:
        self.problems = tuple(problems)
        super().__init__(message, stage=stage, path=path, hint=hint)


class HierarchyError(UserInputError):
    """A malformed hierarchy file, or an asset path that is not in the catalogue."""


class KnowledgeBaseError(UserInputError):
    """A malformed crop knowledge file or a missing entry."""


class ConfigurationError(UserInputError):
    """A bad argument: unknown resolver or backend name, a model path that does not exist."""


class PipelineError(AgrirecipeError):
    """A stage failed on valid input."""


class ModelError(PipelineError):
    """A local model (embedding, GGUF) could not be loaded or run."""


class BackendError(PipelineError):
    """An engine backend (bpy, pxr) failed."""
