"""Resolver strategies by name; built-ins are imported lazily, third parties may register more.

``"auto"`` picks ``"hybrid"`` when the embedding stack (sentence-transformers,
FAISS and a local model) is installed, else ``"rules"``, which needs nothing
beyond the core dependencies.
"""

from __future__ import annotations

import importlib
import importlib.util
import threading
from collections.abc import Callable

from agrirecipe._errors import ConfigurationError
from agrirecipe.resolve._intent import Resolver

__all__ = [
    "BUILTIN_RESOLVERS",
    "available_resolvers",
    "get_resolver",
    "register_resolver",
    "resolve_resolver_name",
]

ResolverFactory = Callable[[], Resolver]

#: Built-in strategies: name -> "module:Class" (imported on first use).
BUILTIN_RESOLVERS: dict[str, str] = {
    "rules": "agrirecipe.resolve._rules:RulesResolver",
    "embedding": "agrirecipe.resolve._embedding:EmbeddingResolver",
    "llm": "agrirecipe.resolve.llm:LlmResolver",
    "hybrid": "agrirecipe.resolve._hybrid:HybridResolver",
    "finetuned": "agrirecipe.finetune._strategy:FinetunedResolver",
}
_REGISTERED: dict[str, ResolverFactory] = {}
# One instance per built-in name and process: instances hold lazily loaded models
# and indexes that later calls reuse.
_INSTANCES: dict[str, Resolver] = {}
_LOCK = threading.Lock()


def register_resolver(name: str, factory: ResolverFactory, *, replace: bool = False) -> None:
    """Make ``factory()`` available as resolver ``name``."""
    if name == "auto" or (not replace and (name in _REGISTERED or name in BUILTIN_RESOLVERS)):
        raise ConfigurationError(
            f"a resolver named {name!r} already exists", stage="resolve", hint="pass replace=True"
        )
    with _LOCK:
        _REGISTERED[name] = factory
        _INSTANCES.pop(name, None)


def available_resolvers() -> list[str]:
    """Names accepted by ``resolver=``: "auto", the built-ins and registered ones, sorted."""
    return sorted({"auto"} | set(BUILTIN_RESOLVERS) | set(_REGISTERED))


def _embedding_stack_installed() -> bool:
    return all(
        importlib.util.find_spec(module) is not None
        for module in ("torch", "sentence_transformers", "faiss")
    )


def resolve_resolver_name(name: str) -> str:
    """The concrete strategy a name stands for ("auto" -> "hybrid" or "rules")."""
    if name != "auto":
        return name
    return "hybrid" if _embedding_stack_installed() else "rules"


def get_resolver(name: str | Resolver = "auto") -> Resolver:
    """The resolver called ``name`` (reused across calls), or ``name`` itself if it is one."""
    if isinstance(name, Resolver):
        return name
    if not isinstance(name, str):
        raise ConfigurationError(
            f"resolver must be a name or a Resolver, not {type(name).__name__}",
            stage="resolve",
            hint="accepted names: " + ", ".join(available_resolvers()),
        )
    concrete = resolve_resolver_name(name)
    with _LOCK:
        cached = _INSTANCES.get(concrete)
        if cached is not None:
            return cached
        if concrete in _REGISTERED:
            instance = _REGISTERED[concrete]()
        elif concrete in BUILTIN_RESOLVERS:
            module_name, _, class_name = BUILTIN_RESOLVERS[concrete].partition(":")
            module = importlib.import_module(module_name)
            instance = getattr(module, class_name)()
        else:
            from rapidfuzz import process

            names = available_resolvers()
            match = process.extractOne(name, names)
            closest = f"; did you mean {match[0]!r}?" if match and match[1] >= 60 else ""
            raise ConfigurationError(
                f"unknown resolver {name!r}{closest}",
                stage="resolve",
                hint="available: " + ", ".join(names),
            )
        _INSTANCES[concrete] = instance
        return instance
