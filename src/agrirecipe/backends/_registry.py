"""Backends by name: built-ins are imported lazily; third parties may register more."""

from __future__ import annotations

import importlib
from collections.abc import Callable

from agrirecipe._errors import ConfigurationError
from agrirecipe.backends._base import Backend

__all__ = ["available_backends", "get_backend", "register_backend"]

BackendFactory = Callable[[], Backend]

_BUILTIN: dict[str, str] = {
    "unreal": "agrirecipe.backends.unreal:UnrealBackend",
    "blender": "agrirecipe.backends.blender:BlenderBackend",
    "usd": "agrirecipe.backends.usd:UsdBackend",
    "annotations": "agrirecipe.backends.annotations:AnnotationsBackend",
    "gazebo": "agrirecipe.backends.gazebo:GazeboBackend",
}
_REGISTERED: dict[str, BackendFactory] = {}


def register_backend(name: str, factory: BackendFactory, *, replace: bool = False) -> None:
    """Make ``factory()`` available as backend ``name``."""
    if not replace and (name in _REGISTERED or name in _BUILTIN):
        raise ConfigurationError(
            f"a backend named {name!r} already exists", stage="compile", hint="pass replace=True"
        )
    _REGISTERED[name] = factory


def available_backends() -> list[str]:
    """Names of every backend, built-in and registered, sorted."""
    return sorted(set(_BUILTIN) | set(_REGISTERED))


def get_backend(name: str) -> Backend:
    """A new instance of the backend called ``name``."""
    if name in _REGISTERED:
        return _REGISTERED[name]()
    target = _BUILTIN.get(name)
    if target is None:
        from rapidfuzz import process

        names = available_backends()
        match = process.extractOne(name, names)
        closest = f"; did you mean {match[0]!r}?" if match and match[1] >= 60 else ""
        raise ConfigurationError(
            f"unknown backend {name!r}{closest}",
            stage="compile",
            hint="available: " + ", ".join(names),
        )
    module_name, _, class_name = target.partition(":")
    module = importlib.import_module(module_name)
    backend_class: type[Backend] = getattr(module, class_name)
    return backend_class()
