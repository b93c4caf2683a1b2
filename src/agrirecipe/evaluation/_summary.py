"""Aggregates over prompt scores: accuracy per type and tag, field-level P/R/F1, latency."""

from __future__ import annotations

import math
import statistics
from collections.abc import Iterable, Sequence
from dataclasses import dataclass

from agrirecipe.evaluation._scoring import PromptScore

__all__ = [
    "FieldCounts",
    "Latency",
    "Rate",
    "accuracy_by",
    "field_counts",
    "latency",
    "percentile",
]


@dataclass(frozen=True, slots=True)
class Rate:
    """``hits`` out of ``total``."""

    hits: int
    total: int

    @property
    def fraction(self) -> float | None:
        """hits / total, or None when there is nothing to count."""
        return self.hits / self.total if self.total else None

    def __str__(self) -> str:
        fraction = self.fraction
        if fraction is None:
            return "–"
        return f"{100 * fraction:.1f} % ({self.hits}/{self.total})"


@dataclass(frozen=True, slots=True)
class FieldCounts:
    """Field-level true positives, predicted fields and truth fields, micro-averaged."""

    true_positives: int
    predicted: int
    truth: int

    @property
    def precision(self) -> float | None:
        """Share of predicted fields that match a truth field."""
        return self.true_positives / self.predicted if self.predicted else None

    @property
    def recall(self) -> float | None:
        """Share of truth fields matched by a predicted field."""
        matched = min(self.true_positives, self.truth)
        return matched / self.truth if self.truth else None

    @property
    def f1(self) -> float | None:
        """Harmonic mean of precision and recall (0 when both are 0)."""
        p, r = self.precision, self.recall
        if p is None or r is None:
            return None
        return 0.0 if p + r == 0 else 2 * p * r / (p + r)

    def __str__(self) -> str:
        values = (self.precision, self.recall, self.f1)
        if any(v is None for v in values):
            return "–"
        return " / ".join(f"{100 * v:.1f}" for v in values if v is not None)


@dataclass(frozen=True, slots=True)
class Latency:
    """Warm wall-clock time per prompt, in milliseconds."""

    count: int
    median_ms: float
    p95_ms: float
    mean_ms: float
    max_ms: float


def accuracy_by(scores: Iterable[PromptScore], key: str) -> dict[str, Rate]:
    """Accuracy grouped by ``"type"`` or by ``"tag"`` (a prompt counts once per tag)."""
    hits: dict[str, int] = {}
    totals: dict[str, int] = {}
    for score in scores:
        groups = score.tags if key == "tag" else (score.type,)
        for group in groups:
            totals[group] = totals.get(group, 0) + 1
            hits[group] = hits.get(group, 0) + int(score.correct)
    return {group: Rate(hits[group], totals[group]) for group in totals}


def field_counts(scores: Iterable[PromptScore], types: Sequence[str] | None = None) -> FieldCounts:
    """Micro-averaged field-level counts over the valid prompts of ``types`` (all when None)."""
    tp = predicted = truth = 0
    for score in scores:
        if score.type == "invalid" or (types is not None and score.type not in types):
            continue
        tp += score.true_positives
        predicted += score.predicted_fields
        truth += score.truth_fields
    return FieldCounts(tp, predicted, truth)


def percentile(values: Sequence[float], q: float) -> float:
    """The ``q``-th percentile (0-100) with linear interpolation between order statistics."""
    if not values:
        raise ValueError("percentile of no values")
    ordered = sorted(values)
    position = (len(ordered) - 1) * q / 100.0
    low = math.floor(position)
    high = math.ceil(position)
    return ordered[low] + (ordered[high] - ordered[low]) * (position - low)


def latency(scores: Iterable[PromptScore]) -> Latency | None:
    """Latency statistics over every timed prompt, or None when none was timed."""
    seconds = [s.seconds for s in scores if s.seconds is not None]
    if not seconds:
        return None
    ms = [1000.0 * value for value in seconds]
    return Latency(
        count=len(ms),
        median_ms=statistics.median(ms),
        p95_ms=percentile(ms, 95),
        mean_ms=statistics.fmean(ms),
        max_ms=max(ms),
    )
