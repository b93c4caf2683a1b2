"""The public API: each package's ``__all__`` is complete and sorted (as in httpx)."""

from __future__ import annotations

import importlib
import inspect
import pkgutil
import subprocess
import sys
import types

import pytest

import agrirecipe

# Public sub-packages (their names do not start with an underscore).
SUBPACKAGES = sorted(
    module.name
    for module in pkgutil.iter_modules(agrirecipe.__path__, prefix="agrirecipe.")
    if module.ispkg and not module.name.rsplit(".", 1)[1].startswith("_")
)
PACKAGES = ["agrirecipe", *SUBPACKAGES]
INCLUDED_PRIVATE_MEMBERS = {"__version__"}
# Heavy dependencies: imported by the feature that needs them, never by `import agrirecipe`.
HEAVY = ("torch", "sentence_transformers", "faiss", "llama_cpp", "bpy", "pxr", "transformers")


def _isort_order(name: str) -> tuple[int, str]:
    """The order ruff (RUF022) keeps ``__all__`` in: CONSTANTS, then Classes, then the rest."""
    if name.isupper() or not any(c.isalpha() for c in name):
        return (0, name)
    return (1, name) if name[0].isupper() else (2, name)


def test_root_all_is_complete_and_sorted() -> None:
    """httpx's test: every public name of ``agrirecipe`` is exported, in order."""
    public = [
        name
        for name, value in vars(agrirecipe).items()
        if (not name.startswith("_") or name in INCLUDED_PRIVATE_MEMBERS)
        and not isinstance(value, types.ModuleType)
    ]
    assert agrirecipe.__all__ == sorted(public, key=_isort_order)


@pytest.mark.parametrize("name", SUBPACKAGES)
def test_subpackage_all_is_complete_and_sorted(name: str) -> None:
    """Every class and function a sub-package defines (in its private modules) is exported."""
    module = importlib.import_module(name)
    assert module.__all__ == sorted(module.__all__, key=_isort_order)
    assert all(hasattr(module, member) for member in module.__all__)
    own = [
        member
        for member, value in vars(module).items()
        if not member.startswith("_")
        and (inspect.isclass(value) or inspect.isfunction(value))
        and value.__module__.startswith(f"{name}.")
    ]
    assert set(own) <= set(module.__all__), f"{name} defines but does not export {own}"


@pytest.mark.parametrize("name", PACKAGES)
def test_public_names_are_documented(name: str) -> None:
    module = importlib.import_module(name)
    assert module.__doc__
    for member in module.__all__:
        value = getattr(module, member)
        if inspect.isclass(value) or inspect.isfunction(value):
            assert value.__doc__, f"{name}.{member} has no docstring"


def test_foundation_names_are_exported() -> None:
    for member in ("generate", "SceneRecipe", "FieldSpec", "AgrirecipeError", "Backend"):
        assert member in agrirecipe.__all__
    from agrirecipe import knowledge

    assert {"KnowledgeRetriever", "RetrievalHit", "default_knowledge_base"} <= set(
        knowledge.__all__
    )


@pytest.mark.parametrize(
    "statement",
    [
        "import agrirecipe",
        "import agrirecipe.knowledge, agrirecipe.hierarchy, agrirecipe.recipe",
        "from agrirecipe.cli import build_parser; build_parser()",
    ],
)
def test_importing_loads_no_heavy_dependency(statement: str) -> None:
    loaded = f"sorted(m for m in {HEAVY!r} if m in sys.modules)"
    code = f"{statement}\nimport sys\nprint(','.join({loaded}))"
    result = subprocess.run(
        [sys.executable, "-c", code], capture_output=True, text=True, check=True
    )
    assert result.stdout.strip() == ""
