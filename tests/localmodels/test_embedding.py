"""The local sentence-transformers embedder and the cached FAISS index, with the real model."""

from __future__ import annotations

from collections.abc import Sequence
from pathlib import Path
from typing import TYPE_CHECKING

import numpy as np
import pytest

from agrirecipe import ConfigurationError
from agrirecipe.localmodels import (
    Embedder,
    SentenceTransformerEmbedder,
    VectorIndex,
    default_embedder,
    default_embedding_model_path,
)

if TYPE_CHECKING:
    from numpy.typing import NDArray

pytestmark = pytest.mark.slow

TEXTS = [
    "a healthy Pink Lady apple orchard in summer",
    "young Nantes carrots on ridges",
    "winter wheat with yellow rust",
    "a vineyard of Pinot Noir at harvest",
    "Cavendish bananas in double rows",
]


class CountingEmbedder:
    def __init__(self, inner: Embedder) -> None:
        self.inner = inner
        self.calls = 0

    @property
    def model_id(self) -> str:
        return self.inner.model_id

    def encode(self, texts: Sequence[str]) -> NDArray[np.float32]:
        self.calls += 1
        return self.inner.encode(texts)


@pytest.fixture(scope="module")
def embedder() -> SentenceTransformerEmbedder:
    """The default model, loaded once for the module (and shared with the process)."""
    return default_embedder()


def test_default_embedder_is_shared() -> None:
    assert default_embedder() is default_embedder()
    assert default_embedder().path == default_embedding_model_path()


def test_model_comes_from_the_installed_package() -> None:
    path = default_embedding_model_path()
    assert (path / "config.json").exists() or (path / "modules.json").exists()


def test_encode_gives_unit_float32_rows(embedder: SentenceTransformerEmbedder) -> None:
    vectors = embedder.encode(TEXTS)
    assert vectors.shape == (5, 384)
    assert vectors.dtype == np.float32
    assert np.allclose(np.linalg.norm(vectors, axis=1), 1.0, atol=1e-5)
    assert np.array_equal(vectors, embedder.encode(TEXTS))  # deterministic
    assert embedder.encode([]).shape == (0, 384)


def test_similar_sentences_are_close(embedder: SentenceTransformerEmbedder) -> None:
    orchard, trees, wheat = embedder.encode(
        ["an apple orchard", "rows of apple trees", "a field of winter wheat"]
    )
    assert float(orchard @ trees) > float(orchard @ wheat) + 0.1


def test_model_id_is_stable(embedder: SentenceTransformerEmbedder) -> None:
    assert embedder.model_id == SentenceTransformerEmbedder(embedder.path).model_id
    assert embedder.model_id.startswith(embedder.path.name + "-")


def test_nothing_loads_until_first_use(tmp_path: Path) -> None:
    lazy = SentenceTransformerEmbedder(tmp_path / "no-model-here")
    assert lazy.model_path == tmp_path / "no-model-here"  # constructing touched nothing
    with pytest.raises(ConfigurationError, match="is not a sentence-transformers model folder"):
        lazy.encode(["apples"])


def test_model_path_from_the_environment(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setenv("AGRIRECIPE_EMBEDDING_MODEL", str(tmp_path))
    assert default_embedding_model_path() == tmp_path


def test_index_is_built_once_and_cached(
    embedder: SentenceTransformerEmbedder, tmp_path: Path
) -> None:
    counting = CountingEmbedder(embedder)
    index = VectorIndex.build(TEXTS, counting, name="test", cache=tmp_path, progress=False)
    assert counting.calls == 1
    files = list((tmp_path / "indexes").glob("test-*.npy"))
    assert len(files) == 1
    again = VectorIndex.build(TEXTS, counting, name="test", cache=tmp_path, progress=False)
    assert counting.calls == 1  # read back from disk
    assert np.array_equal(again.vectors, index.vectors)
    scores, rows = index.search(embedder.encode(["carrots growing on ridges"]), k=2)
    assert rows[0, 0] == 1
    assert scores[0, 0] > scores[0, 1]
    assert index.search(embedder.encode(["x"]), k=50)[1].shape == (1, 5)  # k clipped


def test_changed_texts_get_a_new_cache_entry(
    embedder: SentenceTransformerEmbedder, tmp_path: Path
) -> None:
    VectorIndex.build(TEXTS, embedder, name="test", cache=tmp_path, progress=False)
    VectorIndex.build(TEXTS[:3], embedder, name="test", cache=tmp_path, progress=False)
    assert len(list((tmp_path / "indexes").glob("test-*.npy"))) == 2


def test_a_damaged_cache_file_is_rebuilt(
    embedder: SentenceTransformerEmbedder, tmp_path: Path
) -> None:
    VectorIndex.build(TEXTS, embedder, name="test", cache=tmp_path, progress=False)
    (file,) = (tmp_path / "indexes").glob("test-*.npy")
    file.write_bytes(b"not a numpy file")
    counting = CountingEmbedder(embedder)
    index = VectorIndex.build(TEXTS, counting, name="test", cache=tmp_path, progress=False)
    assert counting.calls == 1
    assert len(index) == 5
    assert np.load(file).shape == (5, 384)
