"""Benchmark: size of the generated Unreal script against plant and field counts.

Target (issue 4): the Unreal script of a 10-field scene stays under 64 KB
whatever the plant count. The script inlines the placement kernel and one JSON
entry per field, never per-plant data, so its size should depend on the number
of fields only.

Run from the repository root::

    .venv/bin/python bench/bench_unreal_script_size.py             # measure, update the doc
    .venv/bin/python bench/bench_unreal_script_size.py --no-write  # measure only

Recipes are built the way the tests build them (field packer + ``build_field``
from the shipped knowledge base; ``tests/backends/unreal/unreal_recipes.py``):
fields of different crops sized so the scene holds about the target number of
plants. For the 1,000,000-plant scene the script is also executed with the
tests' recording fake as ``unreal`` in a fresh process: that measures the
Python work the editor does besides Unreal's own (the kernel computing every
position and one transform per plant); Unreal's instance creation is not in it.
Results go between this script's markers in ``docs/PERFORMANCE.md``.
"""

from __future__ import annotations

import argparse
import json
import os
import platform
import subprocess
import sys
import time
from pathlib import Path

import _doc

# The machine description and peak-memory probe are shared with the layout benchmark.
from bench_layout_usd import cpu_model, peak_rss_mb

REPO = Path(__file__).resolve().parent.parent
DOC = REPO / "docs" / "PERFORMANCE.md"
TESTS = REPO / "tests" / "backends" / "unreal"
START = "<!-- bench_unreal_script_size:start -->"
END = "<!-- bench_unreal_script_size:end -->"
TARGET_BYTES = 64 * 1024
PLANT_TARGETS = (10_000, 100_000, 1_000_000, 4_000_000)
FIELD_COUNTS = (1, 2, 5, 10, 20, 40, 64)


def _script_size(fields: int, plants: int) -> dict[str, float]:
    from unreal_recipes import mixed_crops, packed_recipe

    from agrirecipe import Scene
    from agrirecipe.backends.unreal import UnrealBackend

    recipe = packed_recipe(mixed_crops(fields), plants)
    start = time.perf_counter()
    script = UnrealBackend().script(Scene(recipe))
    seconds = time.perf_counter() - start
    return {
        "fields": fields,
        "target": plants,
        "nominal": recipe.nominal_plant_count,
        "bytes": len(script.encode("utf-8")),
        "seconds": seconds,
    }


def measure(execute: bool) -> dict[str, object]:
    sys.path.insert(0, str(TESTS))
    _script_size(1, 1_000)  # warm-up: one-off loading of the hierarchy and knowledge base
    by_plants = [_script_size(10, plants) for plants in PLANT_TARGETS]
    by_fields = [_script_size(fields, 1_000_000) for fields in FIELD_COUNTS]
    results: dict[str, object] = {"by_plants": by_plants, "by_fields": by_fields}
    if execute:
        output = subprocess.run(
            [sys.executable, __file__, "--child"], check=True, capture_output=True, text=True
        ).stdout
        results["execution"] = json.loads(output.splitlines()[-1])
    return results


def child() -> None:
    """Run the 10-field, 1M-plant script against the recording fake; print one JSON line."""
    sys.path.insert(0, str(TESTS))
    from fake_unreal import run_script
    from unreal_recipes import mixed_crops, packed_recipe

    from agrirecipe import Scene

    recipe = packed_recipe(mixed_crops(10), 1_000_000)
    script = Scene(recipe).script("unreal")
    before = peak_rss_mb()
    start, cpu_start = time.perf_counter(), time.process_time()
    namespace, recording = run_script(script)
    seconds, cpu_seconds = time.perf_counter() - start, time.process_time() - cpu_start
    result = namespace["AGRIRECIPE_RESULT"]
    print(
        json.dumps(
            {
                "plants": result["instances"],
                "seconds": seconds,
                "cpu_seconds": cpu_seconds,
                "peak_rss_mb": peak_rss_mb(),
                "rss_before_mb": before,
                "add_instances_calls": sum(
                    1 for event in recording.events if event.kind == "add_instances"
                ),
            }
        )
    )


def report(results: dict[str, object]) -> str:
    by_plants: list[dict[str, float]] = results["by_plants"]  # type: ignore[assignment]
    by_fields: list[dict[str, float]] = results["by_fields"]  # type: ignore[assignment]
    ten_field = [row["bytes"] for row in by_plants]
    verdict = "meets" if max(ten_field) < TARGET_BYTES else "MISSES"
    lines = [
        START,
        "## Unreal script size (`bench/bench_unreal_script_size.py`)",
        "",
        f"Machine: {cpu_model()}, {os.cpu_count()} cores, Python {platform.python_version()}, "
        f"{platform.system()} {platform.release()}; load average {os.getloadavg()[0]:.1f} when "
        f"the benchmark ended (other work inflates wall time, not CPU time). "
        f"Date: {time.strftime('%Y-%m-%d')}.",
        "",
        "`unreal_build.py` inlines the placement kernel and one JSON entry per field; "
        "Unreal computes every plant itself, so the size follows the number of fields, "
        "not plants.",
        "",
        "| fields | nominal plants | script size | generation time |",
        "|---|---|---|---|",
    ]
    for row in by_plants:
        lines.append(
            f"| {row['fields']:.0f} | {row['nominal']:,.0f} | {row['bytes'] / 1024:.1f} KB "
            f"({row['bytes']:,.0f} B) | {row['seconds'] * 1000:.0f} ms |"
        )
    lines += [
        "",
        "Field count at about 1,000,000 plants (64 fields is the recipe maximum):",
        "",
        "| fields | nominal plants | script size |",
        "|---|---|---|",
    ]
    for row in by_fields:
        lines.append(
            f"| {row['fields']:.0f} | {row['nominal']:,.0f} | {row['bytes'] / 1024:.1f} KB |"
        )
    per_field = (by_fields[-1]["bytes"] - by_fields[0]["bytes"]) / (
        by_fields[-1]["fields"] - by_fields[0]["fields"]
    )
    lines += [
        "",
        f"About {per_field / 1024:.2f} KB per field on top of "
        f"{(by_fields[0]['bytes'] - per_field) / 1024:.1f} KB of kernel and runtime code.",
        "",
        f"Target: a 10-field scene under 64 KB whatever the plant count ({verdict}: "
        f"{max(ten_field) / 1024:.1f} KB at most, from {min(ten_field):,.0f} to "
        f"{max(ten_field):,.0f} bytes over {by_plants[0]['nominal']:,.0f} to "
        f"{by_plants[-1]['nominal']:,.0f} plants).",
    ]
    execution = results.get("execution")
    if isinstance(execution, dict):
        lines += [
            "",
            f"Executing the 10-field script with the tests' recording fake as `unreal` "
            f"(kernel + one `Transform` per plant, {execution['plants']:,} plants in "
            f"{execution['add_instances_calls']} `add_instances` chunks): "
            f"{execution['seconds']:.1f} s wall, {execution['cpu_seconds']:.1f} s CPU, peak "
            f"{execution['peak_rss_mb']:.0f} MB resident "
            "(the fake keeps every transform). This is the Python side of a build in the "
            "editor; Unreal's own instance creation comes on top and is not measured here "
            "(no Unreal on this machine).",
        ]
    lines.append(END)
    return "\n".join(lines) + "\n"


def update_doc(section: str) -> None:
    """Replace this benchmark's section of docs/PERFORMANCE.md (append it the first time)."""
    _doc.update_doc(section, START, END, DOC)


def main() -> int:
    parser = argparse.ArgumentParser(description=(__doc__ or "").split("\n\n")[0])
    parser.add_argument("--no-write", action="store_true", help="do not update docs/PERFORMANCE.md")
    parser.add_argument(
        "--no-execute", action="store_true", help="skip running the 1M-plant script in the fake"
    )
    parser.add_argument("--child", action="store_true", help=argparse.SUPPRESS)
    options = parser.parse_args()
    if options.child:
        child()
        return 0
    results = measure(execute=not options.no_execute)
    section = report(results)
    print(section)
    if not options.no_write:
        update_doc(section)
        print(f"updated {DOC.relative_to(REPO)}")
    by_plants: list[dict[str, float]] = results["by_plants"]  # type: ignore[assignment]
    return 0 if max(row["bytes"] for row in by_plants) < TARGET_BYTES else 1


if __name__ == "__main__":
    sys.exit(main())
