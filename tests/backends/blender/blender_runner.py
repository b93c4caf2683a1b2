"""Run generated ``blender_build.py`` scripts in real bpy, one child process per scene."""

from __future__ import annotations

import json
import subprocess
import sys
from collections.abc import Sequence
from pathlib import Path
from typing import Any

import pytest

from agrirecipe import Scene
from agrirecipe.backends.blender import SCRIPT_NAME, BlenderBackend
from agrirecipe.recipe import SceneRecipe

__all__ = ["build_in_bpy", "run_in_bpy"]

PROBE = Path(__file__).with_name("blender_probe.py")


def run_in_bpy(script: Path, output: Path, args: Sequence[str] = ()) -> dict[str, Any]:
    """Run ``script`` as ``python blender_build.py ARGS`` would, in a child with real bpy.

    Returns the probe's description of the built scene (plus ``"log"``, the
    script's output); fails the test with Blender's output when the child fails.
    """
    completed = subprocess.run(
        [sys.executable, str(PROBE), str(script), str(output), *args],
        capture_output=True,
        text=True,
        errors="replace",
        cwd=script.parent,
        timeout=600,
        check=False,
    )
    if completed.returncode != 0:
        pytest.fail(f"bpy child failed:\n{completed.stdout[-4000:]}\n{completed.stderr[-4000:]}")
    description: dict[str, Any] = json.loads(output.read_text(encoding="utf-8"))
    description["log"] = completed.stdout
    return description


def build_in_bpy(recipe: SceneRecipe, folder: Path, args: Sequence[str] = ()) -> dict[str, Any]:
    """Write the recipe's ``blender_build.py`` into ``folder`` and run it in bpy."""
    BlenderBackend().write(Scene(recipe), folder)
    return run_in_bpy(folder / SCRIPT_NAME, folder / "probe.json", args)
