"""Held-out accuracy of the base model before any fine-tuning (the "epoch 0" point).

Builds the same examples and the same seeded split as ``agrirecipe finetune``
(settings.yaml), and scores the held-out records on the base Gemma 3 model with
no LoRA, with the metric the training loop reports at each epoch's end
(token accuracy, line accuracy, loss on the answered values). Compare with the
per-epoch numbers in the adapter's training record (docs/finetune-training.json).

    python bench/bench_finetune_baseline.py [--record docs/finetune-training.json]
"""

from __future__ import annotations

import argparse
import json
import os
import time
from pathlib import Path


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--record", type=Path, default=Path("docs/finetune-training.json"))
    args = parser.parse_args()
    os.environ.setdefault("HF_HUB_OFFLINE", "1")

    import torch

    from agrirecipe.finetune import build_examples, load_base_model, load_settings, split_examples
    from agrirecipe.finetune._train import _evaluate, encode_examples

    settings = load_settings()
    torch.set_num_threads(max(1, min(os.cpu_count() or 1, 8)))
    examples = build_examples(limit=settings.data.max_prompts, seed=settings.seed)
    _, heldout = split_examples(
        examples.examples, heldout_fraction=settings.data.heldout_fraction, seed=settings.seed
    )
    base = load_base_model()
    items, _ = encode_examples(heldout, base.tokenizer, max_tokens=settings.data.max_tokens)
    pad_id = int(base.tokenizer.pad_token_id or 0)
    newline = int(base.tokenizer("\n", add_special_tokens=False)["input_ids"][-1])
    from peft import LoraConfig, get_peft_model

    lora = settings.lora
    # LoRA's B matrices start at zero: this model answers exactly as the base model,
    # and is what the training loop evaluates (a PEFT model)
    model = get_peft_model(
        base.model,
        LoraConfig(
            r=lora.rank,
            lora_alpha=lora.alpha,
            target_modules=list(lora.targets),
            bias="none",
            task_type="CAUSAL_LM",
        ),
    )
    model.eval()
    started = time.perf_counter()
    metrics = _evaluate(model, items, pad_id, newline)
    print(f"data digest {examples.digest}, {len(items)} held-out records")
    print("epoch 0 (base model):", json.dumps(metrics), f"({time.perf_counter() - started:.0f} s)")
    if args.record.is_file():
        record = json.loads(args.record.read_text(encoding="utf-8"))
        if record["data"]["digest"] != examples.digest:
            print("note: the record was trained on other data (digest differs)")
        for epoch in record["epochs"]:
            print(f"epoch {epoch['epoch']}:", json.dumps(epoch["heldout"]))


if __name__ == "__main__":
    main()
