"""Blender renders for the app: a child process per job, with progress and cancel.

The script is the Blender backend's own (:func:`agrirecipe.backends.blender.blender_script`,
as ``agrirecipe render`` uses); a small driver runs it in a child Python process
with ``bpy`` after hooking Blender's render statistics, so the job can report
"Sample 5/16" as a fraction. Cancelling kills the child. The PNG appears in the
scene's folder as ``render.png`` only when Blender finished it.
"""

from __future__ import annotations

import re
import secrets
import subprocess
import sys
import threading
import time
from dataclasses import dataclass, field
from pathlib import Path
from typing import TYPE_CHECKING, Literal

from agrirecipe._errors import AgrirecipeError, ConfigurationError

if TYPE_CHECKING:
    from agrirecipe._scene import Scene

__all__ = ["RenderJob", "RenderJobs", "RenderState"]

RenderState = Literal["queued", "running", "done", "failed", "cancelled"]
RENDER_NAME = "render.png"
_DRIVER = '''\
"""Run blender_build.py with Blender's render statistics printed (agrirecipe app)."""
import runpy
import bpy

def _stats(text, *_):
    print("agrirecipe-stats:", text, flush=True)

bpy.app.handlers.render_stats.append(_stats)
runpy.run_path("blender_build.py", run_name="__main__")
'''
_FIELD_LINE = re.compile(r"^agrirecipe: [a-z][a-z0-9_]*: [\d,]+ plants")
_SAMPLE = re.compile(r"Sample (\d+)/(\d+)")
_LOG_LINES = 12
# Shares of the bar: building the scene, then Cycles' samples.
_BUILD_SHARE = 0.3


@dataclass
class RenderJob:
    """One render: its state, progress (0..1) and, when done, the image's path."""

    id: str
    scene_id: str
    state: RenderState = "queued"
    progress: float = 0.0
    message: str = "waiting for Blender"
    image: Path | None = None
    error: str | None = None
    started: float = field(default_factory=time.monotonic)
    seconds: float = 0.0
    _process: subprocess.Popen[str] | None = None
    _cancelled: bool = False

    def public(self) -> dict[str, object]:
        """The job as JSON-able values for the page."""
        return {
            "id": self.id,
            "scene_id": self.scene_id,
            "state": self.state,
            "progress": round(self.progress, 3),
            "message": self.message,
            "error": self.error,
            "seconds": round(self.seconds, 1),
            "image": RENDER_NAME if self.state == "done" else None,
        }


class RenderJobs:
    """Render jobs by id; each runs Blender in its own child process on its own thread."""

    def __init__(self, *, timeout_s: float = 1800.0) -> None:
        self.timeout_s = timeout_s
        self._jobs: dict[str, RenderJob] = {}
        self._lock = threading.Lock()

    def start(
        self,
        scene: Scene,
        folder: Path,
        scene_id: str,
        *,
        resolution: tuple[int, int] = (960, 540),
        samples: int = 16,
        view: Literal["overview", "ground"] = "overview",
    ) -> RenderJob:
        """Write the Blender script into ``folder`` and start rendering it."""
        import importlib.util

        from agrirecipe.backends.blender import RenderSettings, blender_script

        if importlib.util.find_spec("bpy") is None:
            raise ConfigurationError(
                "rendering needs Blender's Python module bpy",
                stage="render",
                hint="pip install 'agrirecipe[blender]'",
            )
        settings = RenderSettings(resolution=resolution, samples=samples, view=view)
        work = folder / ".render"
        work.mkdir(parents=True, exist_ok=True)
        target = folder / RENDER_NAME
        partial = work / "partial.png"
        partial.unlink(missing_ok=True)
        script = blender_script(
            scene, settings, render_png=partial, verbose=True, assets_root=folder
        )
        (work / "blender_build.py").write_text(script, encoding="utf-8")
        (work / "driver.py").write_text(_DRIVER, encoding="utf-8")
        job = RenderJob(id=secrets.token_hex(6), scene_id=scene_id)
        with self._lock:
            self._jobs[job.id] = job
        fields = len(scene.recipe.fields)
        thread = threading.Thread(
            target=self._run, args=(job, work, partial, target, fields), daemon=True
        )
        thread.start()
        return job

    def get(self, job_id: str) -> RenderJob:
        """A job by id."""
        with self._lock:
            job = self._jobs.get(job_id)
        if job is None:
            from agrirecipe.app._history import SceneNotFoundError

            raise SceneNotFoundError(f"no render job {job_id[:40]!r}", stage="render")
        return job

    def cancel(self, job_id: str) -> RenderJob:
        """Stop a job: its Blender child is killed; a finished job is left as it is."""
        job = self.get(job_id)
        job._cancelled = True
        process = job._process
        if process is not None and process.poll() is None:
            process.kill()
        return job

    def close(self) -> None:
        """Kill every Blender child still running (the app is stopping)."""
        with self._lock:
            jobs = list(self._jobs.values())
        for job in jobs:
            if job.state in ("queued", "running"):
                self.cancel(job.id)

    def _run(self, job: RenderJob, work: Path, partial: Path, target: Path, fields: int) -> None:
        log: list[str] = []
        built = 0
        try:
            job.state, job.message = "running", "building the scene in Blender"
            process = subprocess.Popen(
                [sys.executable, "-u", "driver.py"],
                cwd=work,
                stdout=subprocess.PIPE,
                stderr=subprocess.STDOUT,
                text=True,
                errors="replace",
            )
            job._process = process
            if job._cancelled:  # cancelled before the child existed
                process.kill()
            watchdog = threading.Timer(self.timeout_s, process.kill)
            watchdog.daemon = True
            watchdog.start()
            assert process.stdout is not None
            for raw in process.stdout:
                line = raw.rstrip()
                log = [*log[-_LOG_LINES:], line]
                if _FIELD_LINE.match(line):
                    built += 1
                    job.progress = _BUILD_SHARE * min(1.0, built / max(1, fields))
                    job.message = f"placed the plants of {built} of {fields} field(s)"
                elif line.startswith("agrirecipe: built"):
                    job.progress, job.message = _BUILD_SHARE, line.removeprefix("agrirecipe: ")
                elif (match := _SAMPLE.search(line)) is not None:
                    done, total = int(match.group(1)), max(1, int(match.group(2)))
                    job.progress = _BUILD_SHARE + (1 - _BUILD_SHARE) * done / total
                    job.message = f"rendering: sample {done} of {total}"
            code = process.wait()
            watchdog.cancel()
            if job._cancelled:
                job.state, job.message = "cancelled", "cancelled"
            elif code != 0 or not partial.is_file():
                job.state, job.message = "failed", "Blender failed"
                job.error = f"Blender exited with status {code}:\n" + "\n".join(log)
            else:
                partial.replace(target)
                job.image = target
                job.state, job.progress, job.message = "done", 1.0, "rendered"
        except (OSError, AgrirecipeError) as exc:
            job.state, job.message, job.error = "failed", "Blender could not start", str(exc)
        finally:
            job.seconds = time.monotonic() - job.started
            partial.unlink(missing_ok=True)
