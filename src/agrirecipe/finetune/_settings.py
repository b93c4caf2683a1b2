"""The fine-tuning settings (``settings.yaml`` beside this module, or a file of the same shape)."""

from __future__ import annotations

from pathlib import Path
from typing import Any, Literal

import yaml
from pydantic import BaseModel, ConfigDict, Field, ValidationError

from agrirecipe._errors import ConfigurationError

__all__ = [
    "DEFAULT_SETTINGS_PATH",
    "DataSettings",
    "FinetuneSettings",
    "LoraSettings",
    "TrainSettings",
    "load_settings",
]

DEFAULT_SETTINGS_PATH = Path(__file__).resolve().parent / "settings.yaml"


class _Frozen(BaseModel):
    model_config = ConfigDict(frozen=True, extra="forbid")


class DataSettings(_Frozen):
    """How the training examples are chosen."""

    heldout_fraction: float = Field(default=0.15, ge=0.0, lt=1.0)
    max_tokens: int = Field(default=160, ge=16, le=2048)
    #: Most development prompts to train and hold out on (None: every usable one),
    #: read in an order shuffled by the seed.
    max_prompts: int | None = Field(default=700, ge=1)


class LoraSettings(_Frozen):
    """The LoRA adapter: rank, alpha (scale = alpha / rank), dropout, target modules."""

    rank: int = Field(default=8, ge=1, le=256)
    alpha: int = Field(default=16, ge=1)
    dropout: float = Field(default=0.05, ge=0.0, lt=1.0)
    targets: tuple[str, ...] = Field(
        default=("q_proj", "k_proj", "v_proj", "o_proj", "gate_proj", "up_proj", "down_proj"),
        min_length=1,
    )
    #: Decoder layers that get LoRA matrices (None: all). Backpropagation stops
    #: at the lowest one, so adapting only the upper layers trains faster.
    layers: tuple[int, ...] | None = None


class TrainSettings(_Frozen):
    """The optimisation: epochs, batch, AdamW learning rate, threads, checkpoints."""

    epochs: int = Field(default=2, ge=1, le=100)
    batch_size: int = Field(default=8, ge=1, le=256)
    learning_rate: float = Field(default=2e-4, gt=0)
    weight_decay: float = Field(default=0.0, ge=0)
    warmup_steps: int = Field(default=10, ge=0)
    threads: int = Field(default=0, ge=0, le=256)
    checkpoint_every: int = Field(default=20, ge=1)


class FinetuneSettings(_Frozen):
    """Every setting of a training run (recorded in the adapter's metadata)."""

    version: Literal[1] = 1
    seed: int = 0
    data: DataSettings = DataSettings()
    lora: LoraSettings = LoraSettings()
    train: TrainSettings = TrainSettings()

    def with_overrides(self, **train: Any) -> FinetuneSettings:
        """A copy with some ``train`` values replaced (None values are ignored)."""
        update = {key: value for key, value in train.items() if value is not None}
        if not update:
            return self
        return self.model_copy(update={"train": self.train.model_copy(update=update)})


def load_settings(path: str | Path | None = None) -> FinetuneSettings:
    """The settings in ``path`` (default: the shipped ``settings.yaml``)."""
    source = Path(path) if path is not None else DEFAULT_SETTINGS_PATH
    try:
        raw = yaml.safe_load(source.read_text(encoding="utf-8"))
    except (OSError, yaml.YAMLError) as exc:
        raise ConfigurationError(
            f"cannot read the fine-tuning settings {str(source)!r}: {exc}", stage="finetune"
        ) from exc
    try:
        return FinetuneSettings.model_validate(raw)
    except ValidationError as exc:
        first = exc.errors()[0]
        where = ".".join(str(part) for part in first["loc"])
        raise ConfigurationError(
            f"{str(source)!r}: {where}: {first['msg']}",
            stage="finetune",
            path=where,
            hint=f"see {DEFAULT_SETTINGS_PATH} for the accepted keys",
        ) from exc
