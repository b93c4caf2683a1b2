"""Benchmark: lay out a ~1,000,000-plant recipe and write its OpenUSD stage.

Target (issue 4): layout + USD write under 10 s and under 1.5 GB peak memory.

Run from the repository root::

    .venv/bin/python bench/bench_layout_usd.py            # measure and update docs/PERFORMANCE.md
    .venv/bin/python bench/bench_layout_usd.py --no-write # measure only

The recipe is a mixed farm built the way the resolver builds one (field packer
+ ``build_field`` from the shipped knowledge base): wheat, carrots, maize,
lettuce and an apple orchard, sized so the nominal plant count is about one
million. Each stage is timed separately, the best of ``--repeat`` runs is
reported with the median, and peak memory is the process's peak resident set
size (``ru_maxrss``: everything, including numpy buffers and OpenUSD's C++
allocations), plus tracemalloc's peak for the layout alone. Results go into
``docs/PERFORMANCE.md`` between this benchmark's markers, leaving other
sections untouched.
"""

from __future__ import annotations

import argparse
import importlib
import json
import math
import os
import platform
import resource
import statistics
import subprocess
import sys
import tempfile
import time
import tracemalloc
from collections.abc import Callable
from dataclasses import dataclass, field
from functools import partial
from pathlib import Path
from typing import TypeVar

import _doc

from agrirecipe.recipe import SceneRecipe

REPO = Path(__file__).resolve().parent.parent
DOC = REPO / "docs" / "PERFORMANCE.md"
START = "<!-- bench_layout_usd:start -->"
END = "<!-- bench_layout_usd:end -->"
TARGET_SECONDS = 10.0
TARGET_PEAK_MB = 1536.0
# Share of the plants per crop (a farm, not one giant field).
T = TypeVar("T")
MIX = (("Wheat", 0.40), ("Carrot", 0.30), ("Maize", 0.15), ("Lettuce", 0.10), ("Apple", 0.05))


def build_recipe(target_plants: int, seed: int) -> SceneRecipe:
    """A recipe of the MIX crops with about ``target_plants`` nominal plants."""
    from agrirecipe.enrich import build_environment, build_field
    from agrirecipe.hierarchy import default_hierarchy
    from agrirecipe.knowledge import default_knowledge_base
    from agrirecipe.layout import FieldRequest, pack_fields

    hierarchy, knowledge = default_hierarchy(), default_knowledge_base()
    requests = []
    for crop, share in MIX:
        planting = knowledge.crop_file(crop).planting
        per_m2 = planting.rows_per_bed / (
            planting.row_spacing_m.value * planting.in_row_spacing_m.value
        )
        headland = knowledge.default_headland_m(crop)
        width, length = knowledge.default_field_size_m(crop)
        area = target_plants * share / per_m2
        aspect = length / width
        usable_w = math.sqrt(area / aspect)
        requests.append(
            FieldRequest(
                id=crop.lower(),
                width_m=round(usable_w + 2 * headland, 1),
                length_m=round(usable_w * aspect + 2 * headland, 1),
                headland_m=headland,
            )
        )
    geometry = pack_fields(requests)
    fields = []
    for crop, _ in MIX:
        fields.append(
            build_field(
                hierarchy=hierarchy,
                knowledge=knowledge,
                field_id=crop.lower(),
                label=f"{crop} field",
                crop=crop,
                variety=knowledge.default_variety(crop),
                stage=knowledge.typical_stage(crop, "Summer"),
                season="Summer",
                health="Healthy",
                geometry=geometry[crop.lower()],
            )
        )
    return SceneRecipe(
        prompt="benchmark: a one-million-plant farm",
        seed=seed,
        environment=build_environment("Summer"),
        fields=tuple(fields),
    )


@dataclass
class Timing:
    """Wall-clock and CPU seconds of one run (CPU time is steadier on a shared machine)."""

    wall_s: float
    cpu_s: float


def timed(function: Callable[[], T]) -> tuple[Timing, T]:
    wall, cpu = time.perf_counter(), time.process_time()
    result = function()
    return Timing(time.perf_counter() - wall, time.process_time() - cpu), result


def best(runs: list[Timing]) -> Timing:
    return min(runs, key=lambda run: run.wall_s)


def peak_rss_mb() -> float:
    # Linux reports ru_maxrss in KiB (macOS in bytes).
    scale = 1024.0 if sys.platform != "darwin" else 1.0
    return resource.getrusage(resource.RUSAGE_SELF).ru_maxrss * scale / 2**20


def cpu_model() -> str:
    try:
        for line in Path("/proc/cpuinfo").read_text().splitlines():
            if line.startswith("model name"):
                return line.split(":", 1)[1].strip()
    except OSError:
        pass
    return platform.processor() or "unknown CPU"


@dataclass
class Results:
    """Everything the report needs."""

    recipe: SceneRecipe
    plant_counts: list[int]
    build: Timing
    pxr_import: Timing
    layout_runs: list[Timing]
    usd_runs: list[Timing]
    kernel: Timing
    annotations: Timing
    usda_mb: float
    layout_traced_peak_mb: float
    fresh: dict[str, float] = field(default_factory=dict)

    @property
    def total(self) -> Timing:
        layout, usd = best(self.layout_runs), best(self.usd_runs)
        return Timing(layout.wall_s + usd.wall_s, layout.cpu_s + usd.cpu_s)


def measure(target_plants: int, repeat: int, seed: int) -> Results:
    from agrirecipe import Scene
    from agrirecipe.backends.annotations import AnnotationsBackend
    from agrirecipe.backends.usd import UsdBackend
    from agrirecipe.layout import field_parameters, layout_scene, place_field

    build, recipe = timed(lambda: build_recipe(target_plants, seed))
    # Import pxr once outside the timings: a one-off cost of any process using USD.
    pxr_import, _ = timed(lambda: importlib.import_module("pxr.Usd"))

    tracemalloc.start()
    first, layout = timed(lambda: layout_scene(recipe))
    _, layout_traced_peak = tracemalloc.get_traced_memory()
    tracemalloc.stop()
    layout_runs = [first] + [timed(lambda: layout_scene(recipe))[0] for _ in range(repeat - 1)]

    usd_runs = []
    with tempfile.TemporaryDirectory() as folder:
        for _ in range(repeat):
            scene = Scene(recipe)
            scene.__dict__["layout"] = layout  # reuse the cached layout: time the USD write alone
            usd_runs.append(timed(partial(UsdBackend().write, scene, Path(folder)))[0])
        usda_mb = (Path(folder) / "scene.usda").stat().st_size / 2**20
        annotations, _ = timed(partial(AnnotationsBackend().write, scene, Path(folder)))

    kernel, _ = timed(lambda: [len(place_field(p)) for p in field_parameters(recipe)])
    return Results(
        recipe=recipe,
        plant_counts=[plants.plant_count for plants in layout.fields],
        build=build,
        pxr_import=pxr_import,
        layout_runs=layout_runs,
        usd_runs=usd_runs,
        kernel=kernel,
        annotations=annotations,
        usda_mb=usda_mb,
        layout_traced_peak_mb=layout_traced_peak / 2**20,
        fresh=fresh_process(target_plants, seed),
    )


def fresh_process(target_plants: int, seed: int) -> dict[str, float]:
    """End-to-end time and peak memory of recipe -> layout -> scene.usda in a new process.

    A separate process, so the peak is that of exactly this work (``ru_maxrss``
    only grows) and includes Python, numpy and OpenUSD as a user would run them.
    """
    command = [sys.executable, __file__, "--child", "--plants", str(target_plants)]
    command += ["--seed", str(seed)]
    output = subprocess.run(command, check=True, capture_output=True, text=True).stdout
    values: dict[str, float] = json.loads(output.splitlines()[-1])
    return values


def child(target_plants: int, seed: int) -> None:
    """The work measured by :func:`fresh_process`; prints one JSON line."""
    from agrirecipe import Scene
    from agrirecipe.backends.usd import UsdBackend

    recipe = build_recipe(target_plants, seed)
    with tempfile.TemporaryDirectory() as folder:
        run, _ = timed(partial(UsdBackend().write, Scene(recipe), Path(folder)))
    print(json.dumps({"wall_s": run.wall_s, "cpu_s": run.cpu_s, "peak_rss_mb": peak_rss_mb()}))


def report(results: Results) -> str:
    import numpy
    from pxr import Usd

    recipe = results.recipe
    total = results.total
    peak = results.fresh["peak_rss_mb"]
    verdict_time = "met" if total.wall_s < TARGET_SECONDS else "MISSED"
    verdict_memory = "met" if peak < TARGET_PEAK_MB else "MISSED"
    layout, usd = best(results.layout_runs), best(results.usd_runs)
    repeat = len(results.usd_runs)
    median_layout = statistics.median(run.wall_s for run in results.layout_runs)
    median_usd = statistics.median(run.wall_s for run in results.usd_runs)
    load = os.getloadavg()[0] if hasattr(os, "getloadavg") else float("nan")
    lines = [
        START,
        "## Layout + OpenUSD write, 1,000,000 plants (`bench/bench_layout_usd.py`)",
        "",
        f"Machine: {cpu_model()}, {os.cpu_count()} cores, Python {platform.python_version()}, "
        f"numpy {numpy.__version__}, OpenUSD {'.'.join(map(str, Usd.GetVersion()))}, "
        f"{platform.system()} {platform.release()}; load average {load:.1f} when the "
        f"benchmark ended (other work on the machine inflates wall time, not CPU time). "
        f"Date: {time.strftime('%Y-%m-%d')}.",
        "",
        f"Recipe: {len(recipe.fields)} fields packed by `pack_fields`, "
        f"{recipe.nominal_plant_count:,} nominal planting positions, "
        f"{sum(results.plant_counts):,} plants after seeded missing plants.",
        "",
        "| field | crop | pattern | size (m) | plants |",
        "|---|---|---|---|---|",
    ]
    for spec, count in zip(recipe.fields, results.plant_counts, strict=True):
        width, length = spec.geometry.size_m
        pattern = spec.agronomy.planting_pattern
        lines.append(
            f"| {spec.id} | {spec.crop} | {pattern} | {width:g} x {length:g} | {count:,} |"
        )
    lines += [
        "",
        f"| stage | wall, best of {repeat} | wall, median | CPU |",
        "|---|---|---|---|",
        f"| `layout_scene` (numpy path, bit-identical to the kernel) | {layout.wall_s:.2f} s "
        f"| {median_layout:.2f} s | {layout.cpu_s:.2f} s |",
        f"| `UsdBackend.write` -> scene.usda ({results.usda_mb:.0f} MB of text) "
        f"| {usd.wall_s:.2f} s | {median_usd:.2f} s | {usd.cpu_s:.2f} s |",
        f"| **layout + USD write** | **{total.wall_s:.2f} s** | | {total.cpu_s:.2f} s |",
        f"| fresh process: `Scene(recipe)` -> scene.usda, layout included "
        f"| {results.fresh['wall_s']:.2f} s | | {results.fresh['cpu_s']:.2f} s |",
        f"| one-off `import pxr.Usd` | {results.pxr_import.wall_s:.2f} s | | "
        f"{results.pxr_import.cpu_s:.2f} s |",
        f"| recipe construction (packer + knowledge base) | {results.build.wall_s:.2f} s | | "
        f"{results.build.cpu_s:.2f} s |",
        f"| `AnnotationsBackend.write` (plants.csv, fields.geojson, preview.png) "
        f"| {results.annotations.wall_s:.2f} s | | {results.annotations.cpu_s:.2f} s |",
        f"| pure-Python kernel `place_field`, every field (what engine scripts run) "
        f"| {results.kernel.wall_s:.2f} s | | {results.kernel.cpu_s:.2f} s |",
        "",
        f"Peak memory: {peak:.0f} MB resident (`ru_maxrss`) for a fresh process that imports "
        "agrirecipe, builds the recipe, lays it out and writes scene.usda (Python, numpy and "
        "OpenUSD's C++ buffers included); the layout's own allocations peak at "
        f"{results.layout_traced_peak_mb:.0f} MB (tracemalloc).",
        "",
        f"Target: layout + USD write under {TARGET_SECONDS:g} s ({verdict_time}: "
        f"{total.wall_s:.2f} s) and under {TARGET_PEAK_MB / 1024:g} GB peak memory "
        f"({verdict_memory}: {peak:.0f} MB).",
        END,
    ]
    return "\n".join(lines) + "\n"


def update_doc(section: str) -> None:
    """Replace this benchmark's section of docs/PERFORMANCE.md (append it the first time)."""
    _doc.update_doc(section, START, END, DOC)


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--plants", type=int, default=1_000_000, help="target nominal plant count")
    parser.add_argument("--repeat", type=int, default=3, help="timed runs per stage")
    parser.add_argument("--seed", type=int, default=0)
    parser.add_argument("--no-write", action="store_true", help="do not update docs/PERFORMANCE.md")
    parser.add_argument("--child", action="store_true", help=argparse.SUPPRESS)
    options = parser.parse_args()
    if options.child:
        child(options.plants, options.seed)
        return 0
    results = measure(options.plants, options.repeat, options.seed)
    section = report(results)
    print(section)
    if not options.no_write:
        update_doc(section)
        print(f"updated {DOC.relative_to(REPO)}")
    met = results.total.wall_s < TARGET_SECONDS and results.fresh["peak_rss_mb"] < TARGET_PEAK_MB
    return 0 if met else 1


if __name__ == "__main__":
    sys.exit(main())
