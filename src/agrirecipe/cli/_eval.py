"""``agrirecipe eval``: run the benchmark, print the paper-shaped tables, write the report."""

from __future__ import annotations

import argparse
import sys
from pathlib import Path
from typing import Any


def register(subparsers: Any) -> None:
    """Add the ``eval`` sub-command."""
    from agrirecipe.evaluation import DEFAULT_STRATEGIES, PROMPT_TYPES, TAGS

    parser = subparsers.add_parser(
        "eval",
        help="measure the resolver strategies on the benchmark",
        description="Run each resolver strategy over the checked-in benchmark "
        "(benchmarks/prompts.yaml, prompts_heldout.yaml and heldout/*.yaml) and the "
        "knowledge retrieval over "
        "benchmarks/knowledge_queries.yaml; print Table I (accuracy per prompt type, "
        "field-level P/R/F1), Table II (retrieval Top-1/2/3) and latency beside the "
        "seed paper's numbers.",
    )
    parser.add_argument(
        "--resolver",
        default=",".join(DEFAULT_STRATEGIES),
        help=f"comma-separated strategies to evaluate (default {','.join(DEFAULT_STRATEGIES)})",
    )
    parser.add_argument(
        "--category",
        default=None,
        help="comma-separated prompt types or tags to keep; types: "
        f"{', '.join(PROMPT_TYPES)}; tags: {', '.join(TAGS)}",
    )
    parser.add_argument(
        "--limit",
        type=int,
        default=None,
        help="evaluate at most N prompts (taken evenly across types) and N knowledge queries",
    )
    parser.add_argument(
        "--write",
        type=Path,
        default=None,
        metavar="PATH",
        help="write the report into PATH (e.g. docs/EVALUATION.md), keeping text outside "
        "the generated block",
    )
    parser.add_argument(
        "--failures",
        action="store_true",
        help="also print every failure case (prompt, expected, got)",
    )
    parser.add_argument(
        "--no-retrieval",
        action="store_true",
        help="skip Table II (it loads the embedding model)",
    )
    parser.add_argument(
        "--retrieval-resolver",
        default=None,
        help="strategy that extracts attributes for Table II (default hybrid if evaluated)",
    )
    parser.add_argument(
        "--benchmark",
        type=Path,
        action="append",
        default=None,
        metavar="PATH",
        help="a prompts file instead of the shipped ones (benchmarks/prompts.yaml, "
        "prompts_heldout.yaml, heldout/*.yaml); repeat for several",
    )
    parser.add_argument(
        "--split",
        choices=["dev", "heldout"],
        default=None,
        help="only the development prompts or only the held-out ones",
    )
    parser.add_argument("--queries", type=Path, default=None, help="a custom knowledge-query file")
    parser.add_argument("--seed", type=int, default=0, help="seed passed to generate (default 0)")
    parser.add_argument("--no-progress", action="store_true", help="no progress bars")
    parser.add_argument(
        "--no-fresh-process",
        action="store_true",
        help="do not time each strategy's first call in a new process (saves a model load)",
    )
    parser.set_defaults(handler=run)


def run(args: argparse.Namespace) -> int:
    """Evaluate, print the tables and optionally write the report."""
    from agrirecipe._errors import ConfigurationError
    from agrirecipe.evaluation import (
        PROMPT_TYPES,
        TAGS,
        evaluate,
        load_benchmark,
        load_knowledge_queries,
        render_markdown,
        round_robin,
        update_document,
    )
    from agrirecipe.resolve import available_resolvers

    strategies = [name.strip() for name in args.resolver.split(",") if name.strip()]
    known = available_resolvers()
    unknown = [name for name in strategies if name not in known]
    if not strategies or unknown:
        raise ConfigurationError(
            f"unknown resolver strategy {', '.join(unknown) or '(none given)'}",
            stage="eval",
            hint="accepted: " + ", ".join(known),
        )
    if args.limit is not None and args.limit < 1:
        raise ConfigurationError("--limit must be at least 1", stage="eval")
    benchmark = load_benchmark(args.benchmark)
    selection: list[str] = []
    if args.category:
        wanted = [name.strip() for name in args.category.split(",") if name.strip()]
        bad = [name for name in wanted if name not in PROMPT_TYPES and name not in TAGS]
        if bad:
            raise ConfigurationError(
                f"unknown prompt category {', '.join(bad)}",
                stage="eval",
                hint=f"types: {', '.join(PROMPT_TYPES)}; tags: {', '.join(TAGS)}",
            )
        types = [name for name in wanted if name in PROMPT_TYPES]
        tags = [name for name in wanted if name in TAGS]
        # A prompt is kept when it has one of the types or carries one of the tags.
        by_type = benchmark.select(types=types).prompts if types else ()
        by_tag = benchmark.select(tags=tags).prompts if tags else ()
        keep = {p.id for p in (*by_type, *by_tag)}
        benchmark = benchmark.select(ids=sorted(keep))
        selection.append(f"categories {', '.join(wanted)}")
    if args.split is not None:
        benchmark = benchmark.select(splits=[args.split])
        selection.append(f"{args.split} split")
    if args.limit is not None:
        benchmark = benchmark.select(limit=args.limit)
        selection.append(f"--limit {args.limit}")
    if not len(benchmark):
        raise ConfigurationError("no prompt matches the selection", stage="eval")
    queries = None
    if not args.no_retrieval:
        queries = load_knowledge_queries(args.queries)
        if args.limit is not None:
            # Every crop in turn, so a small subset still covers them all.
            queries = tuple(round_robin(queries, lambda q: q.key.crop, args.limit))
    described = f"{len(benchmark)} prompts" + (f" ({'; '.join(selection)})" if selection else "")
    report = evaluate(
        benchmark,
        strategies,
        queries=queries,
        retrieval_resolver=args.retrieval_resolver,
        seed=args.seed,
        progress=not args.no_progress,
        selection=described if selection else None,
        fresh_process=not args.no_fresh_process,
    )
    print(render_markdown(report, failures=args.failures), end="")
    if args.write is not None:
        path = update_document(args.write, render_markdown(report, failures=True))
        print(f"wrote {path}", file=sys.stderr)
    return 0
