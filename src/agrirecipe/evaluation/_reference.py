"""The numbers we compare against: the seed paper's results and issue 3's targets.

Both live in ``benchmarks/`` (``paper_results.yaml``, ``targets.yaml``) so they
can be read and corrected without touching code.
"""

from __future__ import annotations

from pathlib import Path
from typing import Literal

from pydantic import BaseModel, ConfigDict, Field, ValidationError, model_validator

from agrirecipe._resources import data_path
from agrirecipe.evaluation._benchmark import BenchmarkError, PromptType, Tag, _read_yaml

__all__ = ["PaperResults", "PaperRow", "Target", "load_paper_results", "load_targets"]


class _Strict(BaseModel):
    model_config = ConfigDict(extra="forbid", frozen=True)


class PaperRow(_Strict):
    """One row of a paper table: a label and the values as the issue quotes them."""

    label: str
    values: tuple[float, ...] = Field(min_length=1)

    def quoted(self) -> str:
        """The values joined the way the issue writes them, e.g. ``100/100/97/98 %``."""
        return "/".join(f"{v:g}" for v in self.values) + " %"


class _TableI(_Strict):
    methods: tuple[str, ...]
    rows: dict[str, PaperRow]
    note: str | None = None


class _TableII(_Strict):
    ks: tuple[int, ...]
    rows: dict[str, PaperRow]


class _Latency(_Strict):
    model: str
    seconds_per_scene: float


class PaperResults(_Strict):
    """The seed paper's Tables I and II and its latency."""

    version: Literal[1]
    table_i: _TableI
    table_ii: _TableII
    latency: _Latency


class Target(_Strict):
    """A number a strategy must reach (``min``) or stay under (``max``)."""

    label: str
    metric: Literal[
        "accuracy", "f1", "retrieval_top1", "latency_median_ms", "latency_p95_ms", "phantom_fields"
    ]
    strategy: str | None = None
    types: tuple[PromptType, ...] = ()
    tags: tuple[Tag, ...] = ()
    method: str | None = None
    min: float | None = None
    max: float | None = None

    @model_validator(mode="after")
    def _one_bound(self) -> Target:
        if (self.min is None) == (self.max is None):
            raise ValueError("give exactly one of min or max")
        if self.metric != "retrieval_top1" and self.strategy is None:
            raise ValueError(f"metric {self.metric} needs a strategy")
        return self

    def met(self, value: float | None) -> bool | None:
        """Whether ``value`` meets the target (None when it was not measured)."""
        if value is None:
            return None
        if self.min is not None:
            return value >= self.min - 1e-9
        assert self.max is not None
        return value <= self.max

    @property
    def unit(self) -> str:
        """How the metric's values read: " %", " ms", or "" for a count."""
        if self.metric.startswith("latency"):
            return " ms"
        return "" if self.metric == "phantom_fields" else " %"

    @property
    def bound(self) -> str:
        """E.g. ``>= 99`` or ``<= 50 ms``."""
        unit = self.unit
        if self.min is not None:
            return f"≥ {self.min:g}{unit}"
        return f"≤ {self.max:g}{unit}"


class _TargetFile(_Strict):
    version: Literal[1]
    targets: tuple[Target, ...]


def load_paper_results(path: str | Path | None = None) -> PaperResults:
    """The paper's numbers (the shipped ``benchmarks/paper_results.yaml`` when None)."""
    source = Path(path) if path is not None else data_path("benchmarks") / "paper_results.yaml"
    try:
        return PaperResults.model_validate(_read_yaml(source, "paper results"))
    except ValidationError as exc:
        raise BenchmarkError(f"{source} is malformed: {exc}", stage="eval") from exc


def load_targets(path: str | Path | None = None) -> tuple[Target, ...]:
    """The targets of issues 3 and 8 (the shipped ``benchmarks/targets.yaml`` when None)."""
    source = Path(path) if path is not None else data_path("benchmarks") / "targets.yaml"
    try:
        return _TargetFile.model_validate(_read_yaml(source, "targets")).targets
    except ValidationError as exc:
        raise BenchmarkError(f"{source} is malformed: {exc}", stage="eval") from exc
