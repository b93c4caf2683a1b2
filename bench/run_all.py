"""Run every benchmark of bench/ in turn; each records its results in docs/.

Run from the repository root (``make bench``). Benchmarks are separate
processes so one's peak memory does not colour another's. The resolver latency
and accuracy benchmark is ``agrirecipe eval --write docs/EVALUATION.md``.
"""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

BENCHMARKS = (
    "bench_layout_usd.py",
    "bench_blender.py",
    "bench_unreal_script_size.py",
    "bench_llm_threads.py",
    "bench_long_prompts.py",
    "bench_gazebo.py",
    "bench_app.py",
    "bench_dataset.py",
)


def main() -> int:
    """Run each benchmark; return non-zero if any failed."""
    folder = Path(__file__).resolve().parent
    failed = []
    for name in BENCHMARKS:
        print(f"== {name}", flush=True)
        if subprocess.run([sys.executable, str(folder / name)], check=False).returncode:
            failed.append(name)
    print("== evaluation", flush=True)
    command = [sys.executable, "-m", "agrirecipe", "eval", "--write", "docs/EVALUATION.md"]
    if subprocess.run(command, check=False, cwd=folder.parent).returncode:
        failed.append("agrirecipe eval")
    if failed:
        print("failed: " + ", ".join(failed), file=sys.stderr)
    return 1 if failed else 0


if __name__ == "__main__":
    raise SystemExit(main())
