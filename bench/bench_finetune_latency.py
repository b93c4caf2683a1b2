"""Accuracy, warm latency and tokens evaluated of the finetuned strategy on benchmark files.

Runs each file through the evaluation runner with one strategy object (warm: the
runner's first call is a warm-up), and counts the tokens llama.cpp evaluates
(``Llama.eval``), the cost that decides the strategy's latency, and the time of
one-token evaluations (generated answers) apart from longer ones (the prompt read in
batches). ``--whole-records``
asks the whole record instead of the local records (an adapter trained before the
local records, e.g. the first shipped one, kept under another path). Run it with
nothing else on the machine; docs/FINETUNE.md keeps the results.

    python bench/bench_finetune_latency.py benchmarks/heldout/g57-*.yaml
    python bench/bench_finetune_latency.py --adapter old.gguf --whole-records FILES
"""

from __future__ import annotations

import argparse
import os
from pathlib import Path


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("files", nargs="+", type=Path, help="benchmark YAML files")
    parser.add_argument("--adapter", type=Path, default=None, help="default: the shipped one")
    parser.add_argument("--whole-records", action="store_true", help="ask whole records")
    args = parser.parse_args()
    os.environ.setdefault("HF_HUB_OFFLINE", "1")

    import time

    import llama_cpp
    import numpy as np

    from agrirecipe.evaluation._benchmark import load_benchmark
    from agrirecipe.evaluation._runner import run_strategy
    from agrirecipe.finetune import FinetunedResolver

    evaluated = [0]
    # [calls, seconds] of one-token evals (generation) and of longer ones (prefill)
    steps = {"generated": [0, 0.0], "prefilled": [0, 0.0]}
    original = llama_cpp.Llama.eval

    def counting(self: llama_cpp.Llama, tokens: list[int]) -> None:
        evaluated[0] += len(tokens)
        started = time.perf_counter()
        original(self, tokens)
        kind = steps["generated" if len(tokens) == 1 else "prefilled"]
        kind[0] += len(tokens)
        kind[1] += time.perf_counter() - started

    llama_cpp.Llama.eval = counting  # type: ignore[method-assign]

    class Whole(FinetunedResolver):
        local_records = False

    strategy = (Whole if args.whole_records else FinetunedResolver)(args.adapter)
    right = total = 0
    for path in args.files:
        benchmark = load_benchmark(path)
        evaluated[0] = 0
        for kind in steps.values():
            kind[:] = [0, 0.0]
        load = Path("/proc/loadavg").read_text().split()[0]
        run = run_strategy(benchmark, strategy, progress=False)  # type: ignore[arg-type]
        seconds = np.array([s.seconds for s in run.scores if s.seconds is not None])
        correct = sum(s.correct for s in run.scores)
        count = len(run.scores)
        right, total = right + correct, total + count
        print(
            f"{path.name}: {correct}/{count} = {100 * correct / count:.1f} %, warm median "
            f"{1000 * np.median(seconds):.0f} ms, p95 {1000 * np.percentile(seconds, 95):.0f} ms, "
            f"max {1000 * seconds.max():.0f} ms, {evaluated[0] / count:.0f} tokens evaluated a "
            f"prompt (1-minute load {load} at the start)",
            flush=True,
        )
        for name, (tokens, spent) in steps.items():
            print(
                f"  {name}: {tokens / count:.1f} tokens a prompt, {1000 * spent / count:.0f} ms a "
                f"prompt ({1000 * spent / max(tokens, 1):.1f} ms a token)",
                flush=True,
            )
    print(f"all: {right}/{total} = {100 * right / total:.1f} %")


if __name__ == "__main__":
    main()
