"""Benchmark: outputs of a large scene - binary USD plants layer and Parquet ground truth.

"a 3 hectare wheat field" (about 4.25 million plants) written with the defaults
(``scene.usda`` small text + ``scene_plants.usdc``; ``plants.parquet``) and, for
comparison, all text (``binary_above=None``; ``plants.csv``): sizes and write times.

    .venv/bin/python bench/bench_outputs_at_scale.py [--no-write]
"""

from __future__ import annotations

import argparse
import os
import platform
import sys
import tempfile
import time
from pathlib import Path
from typing import Any

import _doc
from bench_layout_usd import cpu_model

START = "<!-- bench_outputs_at_scale:start -->"
END = "<!-- bench_outputs_at_scale:end -->"
PROMPT = "a 3 hectare wheat field"


def _mb(path: Path) -> float:
    return path.stat().st_size / 2**20 if path.exists() else 0.0


def measure() -> dict[str, Any]:
    from agrirecipe import generate
    from agrirecipe.backends.annotations import AnnotationsBackend
    from agrirecipe.backends.usd import UsdBackend

    scene = generate(PROMPT, resolver="hybrid")
    plants = scene.layout.plant_count
    result: dict[str, Any] = {"plants": plants}
    with tempfile.TemporaryDirectory(prefix="bench-scale-") as folder:
        out = Path(folder)
        for label, backend in (
            ("usd_binary", UsdBackend()),
            ("usd_text", UsdBackend(binary_above=None)),
            ("parquet", AnnotationsBackend(ground_truth="parquet")),
            ("csv", AnnotationsBackend(ground_truth="csv")),
        ):
            target = out / label
            started = time.perf_counter()
            backend.write(scene, target)
            seconds = time.perf_counter() - started
            result[label] = {
                "seconds": seconds,
                "files": {p.name: _mb(p) for p in sorted(target.iterdir()) if p.is_file()},
            }
    result["load"] = os.getloadavg()[0]
    return result


def report(r: dict[str, Any]) -> str:
    def row(label: str, title: str, names: tuple[str, ...]) -> str:
        files = r[label]["files"]
        sizes = ", ".join(f"`{n}` {files.get(n, 0.0):,.1f} MiB" for n in names)
        return f"| {title} | {r[label]['seconds']:.1f} s | {sizes} |"

    return (
        "\n".join(
            [
                START,
                "## Outputs of a large scene (`bench/bench_outputs_at_scale.py`)",
                "",
                f"Machine: {cpu_model()}, {os.cpu_count()} cores, Python "
                f"{platform.python_version()}; load average {r['load']:.1f} at the end. Date: "
                f"{time.strftime('%Y-%m-%d')}. Scene: {PROMPT!r}, {r['plants']:,} plants (the "
                "layout is computed once, before the timings; USD timings include the plant "
                "meshes in assets/).",
                "",
                "| output | write time | files |",
                "|---|---|---|",
                row(
                    "usd_binary",
                    "USD, default: text root + binary plants layer",
                    ("scene.usda", "scene_plants.usdc"),
                ),
                row("usd_text", "USD, all text (`binary_above=None`)", ("scene.usda",)),
                row(
                    "parquet", "ground truth, default above 1M plants: Parquet", ("plants.parquet",)
                ),
                row("csv", "ground truth as CSV (`ground_truth='csv'`)", ("plants.csv",)),
                "",
                "Both USD variants compose to the same instances (tested); the Parquet table holds "
                "the CSV's columns (tested).",
                END,
            ]
        )
        + "\n"
    )


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--no-write", action="store_true")
    args = parser.parse_args()
    section = report(measure())
    print(section)
    if not args.no_write:
        _doc.update_doc(section, START, END)
    return 0


if __name__ == "__main__":
    sys.exit(main())
