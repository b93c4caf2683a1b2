"""The evaluation: the prompt benchmark, its scoring, and the paper-shaped tables.

``agrirecipe eval`` runs every resolver strategy over the shipped prompt files
(``benchmarks/prompts.yaml``, ``prompts_heldout.yaml``, ``heldout/*.yaml``)
and the knowledge retrieval over ``benchmarks/knowledge_queries.yaml``, and
writes ``docs/EVALUATION.md``::

    from agrirecipe.evaluation import evaluate, load_benchmark, render_markdown

    report = evaluate(load_benchmark().select(limit=20), ["rules"])
    print(render_markdown(report))
"""

from agrirecipe.evaluation._benchmark import (
    ATTRIBUTES,
    GENRE_TAGS,
    GEOMETRY_KEYS,
    PROMPT_TYPES,
    SHIPPED_PROMPT_FILES,
    TAGS,
    Benchmark,
    BenchmarkError,
    BenchmarkPrompt,
    FieldCount,
    KnowledgeQuery,
    TruthField,
    TruthRelation,
    load_benchmark,
    load_knowledge_queries,
    round_robin,
    shipped_prompt_files,
)
from agrirecipe.evaluation._evaluate import DEFAULT_STRATEGIES, evaluate, models_description
from agrirecipe.evaluation._reference import (
    PaperResults,
    Target,
    load_paper_results,
    load_targets,
)
from agrirecipe.evaluation._report import (
    BEGIN_MARKER,
    END_MARKER,
    EvaluationReport,
    machine_description,
    render_markdown,
    update_document,
)
from agrirecipe.evaluation._retrieval import (
    RETRIEVAL_METHODS,
    QueryResult,
    RetrievalRun,
    run_retrieval,
)
from agrirecipe.evaluation._runner import WARMUP_PROMPT, StrategyRun, run_strategy
from agrirecipe.evaluation._scoring import (
    PredictedField,
    PredictedRelation,
    PredictedScene,
    PromptScore,
    optimal_assignment,
    score_prompt,
)
from agrirecipe.evaluation._summary import (
    FieldCounts,
    Latency,
    Rate,
    accuracy_by,
    field_counts,
    latency,
    percentile,
)

__all__ = [
    "ATTRIBUTES",
    "BEGIN_MARKER",
    "DEFAULT_STRATEGIES",
    "END_MARKER",
    "GENRE_TAGS",
    "GEOMETRY_KEYS",
    "PROMPT_TYPES",
    "RETRIEVAL_METHODS",
    "SHIPPED_PROMPT_FILES",
    "TAGS",
    "WARMUP_PROMPT",
    "Benchmark",
    "BenchmarkError",
    "BenchmarkPrompt",
    "EvaluationReport",
    "FieldCount",
    "FieldCounts",
    "KnowledgeQuery",
    "Latency",
    "PaperResults",
    "PredictedField",
    "PredictedRelation",
    "PredictedScene",
    "PromptScore",
    "QueryResult",
    "Rate",
    "RetrievalRun",
    "StrategyRun",
    "Target",
    "TruthField",
    "TruthRelation",
    "accuracy_by",
    "evaluate",
    "field_counts",
    "latency",
    "load_benchmark",
    "load_knowledge_queries",
    "load_paper_results",
    "load_targets",
    "machine_description",
    "models_description",
    "optimal_assignment",
    "percentile",
    "render_markdown",
    "round_robin",
    "run_retrieval",
    "run_strategy",
    "score_prompt",
    "shipped_prompt_files",
    "update_document",
]
