"""Benchmark: Blender scene build for a 1,000,000-plant recipe (target: under 60 s).

Generates ``blender_build.py`` for the same ~1M-plant recipe as
``bench_layout_usd.py`` (wheat, carrot, maize, lettuce, apple fields), then runs
it in a fresh Python process with the real ``bpy`` module, exactly as
``python blender_build.py`` does (no render): the inlined pure-Python kernel
places every plant, the point clouds are filled, the plant library's meshes
(written to ``assets/`` beside the script) are imported and Geometry Nodes
instancers are set up. The Geometry Nodes evaluation of every instance (what
a render or the viewport triggers) is timed separately, and the instances are
counted against the layout. Peak memory is the child's ``ru_maxrss``. With
``--render WxH`` the built scene is also rendered with CPU Cycles.

Run from the repository root::

    .venv/bin/python bench/bench_blender.py                     # measure, update the doc
    .venv/bin/python bench/bench_blender.py --render 960x540    # also time a render
    .venv/bin/python bench/bench_blender.py --no-write          # measure only

Results go between this script's markers in ``docs/PERFORMANCE.md``.
"""

from __future__ import annotations

import argparse
import json
import os
import platform
import runpy
import subprocess
import sys
import tempfile
import time
from pathlib import Path
from typing import Any

import _doc

# The recipe, machine description and peak-memory probe are shared with the layout benchmark.
from bench_layout_usd import build_recipe, cpu_model, peak_rss_mb

REPO = Path(__file__).resolve().parent.parent
DOC = REPO / "docs" / "PERFORMANCE.md"
START = "<!-- bench_blender:start -->"
END = "<!-- bench_blender:end -->"
TARGET_SECONDS = 60.0


def child(script: str, render: str | None, samples: int) -> None:
    """Run the script in this fresh process; print one JSON line of measurements."""
    rss_start = peak_rss_mb()
    started, cpu_started = time.perf_counter(), time.process_time()
    import bpy

    imported = time.perf_counter()
    sys.argv = [script]
    namespace = runpy.run_path(script, run_name="__main__")
    built, cpu_built = time.perf_counter(), time.process_time()
    report = namespace["AGRIRECIPE_REPORT"]
    depsgraph = bpy.context.evaluated_depsgraph_get()
    instances = {}
    for field_id in report["plants"]:
        geometry = bpy.data.objects[field_id].evaluated_get(depsgraph).evaluated_geometry()
        cloud = geometry.instances_pointcloud()
        instances[field_id] = 0 if cloud is None else len(cloud.points)
    evaluated, cpu_evaluated = time.perf_counter(), time.process_time()
    result: dict[str, Any] = {
        "bpy_version": bpy.app.version_string,
        "rss_start_mb": rss_start,
        "import_bpy_s": imported - started,
        "script_s": built - imported,
        "script_cpu_s": cpu_built - cpu_started,
        "builder_s": report["seconds"],
        "timings": report["timings"],
        "plants": report["plants"],
        "evaluate_s": evaluated - built,
        "evaluate_cpu_s": cpu_evaluated - cpu_built,
        "instances": instances,
        "peak_rss_build_mb": peak_rss_mb(),
    }
    if render:
        width, _, height = render.partition("x")
        scene = report["scene"]
        scene.render.resolution_x, scene.render.resolution_y = int(width), int(height)
        scene.cycles.samples = samples
        scene.render.filepath = str(Path(script).with_name("bench_render.png"))
        render_started, cpu_render = time.perf_counter(), time.process_time()
        bpy.ops.render.render(write_still=True)
        result["render"] = {
            "resolution": render,
            "samples": samples,
            "seconds": time.perf_counter() - render_started,
            "cpu_s": time.process_time() - cpu_render,
            "peak_rss_mb": peak_rss_mb(),
        }
    print("BENCH " + json.dumps(result))


def measure(target_plants: int, seed: int, render: str | None, samples: int) -> dict[str, Any]:
    from agrirecipe import Scene
    from agrirecipe.backends.blender import blender_script

    recipe = build_recipe(target_plants, seed)
    generated = time.perf_counter()
    script = blender_script(recipe)
    generated = time.perf_counter() - generated
    layout = Scene(recipe).layout
    with tempfile.TemporaryDirectory(prefix="bench-blender-") as folder:
        from agrirecipe.plants import write_scene_assets

        path = Path(folder) / "blender_build.py"
        path.write_text(script, encoding="utf-8")
        meshes_started = time.perf_counter()
        write_scene_assets(recipe, folder)  # the plant library's meshes, beside the script
        meshes_s = time.perf_counter() - meshes_started
        command = [sys.executable, __file__, "--child", str(path), "--samples", str(samples)]
        if render:
            command += ["--render", render]
        started = time.perf_counter()
        completed = subprocess.run(command, capture_output=True, text=True, check=False)
        process_s = time.perf_counter() - started
    if completed.returncode != 0:
        sys.exit(f"the bpy child failed:\n{completed.stdout[-3000:]}\n{completed.stderr[-3000:]}")
    line = next(x for x in completed.stdout.splitlines() if x.startswith("BENCH "))
    result: dict[str, Any] = json.loads(line.removeprefix("BENCH "))
    result.update(
        recipe=recipe,
        expected={plants.field_id: plants.plant_count for plants in layout.fields},
        script_bytes=len(script.encode("utf-8")),
        meshes_s=meshes_s,
        generate_s=generated,
        process_s=process_s,
        load=os.getloadavg()[0],
    )
    return result


def report(result: dict[str, Any]) -> str:
    """The Markdown section for docs/PERFORMANCE.md."""
    recipe = result["recipe"]
    timings = result["timings"]
    plants = sum(result["plants"].values())
    build_total = result["script_s"] + result["evaluate_s"]
    verdict = "met" if result["script_s"] < TARGET_SECONDS else "MISSED"
    counts_ok = result["instances"] == result["expected"]
    lines = [
        START,
        "## Blender scene build, 1,000,000 plants (`bench/bench_blender.py`)",
        "",
        f"Machine: {cpu_model()}, {os.cpu_count()} cores, Python {platform.python_version()}, "
        f"bpy {result['bpy_version']}, {platform.system()} {platform.release()}; load average "
        f"{result['load']:.1f} when the benchmark ended (other work on the machine inflates "
        f"wall time, not CPU time). Date: {time.strftime('%Y-%m-%d')}.",
        "",
        f"Recipe: the `bench_layout_usd.py` recipe, {len(recipe.fields)} fields, "
        f"{recipe.nominal_plant_count:,} nominal planting positions, {plants:,} plants. "
        f"`blender_build.py` is {result['script_bytes'] / 1024:.1f} KB (generated in "
        f"{result['generate_s'] * 1000:.0f} ms) and is run in a fresh process with the bpy "
        "module, as `python blender_build.py` (no render).",
        "",
        "| field | crop | growth form | plants (layout) | instances after evaluation |",
        "|---|---|---|---|---|",
    ]
    for spec in recipe.fields:
        lines.append(
            f"| {spec.id} | {spec.crop} | {spec.agronomy.growth_form} | "
            f"{result['expected'][spec.id]:,} | {result['instances'][spec.id]:,} |"
        )
    lines += [
        "",
        "| stage | wall | CPU |",
        "|---|---|---|",
        f"| `import bpy` (fresh process) | {result['import_bpy_s']:.2f} s | |",
        f"| **script execution: scene built** | **{result['script_s']:.2f} s** | "
        f"{result['script_cpu_s']:.2f} s (with the import) |",
        f"| - placement kernel, pure Python in Blender | {timings['kernel']:.2f} s | |",
        f"| - point clouds (`foreach_set` of positions, yaw, scale, height) | "
        f"{timings['points']:.2f} s | |",
        f"| - plant meshes: the .glb variants imported (written beside the script in "
        f"{result['meshes_s']:.2f} s) | {timings['proxies']:.2f} s | |",
        f"| - factory reset, node group, ground, sun, camera, sky | {timings['rest']:.2f} s | |",
        f"| Geometry Nodes evaluation of every instance (depsgraph) | "
        f"{result['evaluate_s']:.2f} s | {result['evaluate_cpu_s']:.2f} s |",
        f"| **build + evaluation** | **{build_total:.2f} s** | |",
        "| whole child process (start-up, import, build, evaluation"
        + (", render" if "render" in result else "")
        + f") | {result['process_s']:.2f} s | |",
        "",
        f"Peak memory: {result['peak_rss_build_mb']:,.0f} MB resident (`ru_maxrss` of the "
        "child: Python, bpy, the kernel's list of plant tuples and Blender's evaluated "
        "instances).",
    ]
    if "render" in result:
        render = result["render"]
        lines += [
            "",
            f"Render of the built scene with CPU Cycles at {render['resolution']}, "
            f"{render['samples']} samples, denoised: {render['seconds']:.1f} s wall, "
            f"{render['cpu_s']:.1f} s CPU, peak {render['peak_rss_mb']:,.0f} MB resident.",
        ]
    lines += [
        "",
        f"Target: Blender scene build for a 1,000,000-plant recipe under {TARGET_SECONDS:.0f} s "
        f"({verdict}: {result['script_s']:.1f} s for the script, {build_total:.1f} s with the "
        "instance evaluation). Every field's evaluated instance count "
        + ("equals" if counts_ok else "DIFFERS FROM")
        + " the layout's plant count.",
        END,
    ]
    return "\n".join(lines) + "\n"


def main() -> int:
    parser = argparse.ArgumentParser(description=(__doc__ or "").split("\n\n")[0])
    parser.add_argument("--plants", type=int, default=1_000_000, help="target nominal plant count")
    parser.add_argument("--seed", type=int, default=0)
    parser.add_argument("--render", metavar="WxH", help="also render, e.g. 960x540")
    parser.add_argument("--samples", type=int, default=16, help="render samples (default 16)")
    parser.add_argument("--no-write", action="store_true", help="do not update docs/PERFORMANCE.md")
    parser.add_argument("--child", metavar="SCRIPT", help=argparse.SUPPRESS)
    options = parser.parse_args()
    if options.child:
        child(options.child, options.render, options.samples)
        return 0
    result = measure(options.plants, options.seed, options.render, options.samples)
    section = report(result)
    print(section)
    if not options.no_write:
        update_doc(section)
        print(f"updated {DOC.relative_to(REPO)}")
    met = result["script_s"] < TARGET_SECONDS and result["instances"] == result["expected"]
    return 0 if met else 1


def update_doc(section: str) -> None:
    """Replace this benchmark's section of docs/PERFORMANCE.md (append it the first time)."""
    _doc.update_doc(section, START, END, DOC)


if __name__ == "__main__":
    sys.exit(main())
