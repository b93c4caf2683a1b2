"""Running a resolver strategy over the benchmark: one ``generate`` call per prompt, timed."""

from __future__ import annotations

import os
import sys
import time
from collections.abc import Callable
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

from agrirecipe._errors import ConfigurationError, ModelError
from agrirecipe.evaluation._benchmark import Benchmark
from agrirecipe.evaluation._scoring import PredictedScene, PromptScore, score_prompt

if TYPE_CHECKING:
    from agrirecipe._scene import Scene

__all__ = ["WARMUP_PROMPT", "Generate", "StrategyRun", "run_strategy"]

#: Prompt of the untimed first call: it loads the strategy's models and indexes,
#: so the timed calls measure a warm process, as a user's second call would be.
WARMUP_PROMPT = "a healthy Gala apple orchard in summer next to a field of young Nantes carrots"

Generate = Callable[..., "Scene"]


@dataclass(frozen=True, slots=True)
class StrategyRun:
    """One strategy's scores over a benchmark, or why it could not run."""

    name: str
    scores: tuple[PromptScore, ...] = ()
    cold_seconds: float | None = None
    unavailable: str | None = None
    load_average: float | None = None
    fresh_process_seconds: float | None = None

    @property
    def failures(self) -> tuple[PromptScore, ...]:
        """The prompts this strategy got wrong, in benchmark order."""
        return tuple(s for s in self.scores if not s.correct)


def run_strategy(
    benchmark: Benchmark,
    resolver: str,
    *,
    seed: int = 0,
    progress: bool = True,
    generate: Generate | None = None,
    generate_options: dict[str, Any] | None = None,
    fresh_process: bool = False,
) -> StrategyRun:
    """Resolve every prompt of ``benchmark`` with ``resolver`` and score it.

    The first (warm-up) call is timed separately as ``cold_seconds`` (it may
    reuse models an earlier strategy loaded in this process); with
    ``fresh_process`` the first call is also timed in a new Python process
    (import and model loading included), as a user's first call. When it
    fails because the strategy cannot run here (a missing optional dependency
    or model), the run is returned as unavailable with the reason. Every other
    exception a prompt raises is scored (for an invalid prompt only an
    :class:`AgrirecipeError` counts as a rejection).
    """
    call: Generate
    if generate is None:
        from agrirecipe import generate as call  # registered strategies are plain names too
    else:
        call = generate
    options = dict(generate_options or {})
    start = time.perf_counter()
    try:
        call(WARMUP_PROMPT, seed=seed, resolver=resolver, **options)
    except (ConfigurationError, ModelError) as exc:
        return StrategyRun(name=resolver, unavailable=f"{type(exc).__name__}: {exc}")
    except Exception:
        # The strategy loads; whatever this call did wrong, the scored prompts will show.
        pass
    cold = time.perf_counter() - start

    from tqdm import tqdm

    scores: list[PromptScore] = []
    correct = 0
    bar = tqdm(
        benchmark.prompts,
        desc=f"eval {resolver}",
        unit="prompt",
        disable=not progress,
        file=sys.stderr,
        dynamic_ncols=True,
    )
    with bar:
        for item in bar:
            outcome: PredictedScene | BaseException
            begin = time.perf_counter()
            try:
                scene = call(item.prompt, seed=seed, resolver=resolver, **options)
            except Exception as exc:  # every failure, ours or not, is a scored outcome
                outcome = exc
            else:
                outcome = PredictedScene.from_recipe(scene.recipe)
            elapsed = time.perf_counter() - begin
            score = score_prompt(item, outcome, seconds=elapsed)
            scores.append(score)
            correct += int(score.correct)
            bar.set_postfix(correct=f"{correct}/{len(scores)}", refresh=False)
    return StrategyRun(
        name=resolver,
        scores=tuple(scores),
        cold_seconds=cold,
        load_average=_load_average(),
        fresh_process_seconds=first_call_in_new_process(resolver, seed) if fresh_process else None,
    )


def first_call_in_new_process(resolver: str, seed: int = 0) -> float | None:
    """Seconds from ``import agrirecipe`` to a first recipe in a new process (None on failure)."""
    import subprocess

    code = (
        "import sys, time\n"
        "start = time.perf_counter()\n"
        "import agrirecipe\n"
        "agrirecipe.generate(sys.argv[1], seed=int(sys.argv[2]), resolver=sys.argv[3])\n"
        "print(time.perf_counter() - start)\n"
    )
    try:
        done = subprocess.run(
            [sys.executable, "-c", code, WARMUP_PROMPT, str(seed), resolver],
            capture_output=True,
            text=True,
            timeout=1800,
            check=False,
        )
    except subprocess.TimeoutExpired:
        return None
    if done.returncode != 0:
        return None
    try:
        return float(done.stdout.strip().splitlines()[-1])
    except (ValueError, IndexError):
        return None


def _load_average() -> float | None:
    """The 5-minute load average (other processes on the same cores slow the timings)."""
    return os.getloadavg()[1] if hasattr(os, "getloadavg") else None
