"""The error tree: every error agrirecipe raises on purpose is an ``AgrirecipeError``."""

from __future__ import annotations

import ast
import builtins
from pathlib import Path

import pytest

import agrirecipe
from agrirecipe import _errors
from agrirecipe._errors import (
    AgrirecipeError,
    PipelineError,
    RecipeValidationError,
    UnknownCropError,
    UserInputError,
)

ERROR_CLASSES = [getattr(_errors, name) for name in _errors.__all__]


BUILTIN_EXCEPTIONS = {
    name
    for name, value in vars(builtins).items()
    if isinstance(value, type) and issubclass(value, BaseException)
}
SOURCE = Path(agrirecipe.__file__).resolve().parent


@pytest.mark.parametrize("error", ERROR_CLASSES, ids=lambda error: error.__name__)
def test_every_error_subclasses_the_root(error: type[Exception]) -> None:
    assert issubclass(error, AgrirecipeError)
    if error is not AgrirecipeError:
        assert issubclass(error, UserInputError) != issubclass(error, PipelineError)


@pytest.mark.parametrize("error", ERROR_CLASSES, ids=lambda error: error.__name__)
def test_tree_in_the_docstring_lists_every_error(error: type[Exception]) -> None:
    assert _errors.__doc__ is not None
    assert f"    {error.__name__} " in _errors.__doc__ or f"─ {error.__name__} " in _errors.__doc__
    assert error.__doc__, "every error says when it is raised"


@pytest.mark.parametrize("error", ERROR_CLASSES, ids=lambda error: error.__name__)
def test_errors_are_exported_from_the_package(error: type[Exception]) -> None:
    assert getattr(agrirecipe, error.__name__) is error


def _imports_agrirecipe(tree: ast.Module) -> bool:
    for node in ast.walk(tree):
        if isinstance(node, ast.ImportFrom) and (node.module or "").startswith("agrirecipe"):
            return True
        if isinstance(node, ast.Import) and any(
            a.name.startswith("agrirecipe") for a in node.names
        ):
            return True
    return False


def test_no_exception_class_bypasses_the_root() -> None:
    """Read (not import) every module: engine-side sources only run inside their engine."""
    offenders = []
    for path in sorted(SOURCE.rglob("*.py")):
        tree = ast.parse(path.read_text(encoding="utf-8"), filename=str(path))
        if path.name != "_errors.py" and not _imports_agrirecipe(tree):
            continue  # standalone code inlined into engine scripts cannot import the library
        for node in ast.walk(tree):
            if not isinstance(node, ast.ClassDef) or node.name == "AgrirecipeError":
                continue
            for base in node.bases:
                name = base.id if isinstance(base, ast.Name) else getattr(base, "attr", None)
                if name in BUILTIN_EXCEPTIONS:
                    offenders.append(f"{path.relative_to(SOURCE)}: {node.name}({name})")
    assert offenders == []


def test_message_carries_path_and_hint() -> None:
    error = RecipeValidationError(
        "field too small",
        path="fields[1].geometry.size_m",
        hint="make it bigger",
        problems=[("fields[1].geometry.size_m", "field too small")],
    )
    assert str(error) == "fields[1].geometry.size_m: field too small (make it bigger)"
    assert (error.stage, error.message) == ("validate", "field too small")
    assert error.problems == (("fields[1].geometry.size_m", "field too small"),)
    assert str(AgrirecipeError("plain")) == "plain"


def test_unknown_crop_error_lists_the_nearest() -> None:
    error = UnknownCropError("'aple' is not a crop", requested="aple", nearest=["Apple", "Maple"])
    assert error.requested == "aple"
    assert error.nearest == ("Apple", "Maple")
    assert str(error) == "'aple' is not a crop (nearest known: Apple, Maple)"
    assert error.stage == "resolve"
    assert isinstance(error, agrirecipe.PromptError)


def test_errors_chain_their_cause() -> None:
    from agrirecipe.recipe import parse_recipe

    with pytest.raises(RecipeValidationError) as caught:
        parse_recipe("{")
    assert caught.value.__cause__ is not None
