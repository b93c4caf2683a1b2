"""Benchmark: the plant library (issue 9) - one asset, the whole catalogue, triangle budgets.

- one asset with its 3 shape variants, for the heaviest asset of each archetype
  (drawing the mesh and encoding the .glb; target under 1 s);
- the whole catalogue (every crop x variety x stage x season x health) with 3
  variants on all cores through ``build_library`` (target under 10 minutes on 2 cores),
  with the files' total size;
- triangles per archetype (largest over the catalogue) against the budgets of
  ``plants/data/shapes.yaml``.

Run from the repository root::

    .venv/bin/python bench/bench_plants.py            # measure, update docs/PERFORMANCE.md
    .venv/bin/python bench/bench_plants.py --no-write
"""

from __future__ import annotations

import argparse
import os
import platform
import sys
import tempfile
import time
from collections import defaultdict
from pathlib import Path
from typing import Any

import _doc
from bench_layout_usd import cpu_model

START = "<!-- bench_plants:start -->"
END = "<!-- bench_plants:end -->"
ONE_ASSET_TARGET_S = 1.0
LIBRARY_TARGET_S = 600.0


def measure(workers: int) -> dict[str, Any]:
    from agrirecipe.knowledge import default_knowledge_base
    from agrirecipe.plants import build_library, plant_spec
    from agrirecipe.plants._library import _shapes, asset_glb

    kb = default_knowledge_base()
    keys = list(kb.hierarchy.assets())
    triangles: dict[str, int] = defaultdict(int)
    heaviest: dict[str, tuple[int, Any]] = {}
    for key in keys:  # variant 0 of every asset: the largest mesh per archetype
        spec = plant_spec(kb, key)
        path = kb.hierarchy.asset_path(key)
        mesh, _, _ = asset_glb(spec, key, path, 0)
        if mesh.triangle_count > triangles[spec.archetype]:
            triangles[spec.archetype] = mesh.triangle_count
            heaviest[spec.archetype] = (mesh.triangle_count, key)
    one_asset: dict[str, float] = {}
    for archetype, (_, key) in heaviest.items():
        spec, path = plant_spec(kb, key), kb.hierarchy.asset_path(key)
        best = float("inf")
        for _ in range(3):
            started = time.perf_counter()
            for variant in range(3):
                asset_glb(spec, key, path, variant)
            best = min(best, time.perf_counter() - started)
        one_asset[archetype] = best
    with tempfile.TemporaryDirectory(prefix="bench-plants-") as folder:
        started = time.perf_counter()
        written = build_library(folder, knowledge=kb, variants=3, workers=workers)
        library_s = time.perf_counter() - started
        size = sum(f.bytes for f in written)
    return {
        "assets": len(keys),
        "files": len(written),
        "bytes": size,
        "library_s": library_s,
        "workers": workers,
        "one_asset": one_asset,
        "triangles": dict(triangles),
        "budgets": {k: int(v) for k, v in _shapes()["budgets"].items()},
        "heaviest": {k: kb.hierarchy.asset_path(v[1]) for k, v in heaviest.items()},
        "load": os.getloadavg()[0],
    }


def report(result: dict[str, Any]) -> str:
    slowest = max(result["one_asset"].values())
    lines = [
        START,
        "## The plant library (`bench/bench_plants.py`)",
        "",
        f"Machine: {cpu_model()}, {os.cpu_count()} cores, Python {platform.python_version()}; "
        f"load average {result['load']:.1f} at the end. Date: {time.strftime('%Y-%m-%d')}.",
        "",
        f"Whole catalogue: {result['assets']:,} assets x 3 shape variants = "
        f"{result['files']:,} `.glb` files ({result['bytes'] / 2**20:,.0f} MiB) and "
        f"manifest.json in **{result['library_s']:.1f} s** with {result['workers']} worker "
        f"processes (target: under {LIBRARY_TARGET_S / 60:.0f} minutes on 2 cores: "
        + ("met" if result["library_s"] < LIBRARY_TARGET_S else "MISSED")
        + ").",
        "",
        "| archetype | one asset, 3 variants (best of 3) | most triangles in the catalogue | "
        "budget | heaviest asset |",
        "|---|---|---|---|---|",
    ]
    for archetype in sorted(result["triangles"]):
        lines.append(
            f"| {archetype} | {result['one_asset'][archetype] * 1000:.0f} ms | "
            f"{result['triangles'][archetype]:,} | {result['budgets'][archetype]:,} | "
            f"`{result['heaviest'][archetype].rsplit('/', 1)[-1]}` |"
        )
    lines += [
        "",
        f"Target: one asset with its variants under {ONE_ASSET_TARGET_S:.0f} s ("
        + ("met" if slowest < ONE_ASSET_TARGET_S else "MISSED")
        + f": the slowest archetype takes {slowest * 1000:.0f} ms). Every mesh stays within its "
        "archetype's triangle budget (the library refuses to write one that does not).",
        END,
    ]
    return "\n".join(lines) + "\n"


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--workers", type=int, default=os.cpu_count() or 1)
    parser.add_argument("--no-write", action="store_true", help="do not update the doc")
    args = parser.parse_args()
    section = report(measure(args.workers))
    print(section)
    if not args.no_write:
        _doc.update_doc(section, START, END)
    return 0


if __name__ == "__main__":
    sys.exit(main())
