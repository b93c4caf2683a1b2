"""The evaluation: the prompt benchmark, its scoring, and the paper-shaped tables.

``agrirecipe eval`` runs every resolver strategy over ``benchmarks/prompts.yaml``
and the knowledge retrieval over ``benchmarks/knowledge_queries.yaml``, and
writes ``docs/EVALUATION.md``.
"""

from agrirecipe.evaluation._benchmark import (
    ATTRIBUTES,
    PROMPT_TYPES,
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
)

__all__ = [
    "ATTRIBUTES",
    "PROMPT_TYPES",
    "TAGS",
    "Benchmark",
    "BenchmarkError",
    "BenchmarkPrompt",
    "FieldCount",
    "KnowledgeQuery",
    "TruthField",
    "TruthRelation",
    "load_benchmark",
    "load_knowledge_queries",
]
