"""Benchmark: a 12-row maize field in Blender, agrirecipe beside CropCraft (issue 9).

The field of the comparison in issue 9: 12 maize rows of 100 m at 0.75 m. agrirecipe
builds it from the prompt "12 rows of maize, 100 m long, 75 cm apart" (resolved,
laid out, the plant library's meshes written to assets/, then blender_build.py run
in a fresh bpy process that saves a .blend); CropCraft (Romea/cropcraft, hand-made
textured maize meshes) builds the same rows from a YAML configuration with its
``core/blender_entrypoint.py -- CFG OUT`` in a fresh process with the same bpy.
Both write a .blend; wall time and the child's peak resident memory (``ru_maxrss``)
are measured, best of ``--repeat`` runs.

Run from the repository root, with a CropCraft checkout when you have one::

    .venv/bin/python bench/bench_cropcraft.py --cropcraft /path/to/cropcraft
    .venv/bin/python bench/bench_cropcraft.py            # agrirecipe only

CropCraft needs ``click``, ``msgpack`` and ``appdirs`` next to bpy. Results go
between this script's markers in ``docs/PERFORMANCE.md``.
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

START = "<!-- bench_cropcraft:start -->"
END = "<!-- bench_cropcraft:end -->"
PROMPT = "12 rows of maize, 100 m long, 75 cm apart"
ROWS, ROW_LENGTH_M, ROW_SPACING_M = 12, 100.0, 0.75

# Runs a script as __main__ in this fresh process, then prints its peak memory.
# bpy is imported first and timed on its own: both tools pay the same start-up (about
# a second and 270 MiB for the bpy module here), and the comparison is of their work.
_RUNNER = """
import resource, runpy, sys, time
script, args = sys.argv[1], sys.argv[2:]
sys.argv = [script, *args]
started = time.perf_counter()
import bpy
imported = time.perf_counter()
base = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024.0
code = 0
try:
    runpy.run_path(script, run_name="__main__")
except SystemExit as stop:
    code = stop.code or 0
peak = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024.0
print("RUN", imported - started, time.perf_counter() - imported, base, peak)
sys.exit(code)
"""


def run_child(script: Path, args: list[str], cwd: Path) -> dict[str, float]:
    started = time.perf_counter()
    completed = subprocess.run(
        [sys.executable, "-c", _RUNNER, str(script), *args],
        capture_output=True,
        text=True,
        cwd=cwd,
        check=False,
    )
    wall = time.perf_counter() - started
    lines = [x for x in completed.stdout.splitlines() if x.startswith("RUN ")]
    if completed.returncode != 0 or not lines:
        sys.exit(f"{script.name} failed:\n{completed.stdout[-3000:]}\n{completed.stderr[-3000:]}")
    _, import_s, work_s, base_mb, peak_mb = lines[-1].split()
    return {
        "wall_s": wall,
        "import_s": float(import_s),
        "work_s": float(work_s),
        "base_mb": float(base_mb),
        "peak_mb": float(peak_mb),
    }


def agrirecipe_run(folder: Path) -> dict[str, Any]:
    """Prompt -> recipe -> blender_build.py + assets/ -> a .blend, timed end to end."""
    from agrirecipe import generate
    from agrirecipe.backends.blender import BlenderBackend

    started = time.perf_counter()
    scene = generate(PROMPT, resolver="hybrid")
    BlenderBackend().write(scene, folder)
    library_s = time.perf_counter() - started
    child = run_child(folder / "blender_build.py", ["--save", str(folder / "field.blend")], folder)
    spec = scene.recipe.fields[0]
    return {
        **child,
        "library_s": library_s,
        "plants": scene.layout.plant_count,
        "rows": spec.row_count,
        "row_spacing_m": spec.agronomy.row_spacing_m,
        "in_row_m": spec.agronomy.in_row_spacing_m,
        "row_length_m": spec.row_length_m,
        "blend_mb": (folder / "field.blend").stat().st_size / 2**20,
    }


def cropcraft_run(checkout: Path, folder: Path, in_row_m: float) -> dict[str, Any]:
    """The same rows through CropCraft's own entry point."""
    per_row = int(ROW_LENGTH_M / in_row_m) + 1
    config = {
        "output": {"blender": {"type": "blender_file", "filename": "field.blend"}},
        "field": {
            "bed_width": ROW_SPACING_M,
            "beds": {
                "maize": {
                    "plant_type": "maize",
                    # CropCraft's maize models are young plants, 0.21-0.49 m tall
                    "plant_height": 0.45,
                    "plant_distance": in_row_m,
                    "row_distance": ROW_SPACING_M,
                    "plants_count": per_row,
                    "rows_count": 1,
                    "beds_count": ROWS,
                }
            },
            "noise": {"position": 0.01, "tilt": 0.05, "missing": 0.05, "scale": 0.1},
        },
    }
    path = folder / "field.yaml"
    path.write_text(json.dumps(config), encoding="utf-8")  # JSON is YAML
    out = folder / "cropcraft_out"
    out.mkdir()
    entry = checkout / "core" / "blender_entrypoint.py"
    result = run_child(entry, ["--", str(path), str(out)], checkout)
    blends = list(out.rglob("*.blend"))
    return {
        **result,
        "plants": per_row * ROWS,
        "blend_mb": sum(b.stat().st_size for b in blends) / 2**20,
    }


def report(ours: dict[str, Any], theirs: dict[str, Any] | None, repeat: int) -> str:
    lines = [
        START,
        "## A 12-row maize field in Blender, beside CropCraft (`bench/bench_cropcraft.py`)",
        "",
        f"Machine: {cpu_model()}, {os.cpu_count()} cores, Python {platform.python_version()}; "
        f"load average {os.getloadavg()[0]:.1f} at the end. Date: {time.strftime('%Y-%m-%d')}. "
        f"Best of {repeat} run(s); memory is the child process's peak resident set.",
        "",
        f"agrirecipe: the prompt {PROMPT!r} read into {ours['rows']} rows of "
        f"{ours['row_length_m']:.0f} m at {ours['row_spacing_m']} m, a plant every "
        f"{ours['in_row_m']} m ({ours['plants']:,} plants); the plant library's maize meshes "
        "(3 variants) written to assets/ with blender_build.py, then the script run in a fresh "
        "bpy process that imports the meshes, instances every plant and saves a .blend.",
        "",
        "| tool | plants | resolve, write script and meshes | build and save, after `import bpy` "
        "| memory above bpy | whole process | peak memory | .blend |",
        "|---|---|---|---|---|---|---|---|",
        f"| agrirecipe (plant library meshes) | {ours['plants']:,} | {ours['library_s']:.2f} s | "
        f"**{ours['work_s']:.2f} s** | **{ours['peak_mb'] - ours['base_mb']:.0f} MiB** | "
        f"{ours['wall_s']:.2f} s | {ours['peak_mb']:.0f} MiB | {ours['blend_mb']:.1f} MiB |",
    ]
    if theirs is not None:
        lines.append(
            f"| CropCraft (hand-made young maize meshes, 0.45 m) | {theirs['plants']:,} | – | "
            f"**{theirs['work_s']:.2f} s** | **{theirs['peak_mb'] - theirs['base_mb']:.0f} MiB** | "
            f"{theirs['wall_s']:.2f} s | {theirs['peak_mb']:.0f} MiB | "
            f"{theirs['blend_mb']:.1f} MiB |"
        )
        speedup = theirs["work_s"] / ours["work_s"]
        whole = theirs["wall_s"] / ours["wall_s"]
        lines += [
            "",
            f"`import bpy` alone takes {ours['import_s']:.2f} s and {ours['base_mb']:.0f} MiB "
            "in a fresh process here, the same for both tools. After it, agrirecipe builds and "
            f"saves the field {speedup:.1f}x faster than CropCraft (target: at least 3x) with "
            f"{ours['peak_mb'] - ours['base_mb']:.0f} MiB above bpy's own; whole processes: "
            f"{whole:.1f}x, peak {ours['peak_mb']:.0f} MiB (target: under 300 MiB).",
        ]
    else:
        lines += [
            "",
            "No CropCraft checkout was given to this run (`--cropcraft DIR`); issue 9 quotes "
            "CropCraft at 1.56 s and 514 MiB on this machine for these rows.",
        ]
    lines.append(END)
    return "\n".join(lines) + "\n"


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--cropcraft", type=Path, help="a CropCraft checkout to compare with")
    parser.add_argument("--repeat", type=int, default=3)
    parser.add_argument("--no-write", action="store_true", help="do not update the doc")
    args = parser.parse_args()
    ours_runs, theirs_runs = [], []
    for _ in range(args.repeat):
        with tempfile.TemporaryDirectory(prefix="bench-cropcraft-") as folder:
            ours_runs.append(agrirecipe_run(Path(folder)))
        if args.cropcraft is not None:
            with tempfile.TemporaryDirectory(prefix="bench-cropcraft-") as folder:
                theirs_runs.append(
                    cropcraft_run(args.cropcraft, Path(folder), ours_runs[-1]["in_row_m"])
                )
    ours = min(ours_runs, key=lambda r: r["work_s"])
    theirs = min(theirs_runs, key=lambda r: r["work_s"]) if theirs_runs else None
    section = report(ours, theirs, args.repeat)
    print(section)
    if not args.no_write:
        _doc.update_doc(section, START, END)
    return 0


if __name__ == "__main__":
    sys.exit(main())
