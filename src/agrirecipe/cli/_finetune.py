"""``agrirecipe finetune``: train the LoRA adapter of the "finetuned" strategy on CPU."""

from __future__ import annotations

import argparse
import sys
from pathlib import Path
from typing import Any


def register(subparsers: Any) -> None:
    """Add the ``finetune`` sub-command."""
    parser = subparsers.add_parser(
        "finetune",
        help="train a LoRA adapter for the default GGUF model (CPU)",
        description="Build training examples from benchmarks/prompts.yaml's dev split (each "
        "prompt with the record the llm strategy should write), train a LoRA adapter over "
        "the default GGUF model (Gemma 3 270M) with transformers + peft on the CPU, and write "
        "it as a llama.cpp LoRA GGUF (adapter.gguf) with its training record (training.json). "
        "Seeded and resumable; settings in agrirecipe/finetune/settings.yaml. Needs "
        "pip install 'agrirecipe[finetune]'. See docs/FINETUNE.md.",
    )
    parser.add_argument(
        "-o", "--output", type=Path, required=True, metavar="DIR", help="folder for the run"
    )
    parser.add_argument("--epochs", type=int, default=None, help="override the settings' epochs")
    parser.add_argument(
        "--max-steps", type=int, default=None, help="stop after N optimiser steps (smoke runs)"
    )
    parser.add_argument("--resume", action="store_true", help="continue from DIR/checkpoint.pt")
    parser.add_argument(
        "--settings", type=Path, default=None, help="a settings YAML instead of the shipped one"
    )
    parser.add_argument(
        "--gguf", type=Path, default=None, help="base GGUF (default: the llm strategy's model)"
    )
    parser.add_argument("--threads", type=int, default=None, help="torch CPU threads")
    parser.add_argument("--no-progress", action="store_true", help="no progress bar")
    parser.set_defaults(handler=run)


def run(args: argparse.Namespace) -> int:
    """Train, export the adapter, print where it is."""
    from agrirecipe._errors import ConfigurationError

    if args.max_steps is not None and args.max_steps < 1:
        raise ConfigurationError("--max-steps must be at least 1", stage="finetune")
    if args.epochs is not None and args.epochs < 1:
        raise ConfigurationError("--epochs must be at least 1", stage="finetune")
    try:
        from agrirecipe.finetune import build_examples, load_base_model, load_settings, train
    except ImportError as exc:  # pragma: no cover - depends on the installed extras
        raise ConfigurationError(
            f"fine-tuning needs more packages: {exc}",
            stage="finetune",
            hint="pip install 'agrirecipe[finetune]'",
        ) from exc
    settings = load_settings(args.settings).with_overrides(epochs=args.epochs, threads=args.threads)
    examples = build_examples(limit=settings.data.max_prompts, seed=settings.seed)
    print(
        f"agrirecipe finetune: {len(examples.examples)} examples from {examples.prompts} dev "
        f"prompts ({sum(examples.skipped.values())} others skipped or not read); "
        "loading the base model",
        file=sys.stderr,
    )
    base = load_base_model(args.gguf)
    result = train(
        args.output,
        settings=settings,
        examples=examples,
        base=base,
        resume=args.resume,
        max_steps=args.max_steps,
        progress=not args.no_progress,
    )
    record = result.record
    print(f"adapter: {result.adapter_path}")
    print(f"record:  {result.record_path}")
    print(
        f"steps {record['steps']}/{record['steps_planned']}, "
        f"{record['seconds_per_step']} s/step, last loss {record['step_losses'][-1]}"
    )
    return 0
