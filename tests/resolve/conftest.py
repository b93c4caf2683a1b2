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


def _crop_relations(prompt: str) -> NamedRelations:
    scene = generate(prompt).recipe
    crop = {f.id: f.crop for f in scene.fields}
    return {(r.kind, crop[r.subject], tuple(crop[o] for o in r.objects)) for r in scene.relations}


@pytest.fixture
def crop_relations() -> Callable[[str], NamedRelations]:
    """The relations ``generate`` reads from a prompt (its default resolver), fields named
    by their crop."""
    return _crop_relations
