"""Helpers shared by the resolver's tests."""

from __future__ import annotations

from collections.abc import Callable

import pytest

from agrirecipe import generate

#: A recipe's relations, each field named by its variety when the prompt names one, else
#: by its crop: {(kind, subject, objects)}.
NamedRelations = set[tuple[str, str, tuple[str, ...]]]


def _named_relations(prompt: str) -> NamedRelations:
    scene = generate(prompt, resolver="hybrid").recipe
    name = {f.id: (f.variety if "variety" in f.stated else f.crop) for f in scene.fields}
    return {(r.kind, name[r.subject], tuple(name[o] for o in r.objects)) for r in scene.relations}


@pytest.fixture
def named_relations() -> Callable[[str], NamedRelations]:
    """The relations the hybrid resolver reads from a prompt, fields named by what they grow."""
    return _named_relations
