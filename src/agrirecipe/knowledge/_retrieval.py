"""The seed paper's retrieval over the knowledge base, kept for the evaluation's comparison.

Yoncalik et al. embed one descriptor per asset, search the nearest descriptors
to a query and then keep only hits whose metadata equal the attributes the
language model extracted (a *strict* post-filter). :class:`KnowledgeRetriever`
reproduces that with the local sentence-transformers model and FAISS:

- :meth:`KnowledgeRetriever.search` is plain top-k by cosine similarity;
- :meth:`KnowledgeRetriever.search_filtered` retrieves a larger pool and keeps
  only entries whose attributes equal every given one. Like the paper's, it
  returns *fewer* than ``k`` hits (possibly none) when the pool holds fewer
  matches: that failure mode is what the evaluation measures;
- :meth:`KnowledgeRetriever.exact` is agrirecipe's structured lookup, for
  comparison.

The vectors of all descriptors are computed once and cached on disk, keyed by
the embedding model and the knowledge base's content digest.
"""

from __future__ import annotations

import threading
from dataclasses import dataclass
from pathlib import Path
from typing import TYPE_CHECKING

from agrirecipe._errors import ConfigurationError, HierarchyError, ModelError, PromptError
from agrirecipe.hierarchy import AssetKey
from agrirecipe.knowledge._base import KnowledgeBase, KnowledgeEntry

if TYPE_CHECKING:
    from agrirecipe.localmodels import Embedder, VectorIndex

__all__ = ["KnowledgeRetriever", "RetrievalHit"]

#: Smallest candidate pool the strict filter draws from (the paper filters a
#: generous top-N, not just top-k).
_MIN_POOL = 50


@dataclass(frozen=True, slots=True)
class RetrievalHit:
    """One retrieved knowledge entry: its cosine similarity and 1-based rank."""

    entry: KnowledgeEntry
    score: float
    rank: int


class KnowledgeRetriever:
    """Embedding search over every :class:`KnowledgeEntry` descriptor of a knowledge base.

    Nothing is loaded until the first search: then the embedding model is
    loaded (``agrirecipe.localmodels.default_embedder()`` when ``embedder`` is
    None) and the descriptors are embedded, or read from the cache folder
    ``cache`` (see :func:`agrirecipe.localmodels.cache_dir`).
    """

    def __init__(
        self,
        knowledge_base: KnowledgeBase,
        embedder: Embedder | None = None,
        *,
        cache: str | Path | None = None,
        progress: bool = True,
    ) -> None:
        self.knowledge_base = knowledge_base
        self._embedder = embedder
        self._cache = cache
        self._progress = progress
        self._entries: tuple[KnowledgeEntry, ...] | None = None
        self._index: VectorIndex | None = None
        self._lock = threading.Lock()

    @property
    def embedder(self) -> Embedder:
        """The embedding model (the default local model unless one was given)."""
        if self._embedder is None:
            from agrirecipe.localmodels import default_embedder

            self._embedder = default_embedder()
        return self._embedder

    @property
    def entries(self) -> tuple[KnowledgeEntry, ...]:
        """Every entry of the knowledge base, in catalogue order (the index's rows)."""
        if self._entries is None:
            self._entries = tuple(self.knowledge_base.entries())
        return self._entries

    @property
    def index(self) -> VectorIndex:
        """The FAISS index of all descriptors, built (or read from the cache) on first use."""
        with self._lock:
            if self._index is None:
                self._index = self._build_index()
            return self._index

    def _build_index(self) -> VectorIndex:
        from agrirecipe.localmodels import VectorIndex

        texts = [entry.descriptor for entry in self.entries]
        try:
            return VectorIndex.build(
                texts,
                self.embedder,
                # The name carries the knowledge digest so a changed crop file or
                # hierarchy never reuses stale vectors; build() adds the model id.
                name=f"knowledge-{self.knowledge_base.digest()}",
                cache=self._cache,
                progress=self._progress,
            )
        except ImportError as exc:  # faiss is imported when the first index is built
            raise ConfigurationError(
                f"embedding retrieval needs faiss: {exc}",
                stage="retrieval",
                hint="pip install 'agrirecipe[embedding]' (faiss-cpu)",
            ) from exc
        except RuntimeError as exc:  # FAISS reports failures as RuntimeError
            raise ModelError(f"could not build the FAISS index: {exc}", stage="retrieval") from exc

    # --- searching ---

    def search(self, query: str, k: int = 3) -> list[RetrievalHit]:
        """The ``k`` entries whose descriptors are most similar to ``query``, best first."""
        return self._search(query, k, pool=k)[:k]

    def search_filtered(
        self,
        query: str,
        k: int = 3,
        *,
        crop: str | None = None,
        variety: str | None = None,
        stage: str | None = None,
        season: str | None = None,
        health: str | None = None,
        pool: int | None = None,
    ) -> list[RetrievalHit]:
        """The paper's strict metadata post-filter.

        Retrieves the ``pool`` nearest entries (default ``max(50, 10 * k)``),
        keeps those whose attributes equal every attribute given, and returns
        the best ``k`` of them, re-ranked from 1. Fewer than ``k`` hits (or
        none) come back when the pool holds fewer matching entries.
        """
        wanted = self._check_filters(
            crop=crop, variety=variety, stage=stage, season=season, health=health
        )
        if pool is None:
            pool = max(_MIN_POOL, 10 * k)
        if pool < k:
            raise ConfigurationError(
                f"pool={pool} is smaller than k={k}",
                stage="retrieval",
                hint="the filter draws k hits from a pool of at least k candidates",
            )
        kept = [
            hit
            for hit in self._search(query, k, pool=pool)
            if all(getattr(hit.entry.key, name) == value for name, value in wanted.items())
        ]
        return [
            RetrievalHit(entry=hit.entry, score=hit.score, rank=rank)
            for rank, hit in enumerate(kept[:k], start=1)
        ]

    def exact(self, key: AssetKey) -> KnowledgeEntry:
        """The structured lookup (agrirecipe's own path), for comparison with retrieval."""
        return self.knowledge_base.lookup(key)

    def _search(self, query: str, k: int, *, pool: int) -> list[RetrievalHit]:
        if not isinstance(query, str) or not query.strip():
            raise PromptError(
                "the retrieval query is empty",
                stage="retrieval",
                hint="pass a descriptor such as "
                "'Apple Gala, Reproductive stage in Spring, Healthy'",
            )
        if isinstance(k, bool) or not isinstance(k, int) or k < 1:
            raise ConfigurationError(f"k must be a positive integer, got {k!r}", stage="retrieval")
        index = self.index
        vectors = self.embedder.encode([query])
        if vectors.ndim != 2 or vectors.shape[1] != index.vectors.shape[1]:
            raise ModelError(
                f"the embedder returns vectors of shape {tuple(vectors.shape)} but the index "
                f"holds {index.vectors.shape[1]}-dimensional vectors",
                stage="retrieval",
                hint="the model changed without changing its model_id; clear the cache folder",
            )
        try:
            scores, rows = index.search(vectors, min(pool, len(index)))
        except RuntimeError as exc:
            raise ModelError(f"FAISS search failed: {exc}", stage="retrieval") from exc
        hits: list[RetrievalHit] = []
        for score, row in zip(scores[0].tolist(), rows[0].tolist(), strict=True):
            if row < 0:  # FAISS pads with -1 past the end of the index
                break
            hits.append(
                RetrievalHit(entry=self.entries[row], score=float(score), rank=len(hits) + 1)
            )
        return hits

    def _check_filters(self, **filters: str | None) -> dict[str, str]:
        """The given filters, each checked against the hierarchy's accepted values."""
        hierarchy = self.knowledge_base.hierarchy
        accepted: dict[str, tuple[str, ...]] = {
            "crop": tuple(hierarchy.crops),
            "variety": tuple(dict.fromkeys(v.name for v in hierarchy.varieties)),
            "stage": hierarchy.stages,
            "season": hierarchy.seasons,
            "health": hierarchy.health,
        }
        wanted: dict[str, str] = {}
        for name, value in filters.items():
            if value is None:
                continue
            if value not in accepted[name]:
                raise HierarchyError(
                    f"{value!r} is not a {name} of this hierarchy",
                    stage="retrieval",
                    path=name,
                    hint="accepted: " + ", ".join(accepted[name]),
                )
            wanted[name] = value
        return wanted

    def __repr__(self) -> str:
        state = "indexed" if self._index is not None else "not indexed yet"
        return f"KnowledgeRetriever({self.knowledge_base!r}, {state})"
