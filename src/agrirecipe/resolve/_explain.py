"""What each stage of resolution produced, for ``generate(..., explain=True)`` and ``--explain``."""

from __future__ import annotations

from pydantic import BaseModel, ConfigDict

from agrirecipe.resolve._intent import TraceStep

__all__ = ["Explanation"]

# Stages in the order they run (DESIGN.md); a strategy's own stages come after.
_STAGE_ORDER = ("decompose", "normalise", "retrieve", "validate", "choose", "enrich", "layout")


class Explanation(BaseModel):
    """The resolver's trace: subqueries, candidates and scores, choices, inferences, warnings."""

    model_config = ConfigDict(frozen=True, extra="forbid")

    prompt: str
    resolver: str
    seed: int
    steps: tuple[TraceStep, ...] = ()
    warnings: tuple[str, ...] = ()

    def render(self) -> str:
        """A readable report, one stage after another (repeated steps shown once)."""
        lines = [f"prompt: {self.prompt!r}", f"resolver: {self.resolver} (seed {self.seed})"]
        current = None
        rank = {stage: index for index, stage in enumerate(_STAGE_ORDER)}
        unique = list(dict.fromkeys(self.steps))
        ordered = sorted(unique, key=lambda step: rank.get(step.stage, len(rank)))
        for step in ordered:
            if step.stage != current:
                current = step.stage
                lines.append(f"[{step.stage}]")
            lines.append(f"  {step.subject}: {step.detail}")
            if step.candidates:
                shown = ", ".join(
                    f"{c.value} {c.score:.0f} ({c.source})" for c in step.candidates[:5]
                )
                lines.append(f"    candidates: {shown}")
        if self.warnings:
            lines.append("[warnings]")
            lines.extend(f"  {warning}" for warning in self.warnings)
        return "\n".join(lines)
