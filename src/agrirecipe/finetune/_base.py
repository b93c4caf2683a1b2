"""The base model for training: the default GGUF read by transformers, cached as float weights.

transformers reads Gemma 3 GGUF files itself (``from_pretrained(folder,
gguf_file=...)``), dequantising Q4_K_M to float32; checked against llama.cpp on
the same tokens: identical tokenization, the same top-5 next tokens, logits
within 0.84 (correlation 0.9995; the rest is llama.cpp's quantised matmuls).
That read takes about a minute on 2 cores (most of it parsing the 262,144-token
vocabulary), so the result is saved once as safetensors in agrirecipe's cache
folder, keyed by the GGUF's SHA-256, and later runs load it in seconds.
"""

from __future__ import annotations

import hashlib
import os
import shutil
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from agrirecipe._errors import ModelError
from agrirecipe.localmodels import cache_dir, default_gguf_path

__all__ = ["BaseModel", "file_sha256", "load_base_model"]


@dataclass(frozen=True, slots=True)
class BaseModel:
    """The float base model, its tokenizer and the GGUF it came from."""

    model: Any  # transformers Gemma3ForCausalLM
    tokenizer: Any
    gguf_path: Path
    gguf_sha256: str


def file_sha256(path: Path) -> str:
    """SHA-256 of a file, read in chunks."""
    digest = hashlib.sha256()
    with path.open("rb") as handle:
        for chunk in iter(lambda: handle.read(1 << 22), b""):
            digest.update(chunk)
    return digest.hexdigest()


def load_base_model(gguf_path: str | Path | None = None) -> BaseModel:
    """The base model for training (default: the GGUF the llm strategy uses)."""
    import torch
    from transformers import AutoModelForCausalLM, AutoTokenizer

    path = Path(gguf_path) if gguf_path is not None else default_gguf_path()
    if not path.is_file():
        raise ModelError(f"GGUF model {str(path)!r} does not exist", stage="finetune")
    sha = file_sha256(path)
    folder = cache_dir() / "finetune" / f"base-{sha[:16]}"
    if not (folder / "model.safetensors").is_file():
        _convert(path, folder)
    try:
        model = AutoModelForCausalLM.from_pretrained(
            folder, dtype=torch.float32, local_files_only=True
        )
        tokenizer = AutoTokenizer.from_pretrained(folder, local_files_only=True)
    except (OSError, ValueError) as exc:
        raise ModelError(
            f"cannot load the converted base model in {str(folder)!r}: {exc}",
            stage="finetune",
            hint=f"delete {folder} to convert the GGUF again",
        ) from exc
    return BaseModel(model=model, tokenizer=tokenizer, gguf_path=path, gguf_sha256=sha)


def _convert(path: Path, folder: Path) -> None:
    """Dequantise ``path`` with transformers and save it as float32 safetensors in ``folder``."""
    import torch
    from safetensors.torch import save_file
    from transformers import AutoModelForCausalLM, AutoTokenizer

    partial = folder.with_name(f"{folder.name}.{os.getpid()}.partial")
    shutil.rmtree(partial, ignore_errors=True)
    partial.mkdir(parents=True)
    try:
        tokenizer = AutoTokenizer.from_pretrained(path.parent, gguf_file=path.name)
        model = AutoModelForCausalLM.from_pretrained(
            path.parent, gguf_file=path.name, dtype=torch.float32
        )
    except (OSError, ValueError, KeyError) as exc:
        shutil.rmtree(partial, ignore_errors=True)
        raise ModelError(
            f"transformers cannot read {str(path)!r}: {exc}",
            stage="finetune",
            hint="fine-tuning needs a GGUF architecture transformers can load (Gemma 3 can)",
        ) from exc
    tokenizer.save_pretrained(partial)
    config = model.config
    if hasattr(config, "quantization_config"):
        del config.quantization_config  # the saved weights are plain float32
    config.save_pretrained(partial)
    tied = bool(getattr(config, "tie_word_embeddings", False))
    state = {
        name: tensor.contiguous()
        for name, tensor in model.state_dict().items()
        if not (tied and name == "lm_head.weight")
    }
    save_file(state, str(partial / "model.safetensors"), metadata={"format": "pt"})
    shutil.rmtree(folder, ignore_errors=True)
    partial.replace(folder)
