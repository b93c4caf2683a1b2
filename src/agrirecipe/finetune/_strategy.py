"""The "finetuned" strategy: the llm strategy with a LoRA adapter over the same GGUF model.

Everything the llm strategy does stays (retrieval, narrowing, every answer
under a grammar, the deterministic checks); only the model changes: llama.cpp
loads the base GGUF with the adapter applied (``Llama(lora_path=...)``), the
record starts without the few-shot document, and each question reads only the
lines it depends on (the request, then its part's lines, or the parts' words
before the relations line), because the adapter was trained on those local
records (:mod:`agrirecipe.finetune._examples`). Both make a prompt far shorter
to evaluate: evaluating the record is nearly all of the strategy's time.

The adapter is, in order: the ``adapter`` argument, ``AGRIRECIPE_LORA``, the
``finetuned`` entry of ``models/manifest.yaml`` (checked against its SHA-256).
"""

from __future__ import annotations

import functools
import os
from pathlib import Path
from typing import TYPE_CHECKING, Any

import yaml

from agrirecipe._errors import ModelError
from agrirecipe.resolve.llm import LlmResolver

if TYPE_CHECKING:
    from agrirecipe.localmodels import LanguageModel

__all__ = ["FinetunedResolver", "default_adapter_path"]

_TRAIN_HINT = (
    "train one with `agrirecipe finetune -o runs/lora` (docs/FINETUNE.md), then pass "
    "FinetunedResolver(adapter='runs/lora/adapter.gguf') or set AGRIRECIPE_LORA to it"
)


def default_adapter_path() -> Path:
    """``AGRIRECIPE_LORA`` if set, else the adapter ``models/manifest.yaml`` ships."""
    from agrirecipe._resources import data_path
    from agrirecipe.finetune._base import file_sha256

    configured = os.environ.get("AGRIRECIPE_LORA")
    if configured:
        return Path(configured)
    try:
        folder = data_path("models")
        manifest: Any = yaml.safe_load((folder / "manifest.yaml").read_text(encoding="utf-8"))
    except (FileNotFoundError, OSError, yaml.YAMLError) as exc:
        raise ModelError(
            f"cannot read models/manifest.yaml: {exc}", stage="llm", hint=_TRAIN_HINT
        ) from exc
    entry = manifest.get("finetuned") if isinstance(manifest, dict) else None
    if not isinstance(entry, dict) or not entry.get("file"):
        raise ModelError(
            "no fine-tuned adapter is configured (models/manifest.yaml has no 'finetuned' entry)",
            stage="llm",
            hint=_TRAIN_HINT,
        )
    path = folder / str(entry["file"])
    if not path.is_file():
        raise ModelError(f"the shipped adapter {str(path)!r} is missing", stage="llm")
    expected = str(entry.get("sha256", ""))
    if expected and file_sha256(path) != expected:
        raise ModelError(
            f"the adapter {str(path)!r} does not match its SHA-256 in models/manifest.yaml",
            stage="llm",
            hint="restore the file or retrain it and update the manifest",
        )
    return path


class FinetunedResolver(LlmResolver):
    """The llm strategy over the default GGUF model with the fine-tuned LoRA adapter.

    ``adapter`` is a llama.cpp LoRA GGUF (default :func:`default_adapter_path`);
    ``model_path`` the base GGUF it was trained on (default: the llm strategy's).
    """

    name = "finetuned"
    local_records = True  # each question reads only its lines, as in training

    def __init__(
        self,
        adapter: str | Path | None = None,
        *,
        model_path: str | Path | None = None,
        narrow: bool = True,
    ) -> None:
        super().__init__(None, narrow=narrow)
        self._adapter_arg = Path(adapter) if adapter is not None else None
        self._model_path = Path(model_path) if model_path is not None else None
        self._tuned: LanguageModel | None = None

    @property
    def model(self) -> LanguageModel:
        """The base GGUF with the adapter (created on first use; weights load on the first call)."""
        with self._lock:
            if self._tuned is None:
                from agrirecipe.localmodels import LlamaCppModel, default_gguf_path

                adapter = self._adapter_arg or default_adapter_path()
                if not adapter.is_file():
                    raise ModelError(
                        f"LoRA adapter {str(adapter)!r} does not exist",
                        stage="llm",
                        hint=_TRAIN_HINT,
                    )
                base = self._model_path or default_gguf_path()
                self._tuned = LlamaCppModel(base, lora_path=adapter)
            return self._tuned

    @functools.cached_property
    def prefix(self) -> str:
        """No few-shot document: the adapter was trained on bare records."""
        return ""
