"""The seed paper's embedding retrieval, with the real local model and FAISS."""

from __future__ import annotations

from collections.abc import Sequence
from typing import TYPE_CHECKING

import numpy as np
import pytest

from agrirecipe import ConfigurationError, HierarchyError, ModelError, PromptError
from agrirecipe.knowledge import (
    KnowledgeBase,
    KnowledgeEntry,
    KnowledgeRetriever,
    default_knowledge_base,
)
from agrirecipe.localmodels import Embedder, cache_dir

if TYPE_CHECKING:
    from numpy.typing import NDArray

pytestmark = pytest.mark.slow


class CountingEmbedder:
    """Wraps the real embedder, counting the texts it is asked to embed."""

    def __init__(self, inner: Embedder, *, keep_dimensions: int | None = None) -> None:
        self.inner = inner
        self.texts_encoded = 0
        self.keep_dimensions = keep_dimensions

    @property
    def model_id(self) -> str:
        return self.inner.model_id

    def encode(self, texts: Sequence[str]) -> NDArray[np.float32]:
        self.texts_encoded += len(texts)
        vectors = self.inner.encode(texts)
        return vectors[:, : self.keep_dimensions] if self.keep_dimensions else vectors


@pytest.fixture(scope="module")
def kb() -> KnowledgeBase:
    return default_knowledge_base()


@pytest.fixture(scope="module")
def retriever(kb: KnowledgeBase) -> KnowledgeRetriever:
    """One retriever for the module: the model loads and the index is built (or read) once."""
    retriever = KnowledgeRetriever(kb, progress=False)
    assert len(retriever.index) == 1584
    return retriever


def test_exact_descriptor_finds_its_entry(retriever: KnowledgeRetriever) -> None:
    by_crop: dict[str, list[KnowledgeEntry]] = {}
    for entry in retriever.entries:
        by_crop.setdefault(entry.key.crop, []).append(entry)
    # One entry per crop, spread over varieties, stages, seasons and health.
    picks = [entries[(37 * n + 11) % len(entries)] for n, entries in enumerate(by_crop.values())]
    assert len({(e.key.stage, e.key.season, e.key.health) for e in picks}) > 8
    for entry in picks:
        top = retriever.search(entry.descriptor, k=1)
        assert [hit.entry for hit in top] == [entry]
        assert top[0].score == pytest.approx(1.0, abs=1e-4)
        assert top[0].rank == 1


@pytest.mark.parametrize(
    "attributes",
    [
        ("Apple", "Pink Lady", "Maturation", "Summer"),
        ("Pear", "Conference", "Reproductive", "Spring"),
        ("Grape", "Pinot Noir", "Maturation", "Fall"),
        ("Carrot", "Nantes", "Vegetative", "Summer"),
        ("Wheat", "Spelt", "Maturation", "Summer"),
        ("Lettuce", "Lollo Rosso", "Vegetative", "Spring"),
    ],
)
def test_descriptor_like_query_finds_its_entry(
    retriever: KnowledgeRetriever, kb: KnowledgeBase, attributes: tuple[str, str, str, str]
) -> None:
    crop, variety, stage, season = attributes
    key = kb.hierarchy.key(crop, variety, stage, season, "Healthy")
    query = f"{crop} {variety} ({key.category}), {stage} stage in {season}, Healthy."
    assert retriever.search(query, k=1)[0].entry.key == key


def test_hits_are_ranked_best_first(retriever: KnowledgeRetriever) -> None:
    hits = retriever.search("a young orchard of Conference pears in spring", k=8)
    assert [hit.rank for hit in hits] == list(range(1, 9))
    scores = [hit.score for hit in hits]
    assert scores == sorted(scores, reverse=True)
    assert all(-1.0 <= score <= 1.0 + 1e-5 for score in scores)
    assert hits[0].entry.key.crop == "Pear"
    assert len(retriever.search("pears", k=5000)) == 1584  # k is clipped to the index


def test_strict_filter_keeps_only_matching_metadata(retriever: KnowledgeRetriever) -> None:
    hits = retriever.search_filtered(
        "a flowering pear orchard in spring", k=4, crop="Pear", season="Winter", health="Ill"
    )
    assert len(hits) == 4
    assert {(h.entry.key.crop, h.entry.key.season, h.entry.key.health) for h in hits} == {
        ("Pear", "Winter", "Ill")
    }
    assert [hit.rank for hit in hits] == [1, 2, 3, 4]
    assert [hit.score for hit in hits] == sorted((hit.score for hit in hits), reverse=True)


def test_strict_filter_returns_fewer_hits_when_the_pool_lacks_matches(
    retriever: KnowledgeRetriever, kb: KnowledgeBase
) -> None:
    # The paper's failure mode: a query about apples, metadata saying wheat.
    query = "Apple Gala (Fruits), Reproductive stage in Spring, Healthy."
    assert retriever.search_filtered(query, k=3, crop="Wheat", pool=20) == []
    key = kb.hierarchy.key("Apple", "Gala", "Reproductive", "Spring", "Healthy")
    every_attribute = retriever.search_filtered(
        query,
        k=3,
        crop="Apple",
        variety="Gala",
        stage="Reproductive",
        season="Spring",
        health="Healthy",
    )
    assert [hit.entry.key for hit in every_attribute] == [key]


def test_exact_is_the_structured_lookup(retriever: KnowledgeRetriever, kb: KnowledgeBase) -> None:
    key = kb.hierarchy.key("Maize", "Sweet Corn", "Maturation", "Summer", "Ill")
    assert retriever.exact(key) == kb.lookup(key)


@pytest.mark.parametrize(
    ("filters", "fragment"),
    [
        ({"stage": "Flowering"}, "accepted: Vegetative, Reproductive, Maturation"),
        ({"crop": "Aple"}, "'Aple' is not a crop"),
        ({"variety": "Honeycrisp"}, "'Honeycrisp' is not a variety"),
        ({"season": "Autumn"}, "accepted: Spring, Summer, Fall, Winter"),
    ],
)
def test_filters_are_checked(
    retriever: KnowledgeRetriever, filters: dict[str, str], fragment: str
) -> None:
    with pytest.raises(HierarchyError) as caught:
        retriever.search_filtered("apples", **filters)
    assert fragment in str(caught.value)


def test_bad_arguments(retriever: KnowledgeRetriever) -> None:
    with pytest.raises(PromptError, match="query is empty"):
        retriever.search("   ")
    with pytest.raises(ConfigurationError, match="k must be a positive integer"):
        retriever.search("apples", k=0)
    with pytest.raises(ConfigurationError, match="pool=2 is smaller than k=3"):
        retriever.search_filtered("apples", k=3, pool=2)


def test_vectors_are_cached_by_model_and_knowledge(
    retriever: KnowledgeRetriever, kb: KnowledgeBase
) -> None:
    counting = CountingEmbedder(retriever.embedder)
    again = KnowledgeRetriever(kb, counting, progress=False)
    assert "not indexed yet" in repr(again)
    assert counting.texts_encoded == 0  # nothing loads before the first search
    assert len(again.index) == 1584
    assert counting.texts_encoded == 0  # read from the cache, not re-embedded
    cached = list((cache_dir() / "indexes").glob(f"knowledge-{kb.digest()}-{counting.model_id}-*"))
    assert len(cached) == 1
    assert again.search("apples", k=1)[0].entry.key.crop == "Apple"
    assert counting.texts_encoded == 1


def test_faiss_failures_become_model_errors(
    retriever: KnowledgeRetriever, monkeypatch: pytest.MonkeyPatch
) -> None:
    def broken(queries: object, k: int) -> None:
        raise RuntimeError("Error in faiss::IndexFlat::search: out of memory")

    monkeypatch.setattr(retriever.index, "search", broken)
    with pytest.raises(ModelError, match=r"FAISS search failed: .*out of memory"):
        retriever.search("apples")


def test_an_embedder_that_changed_shape_is_a_model_error(
    retriever: KnowledgeRetriever, kb: KnowledgeBase
) -> None:
    shrunk = CountingEmbedder(retriever.embedder, keep_dimensions=16)
    mismatched = KnowledgeRetriever(kb, shrunk, progress=False)
    mismatched._index = retriever.index  # the cache of the full model
    with pytest.raises(ModelError, match="holds 384-dimensional vectors"):
        mismatched.search("apples")
