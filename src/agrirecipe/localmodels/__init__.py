"""Local models: sentence embeddings with a FAISS index, and a GGUF language model.

Everything here loads lazily from local files; nothing is ever downloaded.
"""

from agrirecipe.localmodels._cache import cache_dir
from agrirecipe.localmodels._embedding import (
    Embedder,
    SentenceTransformerEmbedder,
    VectorIndex,
    default_embedder,
    default_embedding_model_path,
)
from agrirecipe.localmodels._llm import (
    LanguageModel,
    LlamaCppModel,
    default_gguf_path,
    default_language_model,
)

__all__ = [
    "Embedder",
    "LanguageModel",
    "LlamaCppModel",
    "SentenceTransformerEmbedder",
    "VectorIndex",
    "cache_dir",
    "default_embedder",
    "default_embedding_model_path",
    "default_gguf_path",
    "default_language_model",
]
