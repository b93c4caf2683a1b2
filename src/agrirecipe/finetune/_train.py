"""The LoRA training loop: seeded, on CPU, with a progress bar, checkpoints and resume.

Tools: **transformers** runs the Gemma 3 model in PyTorch (read from the GGUF,
:mod:`._base`); **peft** wraps its linear projections with LoRA matrices and
freezes everything else; **torch** does the optimisation (AdamW, linear
warm-up then linear decay); **tqdm** draws the progress bar with its ETA. The
adapter is written for llama.cpp by :mod:`._export` (the ``gguf`` package).

The loss is next-token cross-entropy on the record's lines only (the request
line is context). Logits are computed only at those positions: Gemma 3's
output layer is as large as the rest of the 270M model (262,144 x 640), so
skipping it at the ~30% of positions that carry no loss saves real time.

A run is reproducible: examples, split, initial LoRA weights, batch order and
dropout all follow ``settings.seed``. Every ``checkpoint_every`` steps the LoRA
weights, optimiser, schedule, RNG state and losses are saved to
``<output>/checkpoint.pt``; ``resume=True`` continues from there and ends with
the same adapter as an uninterrupted run.
"""

from __future__ import annotations

import json
import math
import os
import platform
import random
import time
from collections.abc import Sequence
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from agrirecipe._errors import ConfigurationError
from agrirecipe.finetune._examples import ExampleSet, TrainingExample, split_examples
from agrirecipe.finetune._settings import FinetuneSettings

__all__ = ["Batch", "TrainingResult", "encode_examples", "train"]

CHECKPOINT = "checkpoint.pt"
ADAPTER = "adapter.gguf"
RECORD = "training.json"
_IGNORE = -100


@dataclass(frozen=True, slots=True)
class _Encoded:
    prompt_id: str
    input_ids: list[int]
    labels: list[int]  # -100 where there is no loss (the request line)


@dataclass(frozen=True, slots=True)
class Batch:
    """Right-padded token ids, attention mask and labels of a few examples."""

    input_ids: Any
    attention_mask: Any
    labels: Any


@dataclass(slots=True)
class TrainingResult:
    """What a run produced: the adapter, its record, and the losses."""

    adapter_path: Path
    record_path: Path
    record: dict[str, Any] = field(default_factory=dict)


def encode_examples(
    examples: Sequence[TrainingExample], tokenizer: Any, *, max_tokens: int
) -> tuple[list[_Encoded], int]:
    """Token ids and labels of each example; the number skipped for being longer than
    ``max_tokens``.

    The text is tokenized the way the strategy's calls see it: the record up to
    a line's label (``...Crop:``) is the prompt, the value (`` Apple\n``) is
    the answer. Only the values of the lines the model can be asked carry a
    loss (the relations line among them); the request, the labels and the
    ``Parts`` / ``Part N`` lines, which the strategy writes itself when no
    boundary is open, are context.
    """
    encoded: list[_Encoded] = []
    too_long = 0
    for example in examples:
        ids = list(tokenizer(example.context, add_special_tokens=True)["input_ids"])
        labels = [_IGNORE] * len(ids)
        for line in example.target.splitlines(keepends=True):
            label, colon, value = line.partition(":")
            if not colon:
                continue  # the blank line that ends a record
            head = tokenizer(label + colon, add_special_tokens=False)["input_ids"]
            tail = tokenizer(value, add_special_tokens=False)["input_ids"]
            asked = label != "Parts" and not label.startswith("Part ")
            ids += head + tail
            labels += [_IGNORE] * len(head) + (tail if asked else [_IGNORE] * len(tail))
        if len(ids) > max_tokens:
            too_long += 1
            continue
        encoded.append(_Encoded(example.prompt_id, ids, labels))
    return encoded, too_long


def _collate(items: Sequence[_Encoded], pad_id: int) -> Batch:
    import torch

    width = max(len(item.input_ids) for item in items)
    ids = torch.full((len(items), width), pad_id, dtype=torch.long)
    mask = torch.zeros((len(items), width), dtype=torch.long)
    labels = torch.full((len(items), width), _IGNORE, dtype=torch.long)
    for row, item in enumerate(items):
        size = len(item.input_ids)
        ids[row, :size] = torch.tensor(item.input_ids)
        mask[row, :size] = 1
        labels[row, :size] = torch.tensor(item.labels)
    return Batch(ids, mask, labels)


def _loss_and_hits(model: Any, batch: Batch) -> tuple[Any, Any, Any]:
    """Mean cross-entropy over labelled positions, and per-position argmax hits and targets."""
    from torch.nn import functional

    causal = model.get_base_model()
    hidden = causal.model(
        input_ids=batch.input_ids, attention_mask=batch.attention_mask
    ).last_hidden_state
    targets = batch.labels[:, 1:]
    chosen = targets != _IGNORE
    states = hidden[:, :-1][chosen]
    logits = causal.lm_head(states)
    cap = getattr(causal.config, "final_logit_softcapping", None)
    if cap:
        logits = (logits / cap).tanh() * cap
    gold = targets[chosen]
    loss = functional.cross_entropy(logits.float(), gold)
    return loss, logits.argmax(dim=-1) == gold, gold


def _evaluate(model: Any, items: Sequence[_Encoded], pad_id: int, newline: int) -> dict[str, float]:
    """Held-out loss, token accuracy and line accuracy (every token of a line right,
    teacher-forced: each line is predicted after the true previous lines)."""
    import torch

    if not items:
        return {}
    model.eval()
    total_loss = 0.0
    tokens = right_tokens = lines = right_lines = 0
    with torch.no_grad():
        for start in range(0, len(items), 8):
            chunk = items[start : start + 8]
            batch = _collate(chunk, pad_id)
            loss, hits, gold = _loss_and_hits(model, batch)
            count = int(gold.numel())
            total_loss += float(loss.detach()) * count
            tokens += count
            right_tokens += int(hits.sum())
            line_ok = True
            for hit, token in zip(hits.tolist(), gold.tolist(), strict=True):
                line_ok = line_ok and hit
                if token == newline:
                    lines += 1
                    right_lines += int(line_ok)
                    line_ok = True
    model.train()
    return {
        "loss": total_loss / max(tokens, 1),
        "token_accuracy": right_tokens / max(tokens, 1),
        "line_accuracy": right_lines / max(lines, 1),
    }


def _schedule(step: int, *, warmup: int, total: int) -> float:
    if step < warmup:
        return (step + 1) / (warmup + 1)
    return max(0.0, (total - step) / max(1, total - warmup))


def _versions() -> dict[str, str]:
    from importlib.metadata import PackageNotFoundError, version

    found = {"python": platform.python_version()}
    for name in ("agrirecipe", "torch", "transformers", "peft", "gguf", "llama-cpp-python"):
        try:
            found[name] = version(name)
        except PackageNotFoundError:
            found[name] = "not installed"
    return found


def train(
    output: str | Path,
    *,
    settings: FinetuneSettings,
    examples: ExampleSet,
    base: Any,
    resume: bool = False,
    max_steps: int | None = None,
    progress: bool = True,
    evaluate: bool = True,
) -> TrainingResult:
    """Train a LoRA adapter on ``examples`` over ``base`` (:func:`load_base_model`'s result).

    Writes ``adapter.gguf`` (llama.cpp LoRA) and ``training.json`` (the record:
    data digest, settings, seed, versions, losses) into ``output``;
    ``max_steps`` stops early (for smoke runs and speed measurements);
    ``evaluate=False`` skips the held-out evaluation (at epoch ends and at the stop).
    """
    import torch
    from peft import (
        LoraConfig,
        get_peft_model,
        get_peft_model_state_dict,
        set_peft_model_state_dict,
    )
    from tqdm.auto import tqdm

    from agrirecipe.finetune._export import export_lora_gguf, lora_weights

    folder = Path(output)
    folder.mkdir(parents=True, exist_ok=True)
    checkpoint_path = folder / CHECKPOINT
    if resume and not checkpoint_path.is_file():
        raise ConfigurationError(
            f"nothing to resume: {checkpoint_path} does not exist",
            stage="finetune",
            hint="run without --resume to start a new training run",
        )
    run = settings.train
    threads = run.threads or max(1, min(os.cpu_count() or 1, 8))
    torch.set_num_threads(threads)
    random.seed(settings.seed)
    torch.manual_seed(settings.seed)

    tokenizer = base.tokenizer
    train_set, heldout_set = split_examples(
        examples.examples, heldout_fraction=settings.data.heldout_fraction, seed=settings.seed
    )
    train_items, long_train = encode_examples(
        train_set, tokenizer, max_tokens=settings.data.max_tokens
    )
    heldout_items, long_heldout = encode_examples(
        heldout_set, tokenizer, max_tokens=settings.data.max_tokens
    )
    if not train_items:
        raise ConfigurationError("no training example fits max_tokens", stage="finetune")
    pad_id = int(tokenizer.pad_token_id or 0)
    newline = int(tokenizer("\n", add_special_tokens=False)["input_ids"][-1])

    lora = settings.lora
    config = LoraConfig(
        r=lora.rank,
        lora_alpha=lora.alpha,
        lora_dropout=lora.dropout,
        target_modules=list(lora.targets),
        layers_to_transform=list(lora.layers) if lora.layers is not None else None,
        bias="none",
        task_type="CAUSAL_LM",
    )
    model = get_peft_model(base.model, config)
    model.train()
    trainable = [p for p in model.parameters() if p.requires_grad]
    optimizer = torch.optim.AdamW(trainable, lr=run.learning_rate, weight_decay=run.weight_decay)
    per_epoch = math.ceil(len(train_items) / run.batch_size)
    total = per_epoch * run.epochs
    scheduler = torch.optim.lr_scheduler.LambdaLR(
        optimizer, lambda step: _schedule(step, warmup=run.warmup_steps, total=total)
    )
    step = 0
    step_losses: list[float] = []
    epochs: list[dict[str, Any]] = []
    seconds = 0.0
    # what must not change between a checkpoint and its resumption (threads may)
    fingerprint = {
        "digest": examples.digest,
        "settings": settings.model_dump(mode="json", exclude={"train": {"threads"}}),
    }
    if resume:
        state = torch.load(checkpoint_path, weights_only=False)
        if state.get("fingerprint") != fingerprint:
            raise ConfigurationError(
                f"{checkpoint_path} was made with other training data or settings",
                stage="finetune",
                hint="resume with the same settings, or start a new run in another folder",
            )
        set_peft_model_state_dict(model, state["lora"])
        optimizer.load_state_dict(state["optimizer"])
        scheduler.load_state_dict(state["scheduler"])
        torch.set_rng_state(state["torch_rng"])
        step, step_losses, epochs = state["step"], state["losses"], state["epochs"]
        seconds = state.get("seconds", 0.0)

    def save_checkpoint() -> None:
        partial = checkpoint_path.with_suffix(".partial")
        torch.save(
            {
                "step": step,
                "fingerprint": fingerprint,
                "lora": get_peft_model_state_dict(model),
                "optimizer": optimizer.state_dict(),
                "scheduler": scheduler.state_dict(),
                "torch_rng": torch.get_rng_state(),
                "losses": step_losses,
                "epochs": epochs,
                "seconds": seconds,
            },
            partial,
        )
        partial.replace(checkpoint_path)

    stop = min(total, max_steps) if max_steps is not None else total
    bar = tqdm(total=stop, initial=step, disable=not progress, desc="finetune", unit="step")
    while step < stop:
        epoch, index = divmod(step, per_epoch)
        order = list(range(len(train_items)))
        random.Random(settings.seed * 1000 + epoch).shuffle(order)
        chosen = order[index * run.batch_size : (index + 1) * run.batch_size]
        started = time.perf_counter()
        loss, _, _ = _loss_and_hits(model, _collate([train_items[i] for i in chosen], pad_id))
        loss.backward()
        value = float(loss.detach())
        optimizer.step()
        scheduler.step()
        optimizer.zero_grad(set_to_none=True)
        seconds += time.perf_counter() - started
        step += 1
        step_losses.append(value)
        bar.update(1)
        bar.set_postfix(loss=f"{value:.3f}", epoch=epoch + 1)
        if step % per_epoch == 0:
            done = step // per_epoch
            first = (done - 1) * per_epoch
            epochs.append(
                {
                    "epoch": done,
                    "train_loss": sum(step_losses[first:step]) / per_epoch,
                    "heldout": _evaluate(model, heldout_items, pad_id, newline) if evaluate else {},
                }
            )
        if step % run.checkpoint_every == 0 or step == stop:
            save_checkpoint()
    bar.close()

    record = {
        "base_gguf": base.gguf_path.name,
        "base_sha256": base.gguf_sha256,
        "data": {
            "source": "benchmarks/prompts.yaml (dev split)",
            # each question reads only its lines (resolve.llm._LocalRecord, render_local)
            "records": "local",
            "digest": examples.digest,
            "prompts": examples.prompts,
            "examples": len(examples.examples),
            "train": len(train_items),
            "heldout": len(heldout_items),
            "too_long": long_train + long_heldout,
            "skipped": examples.skipped,
            "heldout_ids": sorted({item.prompt_id for item in heldout_items}),
        },
        "settings": settings.model_dump(mode="json"),
        "seed": settings.seed,
        "threads": threads,
        "versions": _versions(),
        "steps": step,
        "steps_planned": total,
        "seconds_training": round(seconds, 1),
        "seconds_per_step": round(seconds / max(step, 1), 3),
        "step_losses": [round(value, 4) for value in step_losses],
        "epochs": epochs,
    }
    if evaluate and step < total and not epochs:
        record["heldout_at_stop"] = _evaluate(model, heldout_items, pad_id, newline)
    adapter = export_lora_gguf(
        lora_weights(model),
        folder / ADAPTER,
        alpha=lora.alpha,
        n_layers=int(base.model.config.num_hidden_layers),
        architecture=_architecture(base.model.config),
        record=record,
    )
    record_path = folder / RECORD
    record_path.write_text(json.dumps(record, indent=2, sort_keys=True) + "\n", encoding="utf-8")
    model.unload()  # give the base model back without the LoRA layers
    return TrainingResult(adapter_path=adapter, record_path=record_path, record=record)


def _architecture(config: Any) -> str:
    """The GGUF architecture name of a transformers config (``gemma3_text`` -> ``gemma3``)."""
    model_type = str(getattr(config, "model_type", ""))
    return {"gemma3_text": "gemma3", "gemma3": "gemma3"}.get(model_type, model_type)
