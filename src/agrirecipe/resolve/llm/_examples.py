"""Few-shot examples of the llm strategy and the document rendered from them."""

from __future__ import annotations

import functools
import re
from collections.abc import Mapping, Sequence
from pathlib import Path
from typing import Any

import yaml

from agrirecipe._errors import ConfigurationError
from agrirecipe.resolve._grammar import ANY_PREFIX, NONE, OTHER, prompt_words

__all__ = ["DATA_DIR", "load_examples", "render_examples", "render_local"]

DATA_DIR = Path(__file__).resolve().parent.parent / "data" / "llm"
_STATE_KEYS = ("stage", "season", "health")


# --- few-shot examples -----------------------------------------------------------


@functools.lru_cache(maxsize=4)
def load_examples(path: str | Path | None = None) -> tuple[dict[str, Any], ...]:
    """The few-shot examples (``data/llm/fewshot.yaml`` unless ``path`` is given)."""
    source = Path(path) if path is not None else DATA_DIR / "fewshot.yaml"
    try:
        data = yaml.safe_load(source.read_text(encoding="utf-8"))
    except (OSError, yaml.YAMLError) as exc:
        raise ConfigurationError(
            f"cannot read the llm few-shot examples {str(source)!r}: {exc}", stage="llm"
        ) from exc
    examples = data.get("examples") if isinstance(data, dict) else None
    if not isinstance(examples, list) or not examples:
        raise ConfigurationError(
            f"{str(source)!r} holds no 'examples' list",
            stage="llm",
            hint="see agrirecipe/resolve/data/llm/fewshot.yaml for the format",
        )
    return tuple(examples)


def _words_text(text: str) -> str:
    return " ".join(prompt_words(text))


def _part_block(index: int, part: Mapping[str, Any], suffix: str = "") -> str:
    """The record of one part, line for line as :class:`LlmResolver` writes it."""
    text = _words_text(str(part["text"]))
    crop = str(part["crop"])
    lines = [f"Part {index}: {text}{suffix}", f"Count: {part.get('count', 1)}", f"Crop: {crop}"]
    if crop == OTHER:
        lines.append(f"Name: {part['name']}")
        return "\n".join(lines) + "\n"
    if crop.startswith(ANY_PREFIX):
        lines.append(f"Different: {part.get('different', 'no')}")
    else:
        lines.append(f"Variety: {part.get('variety', NONE)}")
    lines += [f"{key.capitalize()}: {part.get(key, NONE)}" for key in _STATE_KEYS]
    if re.search(r"\d", text):
        lines.append(f"Size: {part.get('size', NONE)}")
    return "\n".join(lines) + "\n"


def render_examples(examples: Sequence[Mapping[str, Any]]) -> str:
    """The few-shot document: one record per example, a blank line after each."""
    blocks = []
    for example in examples:
        lines = [f"Request: {example['request']}\n"]
        parts = example["parts"]
        if parts == NONE:
            lines.append(f"Parts: {NONE}\n")
        else:
            lines.append("Parts: " + " | ".join(_words_text(str(p["text"])) for p in parts) + "\n")
            fields = [part for part in parts if not part.get("shared")]
            suffix = "".join(f" + {_words_text(str(p['text']))}" for p in parts if p.get("shared"))
            lines += [_part_block(i, part, suffix) for i, part in enumerate(fields, start=1)]
            if len(fields) > 1:
                lines.append(f"Relations: {example.get('relations', NONE)}\n")
        blocks.append("".join(lines))
    return "\n".join(blocks) + "\n"


def render_local(example: Mapping[str, Any]) -> list[tuple[str, str]]:
    """One example as the local records the finetuned strategy asks: (context, lines) pairs.

    Each part is the request, then that part's lines; with several parts, the
    relations line follows the request and the parts' own words
    (``_LocalRecord`` in :mod:`agrirecipe.resolve.llm._strategy` asks them so).
    """
    head = f"Request: {example['request']}\n"
    parts = example["parts"]
    if parts == NONE:
        return [(head, f"Parts: {NONE}\n")]
    fields = [part for part in parts if not part.get("shared")]
    suffix = "".join(f" + {_words_text(str(p['text']))}" for p in parts if p.get("shared"))
    records = [(head, _part_block(i, part, suffix)) for i, part in enumerate(fields, start=1)]
    if len(fields) > 1:
        named = "".join(
            f"Part {i}: {_words_text(str(part['text']))}\n"
            for i, part in enumerate(fields, start=1)
        )
        records.append((head, named + f"Relations: {example.get('relations', NONE)}\n"))
    return records


@functools.lru_cache(maxsize=1)
def _choice_prefix() -> str:
    data = yaml.safe_load((DATA_DIR / "choose.yaml").read_text(encoding="utf-8"))
    blocks = [
        f"Question: {ex['question']}\nOptions: {', '.join(ex['options'])}\nAnswer: {ex['answer']}\n"
        for ex in data["examples"]
    ]
    return "\n".join(blocks) + "\n"
