"""The training loop, smoke-sized: a tiny Gemma 3 with the real loop, export and resume."""

from __future__ import annotations

import math
from pathlib import Path
from types import SimpleNamespace
from typing import Any

import pytest

from agrirecipe import ConfigurationError
from agrirecipe.finetune import (
    ExampleSet,
    FinetuneSettings,
    TrainingExample,
    encode_examples,
    read_adapter,
    train,
)

torch = pytest.importorskip("torch")
pytest.importorskip("peft")
pytest.importorskip("gguf")

EXAMPLES = ExampleSet(
    examples=(
        TrainingExample(
            "a-1",
            "Request: ripe apples\n",
            "Parts: ripe apples\nPart 1: ripe apples\nCount: 1\nCrop: Apple\nStage: Maturation\n\n",
        ),
        TrainingExample(
            "a-2",
            "Request: young carrots\n",
            "Parts: young carrots\nPart 1: young "
            "carrots\nCount: 1\nCrop: Carrot\nStage: Vegetative\n\n",
        ),
        TrainingExample(
            "a-3",
            "Request: pears in bloom\n",
            "Parts: pears in bloom\nPart 1: pears "
            "in bloom\nCount: 1\nCrop: Pear\nStage: Reproductive\n\n",
        ),
    ),
    skipped={},
)


class CharTokenizer:
    """A byte-level stand-in for the Gemma tokenizer (start-of-text 2, padding 0)."""

    pad_token_id = 0

    def __call__(self, text: str, add_special_tokens: bool = True) -> dict[str, list[int]]:
        ids = [3 + byte for byte in text.encode("utf-8")]
        return {"input_ids": ([2] if add_special_tokens else []) + ids}


def _tiny_base() -> Any:
    from transformers import Gemma3ForCausalLM, Gemma3TextConfig

    torch.manual_seed(0)
    config = Gemma3TextConfig(
        vocab_size=260,
        hidden_size=32,
        intermediate_size=64,
        num_hidden_layers=2,
        num_attention_heads=2,
        num_key_value_heads=1,
        head_dim=16,
        layer_types=["sliding_attention", "full_attention"],
        sliding_window=64,
        max_position_embeddings=512,
    )
    return SimpleNamespace(
        model=Gemma3ForCausalLM(config),
        tokenizer=CharTokenizer(),
        gguf_path=Path("tiny.gguf"),
        gguf_sha256="0" * 64,
    )


def _settings(**train_values: Any) -> FinetuneSettings:
    values = {"epochs": 3, "batch_size": 2, "learning_rate": 5e-3, "warmup_steps": 0}
    values |= {"threads": 1, "checkpoint_every": 1, **train_values}
    return FinetuneSettings.model_validate(
        {
            "seed": 0,
            "data": {"heldout_fraction": 0.34, "max_tokens": 512},
            "lora": {"rank": 4, "alpha": 8, "dropout": 0.0, "targets": ["q_proj", "up_proj"]},
            "train": values,
        }
    )


def test_only_the_asked_values_carry_a_loss() -> None:
    (encoded,), too_long = encode_examples(EXAMPLES.examples[:1], CharTokenizer(), max_tokens=512)
    assert too_long == 0
    learnt = bytes(t - 3 for t in encoded.labels if t != -100).decode()
    assert learnt == " 1\n Apple\n Maturation\n"
    assert encoded.input_ids[0] == 2
    _, too_long = encode_examples(EXAMPLES.examples, CharTokenizer(), max_tokens=40)
    assert too_long == 3


def test_smoke_run_trains_exports_and_records(tmp_path: Path) -> None:
    result = train(
        tmp_path, settings=_settings(), examples=EXAMPLES, base=_tiny_base(), progress=False
    )
    record = result.record
    losses = record["step_losses"]
    assert record["steps"] == record["steps_planned"] == 3  # 2 training examples, batch 2
    assert all(math.isfinite(value) for value in losses)
    assert losses[-1] < losses[0]
    assert [epoch["epoch"] for epoch in record["epochs"]] == [1, 2, 3]
    assert record["data"] == {
        "source": "benchmarks/prompts.yaml (dev split)",
        "records": "local",
        "digest": EXAMPLES.digest,
        "prompts": 3,
        "examples": 3,
        "train": 2,
        "heldout": 1,
        "too_long": 0,
        "skipped": {},
        "heldout_ids": record["data"]["heldout_ids"],
    }
    assert 0.0 <= record["epochs"][-1]["heldout"]["line_accuracy"] <= 1.0
    assert record["versions"]["peft"] and record["seed"] == 0

    adapter = read_adapter(result.adapter_path)
    assert (adapter.general_type, adapter.adapter_type) == ("adapter", "lora")
    assert adapter.architecture == "gemma3"
    assert adapter.alpha == 8.0
    assert adapter.tensors == {
        f"blk.{layer}.{name}.weight.lora_{part}": shape
        for layer in (0, 1)
        for name, (a_shape, b_shape) in {
            "attn_q": ((4, 32), (32, 4)),
            "ffn_up": ((4, 32), (64, 4)),
        }.items()
        for part, shape in (("a", a_shape), ("b", b_shape))
    }
    assert adapter.record["step_losses"] == losses
    assert adapter.record["data"]["digest"] == EXAMPLES.digest


def test_resume_ends_with_the_same_adapter(tmp_path: Path) -> None:
    import gguf

    whole = train(
        tmp_path / "whole",
        settings=_settings(),
        examples=EXAMPLES,
        base=_tiny_base(),
        progress=False,
    )
    train(
        tmp_path / "split",
        settings=_settings(),
        examples=EXAMPLES,
        base=_tiny_base(),
        max_steps=2,
        progress=False,
    )
    resumed = train(
        tmp_path / "split",
        settings=_settings(),
        examples=EXAMPLES,
        base=_tiny_base(),
        resume=True,
        progress=False,
    )
    assert resumed.record["step_losses"] == whole.record["step_losses"]
    first = {t.name: t.data.tobytes() for t in gguf.GGUFReader(whole.adapter_path).tensors}
    second = {t.name: t.data.tobytes() for t in gguf.GGUFReader(resumed.adapter_path).tensors}
    assert first == second


def test_resume_with_other_settings_is_refused(tmp_path: Path) -> None:
    train(
        tmp_path,
        settings=_settings(),
        examples=EXAMPLES,
        base=_tiny_base(),
        max_steps=1,
        progress=False,
    )
    with pytest.raises(ConfigurationError, match="other training data or settings"):
        train(
            tmp_path,
            settings=_settings(learning_rate=1e-3),
            examples=EXAMPLES,
            base=_tiny_base(),
            resume=True,
            progress=False,
        )


def test_resume_without_a_checkpoint_is_a_clear_error(tmp_path: Path) -> None:
    with pytest.raises(ConfigurationError, match="nothing to resume"):
        train(tmp_path, settings=_settings(), examples=EXAMPLES, base=_tiny_base(), resume=True)
