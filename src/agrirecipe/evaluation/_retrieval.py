"""The paper's Table II: exact-match Top-k of knowledge retrieval, embedding vs structured.

For each query (an asset described in words) three methods look for the asset:

- ``rag``: the seed paper's RAG, nearest descriptors by embedding only;
- ``paper_filter``: the paper's hybrid, the same search with a strict metadata
  post-filter on the attributes extracted from the query (here by our resolver:
  the attributes it marks as stated);
- ``exact``: agrirecipe's path, the resolver's structured attributes looked up
  exactly in the knowledge base (one answer, so Top-1 = Top-2 = Top-3);

plus ``oracle_filter``, a diagnostic: the strict filter given the *true*
attributes, which isolates the embedding pool from extraction errors.
"""

from __future__ import annotations

import sys
import time
from collections.abc import Sequence
from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Any

from agrirecipe._errors import AgrirecipeError, ConfigurationError, ModelError
from agrirecipe.evaluation._benchmark import KnowledgeQuery
from agrirecipe.evaluation._summary import Rate

if TYPE_CHECKING:
    from agrirecipe.evaluation._runner import Generate
    from agrirecipe.hierarchy import AssetKey
    from agrirecipe.knowledge import KnowledgeBase, KnowledgeRetriever, RetrievalHit

__all__ = ["RETRIEVAL_METHODS", "QueryResult", "RetrievalRun", "run_retrieval"]

RETRIEVAL_METHODS: tuple[str, ...] = ("rag", "paper_filter", "exact", "oracle_filter")
_FILTERABLE = ("crop", "variety", "stage", "season", "health")


@dataclass(frozen=True, slots=True)
class QueryResult:
    """Where each method ranked the right asset (1-based; None = not in its top k)."""

    query: str
    expected: AssetKey
    ranks: dict[str, int | None]
    extracted: dict[str, str] = field(default_factory=dict)
    stated: tuple[str, ...] = ()
    top_rag: str | None = None
    error: str | None = None


@dataclass(frozen=True, slots=True)
class RetrievalRun:
    """Table II's measurements, or why they could not be taken."""

    k: int
    resolver: str
    results: tuple[QueryResult, ...] = ()
    seconds: dict[str, float] = field(default_factory=dict)
    unavailable: str | None = None

    def top(self, method: str, k: int) -> Rate:
        """How many queries ``method`` answered with the right asset within its top ``k``."""
        hits = sum(
            1 for r in self.results if (rank := r.ranks.get(method)) is not None and rank <= k
        )
        return Rate(hits, len(self.results))

    def misses(self, method: str) -> tuple[QueryResult, ...]:
        """The queries ``method`` did not answer at rank 1."""
        return tuple(r for r in self.results if r.ranks.get(method) != 1)


def _rank(hits: Sequence[RetrievalHit], expected: AssetKey) -> int | None:
    for position, hit in enumerate(hits, start=1):
        if hit.entry.key == expected:
            return position
    return None


def _describe(key: AssetKey) -> str:
    return f"{key.crop}/{key.variety}, {key.stage}, {key.season}, {key.health}"


def run_retrieval(
    queries: Sequence[KnowledgeQuery],
    *,
    resolver: str = "hybrid",
    k: int = 3,
    seed: int = 0,
    progress: bool = True,
    knowledge: KnowledgeBase | None = None,
    retriever: KnowledgeRetriever | None = None,
    generate: Generate | None = None,
    generate_options: dict[str, Any] | None = None,
) -> RetrievalRun:
    """Measure every method on ``queries`` with the real embedding model.

    ``resolver`` extracts the structured attributes (for ``paper_filter`` and
    ``exact``). Returns an unavailable run when the embedding stack is missing.
    """
    from tqdm import tqdm

    from agrirecipe.knowledge import KnowledgeRetriever, default_knowledge_base

    call: Generate
    if generate is None:
        from agrirecipe import generate as call
    else:
        call = generate
    knowledge = knowledge or default_knowledge_base()
    retriever = retriever or KnowledgeRetriever(knowledge, progress=progress)
    options = dict(generate_options or {})
    try:
        retriever.search(queries[0].query if queries else "apple", k)  # loads model and index
    except (ConfigurationError, ModelError) as exc:
        return RetrievalRun(k=k, resolver=resolver, unavailable=f"{type(exc).__name__}: {exc}")
    seconds = dict.fromkeys(("rag", "extract", "paper_filter", "exact"), 0.0)
    results: list[QueryResult] = []
    for item in tqdm(
        queries, desc="eval retrieval", unit="query", disable=not progress, file=sys.stderr
    ):
        expected = item.key
        ranks: dict[str, int | None] = dict.fromkeys(RETRIEVAL_METHODS)
        begin = time.perf_counter()
        rag_hits = retriever.search(item.query, k)
        seconds["rag"] += time.perf_counter() - begin
        ranks["rag"] = _rank(rag_hits, expected)
        oracle = {name: getattr(expected, name) for name in _FILTERABLE}
        ranks["oracle_filter"] = _rank(retriever.search_filtered(item.query, k, **oracle), expected)
        extracted: dict[str, str] = {}
        stated_names: tuple[str, ...] = ()
        error: str | None = None
        begin = time.perf_counter()
        try:
            scene = call(item.query, seed=seed, resolver=resolver, **options)
        except Exception as exc:  # a failed extraction is a miss for both structured methods
            error = f"{type(exc).__name__}: {exc}"
            seconds["extract"] += time.perf_counter() - begin
        else:
            seconds["extract"] += time.perf_counter() - begin
            spec = scene.recipe.fields[0]
            extracted = {name: getattr(spec, name) for name in _FILTERABLE}
            stated_names = tuple(name for name in _FILTERABLE if name in spec.stated)
            stated = {name: extracted[name] for name in stated_names}
            begin = time.perf_counter()
            filtered = retriever.search_filtered(
                item.query,
                k,
                crop=stated.get("crop"),
                variety=stated.get("variety"),
                stage=stated.get("stage"),
                season=stated.get("season"),
                health=stated.get("health"),
            )
            seconds["paper_filter"] += time.perf_counter() - begin
            ranks["paper_filter"] = _rank(filtered, expected)
            begin = time.perf_counter()
            try:
                key = knowledge.hierarchy.key(
                    spec.crop, spec.variety, spec.stage, spec.season, spec.health
                )
                found = knowledge.lookup(key).key
            except AgrirecipeError as exc:
                error = f"{type(exc).__name__}: {exc}"
            else:
                ranks["exact"] = 1 if found == expected else None
            seconds["exact"] += time.perf_counter() - begin
        results.append(
            QueryResult(
                query=item.query,
                expected=expected,
                ranks=ranks,
                extracted=extracted,
                stated=stated_names,
                top_rag=_describe(rag_hits[0].entry.key) if rag_hits else None,
                error=error,
            )
        )
    return RetrievalRun(k=k, resolver=resolver, results=tuple(results), seconds=seconds)
