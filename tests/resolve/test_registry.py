"""Strategies by name: built-ins, "auto", third-party registration, helpful errors."""

from __future__ import annotations

import pytest

from agrirecipe import ConfigurationError
from agrirecipe.resolve import (
    FieldIntent,
    ResolveContext,
    Resolver,
    SceneIntent,
    available_resolvers,
    get_resolver,
    register_resolver,
    resolve,
    resolve_resolver_name,
)
from agrirecipe.resolve._registry import _INSTANCES, _REGISTERED


class _Fixed(Resolver):
    """Always one Fuji apple orchard: a stand-in third-party strategy."""

    name = "fixed"

    def resolve_intent(self, prompt: str, context: ResolveContext) -> SceneIntent:
        field = FieldIntent(text=prompt, crop="Apple", variety="Fuji")
        return SceneIntent(prompt=prompt, fields=(field,), resolver=self.name)


def test_names() -> None:
    assert {"auto", "rules", "embedding", "llm", "hybrid"} <= set(available_resolvers())
    assert available_resolvers() == sorted(available_resolvers())
    assert resolve_resolver_name("rules") == "rules"
    assert resolve_resolver_name("auto") in ("hybrid", "rules")


def test_instances_are_reused() -> None:
    assert get_resolver("rules") is get_resolver("rules")
    assert get_resolver("rules").name == "rules"


def test_a_resolver_object_is_used_as_is() -> None:
    fixed = _Fixed()
    assert get_resolver(fixed) is fixed
    recipe = resolve("anything at all", resolver=fixed).recipe
    assert (recipe.fields[0].variety, recipe.resolver) == ("Fuji", "fixed")


def test_register_a_strategy() -> None:
    try:
        register_resolver("fixed", _Fixed)
        assert "fixed" in available_resolvers()
        assert resolve("x", resolver="fixed").recipe.fields[0].crop == "Apple"  # type: ignore[arg-type]
        with pytest.raises(ConfigurationError, match="already exists"):
            register_resolver("fixed", _Fixed)
        register_resolver("fixed", _Fixed, replace=True)
    finally:
        _REGISTERED.pop("fixed", None)
        _INSTANCES.pop("fixed", None)


@pytest.mark.parametrize("name", ["auto", "rules"])
def test_builtin_names_cannot_be_taken(name: str) -> None:
    with pytest.raises(ConfigurationError):
        register_resolver(name, _Fixed)


def test_unknown_name_suggests_the_closest() -> None:
    with pytest.raises(ConfigurationError) as caught:
        get_resolver("hybird")
    assert "did you mean 'hybrid'" in str(caught.value)
    assert "rules" in (caught.value.hint or "")
