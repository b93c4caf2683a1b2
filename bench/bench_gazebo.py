"""Benchmark: the 12-row maize field to a Gazebo world, beside virtual_maize_field and CropCraft.

The field of issue 13: 12 maize rows of 100 m at 0.75 m, from the prompt "12 rows of
maize, 100 m long, 75 cm apart". Each run is a fresh Python process that resolves the
prompt, lays the field out, then writes ``gazebo/`` (world.sdf, the field model with
its merged plant meshes, spawn.yaml, markers.csv) with the Gazebo backend; the
backend's wall time and the process's peak resident memory (``ru_maxrss``) are
measured, best of ``--repeat`` runs, for both ways of drawing leaf backs
(``double_sided="flag"``, the default, and ``"duplicate"``).

The peers' figures are those issue 13 quotes for this machine (virtual_maize_field
7.9 s and 1.7 GB, CropCraft 1.6 s and 0.5 GB); CropCraft's own Gazebo export is not
run here (``bench_cropcraft.py`` compares the Blender builds).

Run from the repository root::

    .venv/bin/python bench/bench_gazebo.py

Results go between this script's markers in ``docs/PERFORMANCE.md``.
"""

from __future__ import annotations

import argparse
import json
import os
import platform
import subprocess
import sys
import tempfile
import time
from pathlib import Path
from typing import Any

import _doc
from bench_layout_usd import cpu_model

START = "<!-- bench_gazebo:start -->"
END = "<!-- bench_gazebo:end -->"
PROMPT = "12 rows of maize, 100 m long, 75 cm apart"
PEERS = {"virtual_maize_field": (7.9, 1.7 * 1024), "CropCraft": (1.6, 0.5 * 1024)}

_CHILD = """
import json, resource, sys, time
from pathlib import Path
started = time.perf_counter()
from agrirecipe import generate
from agrirecipe.backends.gazebo import GazeboBackend
scene = generate(sys.argv[1], resolver=sys.argv[2])
scene.layout
resolved = time.perf_counter()
before_mb = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024.0
files = GazeboBackend(double_sided=sys.argv[4]).write(scene, Path(sys.argv[3]))
written = time.perf_counter()
peak_mb = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024.0
meshes = [f for f in files if f.suffix == ".stl"]
spec = scene.recipe.fields[0]
print("RUN " + json.dumps({
    "resolve_s": resolved - started, "write_s": written - resolved,
    "before_mb": before_mb, "peak_mb": peak_mb,
    "plants": scene.layout.plant_count, "rows": spec.row_count,
    "in_row_m": spec.agronomy.in_row_spacing_m,
    "meshes": len(meshes), "mesh_mb": sum(f.stat().st_size for f in meshes) / 2**20,
    "triangles": sum((f.stat().st_size - 84) // 50 for f in meshes),
}))
"""


def run(folder: Path, resolver: str, double_sided: str) -> dict[str, Any]:
    started = time.perf_counter()
    completed = subprocess.run(
        [sys.executable, "-c", _CHILD, PROMPT, resolver, str(folder), double_sided],
        capture_output=True,
        text=True,
        check=False,
    )
    wall = time.perf_counter() - started
    lines = [x for x in completed.stdout.splitlines() if x.startswith("RUN ")]
    if completed.returncode != 0 or not lines:
        sys.exit(f"the Gazebo run failed:\n{completed.stdout[-3000:]}\n{completed.stderr[-3000:]}")
    return {**json.loads(lines[-1][4:]), "wall_s": wall}


def report(results: dict[str, dict[str, Any]], resolver: str, repeat: int) -> str:
    flag = results["flag"]
    faster_peer = min(seconds for seconds, _ in PEERS.values())
    lines = [
        START,
        "## The 12-row maize field to a Gazebo world (`bench/bench_gazebo.py`)",
        "",
        f"Machine: {cpu_model()}, {os.cpu_count()} cores, Python {platform.python_version()}; "
        f"load average {os.getloadavg()[0]:.1f} at the end. Date: {time.strftime('%Y-%m-%d')}. "
        f"Best of {repeat} run(s), each a fresh process.",
        "",
        f"The prompt {PROMPT!r} ({resolver} resolver) gives {flag['rows']} rows, a plant every "
        f"{flag['in_row_m']} m: {flag['plants']:,} maize plants of the plant library (3 shape "
        "variants). The Gazebo backend writes `gazebo/world.sdf`, the field model with its "
        "soil and the plants merged per group of rows into binary STL meshes (one per "
        "material), `spawn.yaml` and `markers.csv`. *Write* is the backend alone; *memory* "
        "is the process's peak resident set (Python, numpy and the resolved scene included).",
        "",
        "| tool | leaf backs | resolve + lay out | write the world | whole process "
        "| peak memory | meshes | triangles |",
        "|---|---|---|---|---|---|---|---|",
    ]
    for mode, label in (("flag", "`<double_sided>` (gz-sim)"), ("duplicate", "duplicated")):
        r = results[mode]
        lines.append(
            f"| agrirecipe | {label} | {r['resolve_s']:.2f} s | **{r['write_s']:.2f} s** | "
            f"{r['wall_s']:.2f} s | **{r['peak_mb']:.0f} MiB** | {r['meshes']} files, "
            f"{r['mesh_mb']:.0f} MiB | {r['triangles']:,} |"
        )
    for name, (seconds, memory_mb) in PEERS.items():
        lines.append(
            f"| {name} (issue 13's figures) | – | – | **{seconds:.1f} s** | – | "
            f"**{memory_mb:.0f} MiB** | – | – |"
        )
    lines += [
        "",
        f"Writing the world takes {flag['write_s']:.2f} s with the default leaf backs: "
        f"{faster_peer / flag['write_s']:.1f}x faster than the faster peer (CropCraft, "
        f"{faster_peer} s; target at least 3x) and "
        f"{PEERS['virtual_maize_field'][0] / flag['write_s']:.0f}x faster than "
        f"virtual_maize_field; with duplicated leaf backs (right in Gazebo Classic too) "
        f"{faster_peer / results['duplicate']['write_s']:.1f}x. The process peaks at "
        f"{flag['peak_mb']:.0f} MiB, of which {flag['before_mb']:.0f} MiB were already in use "
        "before the backend started. The peers' numbers are the ones issue 13 measured on this "
        "machine; they were not re-run here.",
        END,
    ]
    return "\n".join(lines) + "\n"


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeat", type=int, default=3)
    parser.add_argument("--resolver", default="rules")
    parser.add_argument("--no-write", action="store_true", help="do not update the doc")
    args = parser.parse_args()
    results: dict[str, dict[str, Any]] = {}
    for mode in ("flag", "duplicate"):
        runs = []
        for _ in range(args.repeat):
            with tempfile.TemporaryDirectory(prefix="bench-gazebo-") as folder:
                runs.append(run(Path(folder), args.resolver, mode))
        results[mode] = min(runs, key=lambda r: r["write_s"])
    section = report(results, args.resolver, args.repeat)
    print(section)
    if not args.no_write:
        _doc.update_doc(section, START, END)
    return 0


if __name__ == "__main__":
    sys.exit(main())
