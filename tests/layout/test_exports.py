"""``agrirecipe.layout``'s public surface: complete, documented, importable."""

from __future__ import annotations

import inspect

import agrirecipe.layout as layout


def test_every_public_name_is_exported_and_documented() -> None:
    for name in layout.__all__:
        value = getattr(layout, name)
        if inspect.isfunction(value) or inspect.isclass(value):
            assert inspect.getdoc(value), f"{name} has no docstring"
    public = {
        name
        for name, value in vars(layout).items()
        if not name.startswith("_") and not inspect.ismodule(value)
    }
    assert public == set(layout.__all__)
