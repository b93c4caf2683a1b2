"""Fine-tuning the default GGUF model: a LoRA adapter trained on CPU from the project's data.

``agrirecipe finetune -o DIR`` builds training examples from the development
prompts (:func:`build_examples`: each prompt with the record the llm strategy
should write for its ground truth), trains a LoRA adapter over the Gemma 3 270M
weights read from the GGUF (:func:`train`), and writes it as a llama.cpp LoRA
GGUF (:func:`export_lora_gguf`) that llama-cpp-python loads over the same base
model for the "finetuned" strategy. Settings live in ``settings.yaml``.

The modules:

- ``_settings``: :class:`FinetuneSettings` and :func:`load_settings` (YAML).
- ``_examples``: training examples and the seeded train / held-out split.
- ``_base``: the base model read from the GGUF by transformers, cached as float weights.
- ``_train``: the training loop (peft LoRA, AdamW, progress bar, checkpoints, resume).
- ``_export``: the llama.cpp LoRA GGUF writer and reader.
- ``_strategy``: the "finetuned" resolver strategy.

transformers, peft and gguf are imported only inside the functions that need
them (``pip install 'agrirecipe[finetune]'``).
"""

from __future__ import annotations

from agrirecipe.finetune._base import BaseModel, load_base_model
from agrirecipe.finetune._examples import (
    ExampleSet,
    TrainingExample,
    build_examples,
    split_examples,
    write_examples,
)
from agrirecipe.finetune._export import AdapterInfo, export_lora_gguf, lora_weights, read_adapter
from agrirecipe.finetune._settings import (
    DEFAULT_SETTINGS_PATH,
    FinetuneSettings,
    load_settings,
)
from agrirecipe.finetune._strategy import FinetunedResolver, default_adapter_path
from agrirecipe.finetune._train import TrainingResult, encode_examples, train

__all__ = [
    "DEFAULT_SETTINGS_PATH",
    "AdapterInfo",
    "BaseModel",
    "ExampleSet",
    "FinetuneSettings",
    "FinetunedResolver",
    "TrainingExample",
    "TrainingResult",
    "build_examples",
    "default_adapter_path",
    "encode_examples",
    "export_lora_gguf",
    "load_base_model",
    "load_settings",
    "lora_weights",
    "read_adapter",
    "split_examples",
    "train",
    "write_examples",
]
