"""The app's scenes on disk: one output folder each, and their history in SQLite.

Everything lives under one root in the cache folder (``cache_dir()/app`` by
default)::

    app/history.sqlite3        one row per scene the app made (survives a restart)
    app/scenes/<id>/           recipe.json, preview.png, assets/, every backend's outputs,
                               render.png
    app/zips/<id>.zip          the download of a scene's outputs

Scene ids are 12 lowercase hex digits. :meth:`SceneStore.file` is the only way
a route turns a request into a path, and it never leaves the scene's folder:
the joined path is resolved (symbolic links and ``..`` included) and must stay
inside the resolved folder.
"""

from __future__ import annotations

import json
import re
import secrets
import sqlite3
import threading
from collections.abc import Iterator, Sequence
from contextlib import contextmanager
from dataclasses import dataclass
from datetime import UTC, datetime
from pathlib import Path

from agrirecipe._errors import UserInputError

__all__ = ["SceneNotFoundError", "SceneRecord", "SceneStore", "UnsafePathError"]

_SCENE_ID = re.compile(r"^[0-9a-f]{12}$")
_SCHEMA = """
CREATE TABLE IF NOT EXISTS scenes (
    id TEXT PRIMARY KEY,
    created TEXT NOT NULL,
    action TEXT NOT NULL,
    text TEXT NOT NULL,
    parent TEXT,
    changes TEXT NOT NULL,
    summary TEXT NOT NULL,
    field_count INTEGER NOT NULL,
    plant_count INTEGER NOT NULL,
    explanation TEXT
)
"""
_COLUMNS = (
    "id, created, action, text, parent, changes, summary, field_count, plant_count, explanation"
)


class SceneNotFoundError(UserInputError):
    """A scene id or a file of a scene that the app does not hold."""


class UnsafePathError(UserInputError):
    """A file path that would leave the scene's own output folder."""


@dataclass(frozen=True, slots=True)
class SceneRecord:
    """One scene of the history: how it was made and what it holds.

    ``action`` is ``"prompt"``, ``"edit"`` (a change made in the field table),
    ``"refine"`` (an instruction in words) or ``"upload"`` (a recipe file);
    ``text`` is the prompt, the instruction or the edit described in words;
    ``parent`` the scene it was made from; ``changes`` the recipe's diff lines.
    """

    id: str
    created: str
    action: str
    text: str
    parent: str | None
    changes: tuple[str, ...]
    summary: str
    field_count: int
    plant_count: int
    explanation: str | None = None

    def public(self) -> dict[str, object]:
        """The record as JSON-able values for the page (without the explanation text)."""
        return {
            "id": self.id,
            "created": self.created,
            "action": self.action,
            "text": self.text,
            "parent": self.parent,
            "changes": list(self.changes),
            "summary": self.summary,
            "field_count": self.field_count,
            "plant_count": self.plant_count,
        }


class SceneStore:
    """The scene folders and the SQLite history under ``root`` (created if needed)."""

    def __init__(self, root: str | Path) -> None:
        self.root = Path(root).resolve()
        self.scenes_dir = self.root / "scenes"
        self.zips_dir = self.root / "zips"
        for folder in (self.scenes_dir, self.zips_dir):
            folder.mkdir(parents=True, exist_ok=True)
        self.database = self.root / "history.sqlite3"
        self._write_lock = threading.Lock()
        with self._connect() as connection:
            connection.execute("PRAGMA journal_mode=WAL")
            connection.execute(_SCHEMA)

    @contextmanager
    def _connect(self) -> Iterator[sqlite3.Connection]:
        # One short-lived connection per call: sqlite3 connections are not shared
        # between the server's worker threads.
        connection = sqlite3.connect(self.database, timeout=10.0)
        try:
            with connection:
                yield connection
        finally:
            connection.close()

    @staticmethod
    def new_id() -> str:
        """A fresh random scene id (12 hex digits)."""
        return secrets.token_hex(6)

    @staticmethod
    def check_id(scene_id: str) -> str:
        """``scene_id`` if it has the form of a scene id, else :class:`SceneNotFoundError`."""
        if not _SCENE_ID.fullmatch(scene_id):
            raise SceneNotFoundError(
                f"{scene_id[:40]!r} is not a scene id", stage="app", hint="12 hex digits"
            )
        return scene_id

    def folder(self, scene_id: str) -> Path:
        """The output folder of a scene (it may not exist yet)."""
        return self.scenes_dir / self.check_id(scene_id)

    def add(
        self,
        *,
        scene_id: str,
        action: str,
        text: str,
        parent: str | None,
        changes: Sequence[str],
        summary: str,
        field_count: int,
        plant_count: int,
        explanation: str | None,
    ) -> SceneRecord:
        """Record a scene whose folder is written; return its record."""
        record = SceneRecord(
            id=self.check_id(scene_id),
            created=datetime.now(UTC).isoformat(timespec="seconds"),
            action=action,
            text=text,
            parent=parent,
            changes=tuple(changes),
            summary=summary,
            field_count=field_count,
            plant_count=plant_count,
            explanation=explanation,
        )
        with self._write_lock, self._connect() as connection:
            connection.execute(
                f"INSERT INTO scenes ({_COLUMNS}) VALUES (?, ?, ?, ?, ?, ?, ?, ?, ?, ?)",
                (
                    record.id,
                    record.created,
                    record.action,
                    record.text,
                    record.parent,
                    json.dumps(list(record.changes)),
                    record.summary,
                    record.field_count,
                    record.plant_count,
                    record.explanation,
                ),
            )
        return record

    @staticmethod
    def _record(row: tuple[object, ...]) -> SceneRecord:
        (scene_id, created, action, text, parent, changes, summary, fields, plants, expl) = row
        return SceneRecord(
            id=str(scene_id),
            created=str(created),
            action=str(action),
            text=str(text),
            parent=None if parent is None else str(parent),
            changes=tuple(json.loads(str(changes))),
            summary=str(summary),
            field_count=int(str(fields)),
            plant_count=int(str(plants)),
            explanation=None if expl is None else str(expl),
        )

    def get(self, scene_id: str) -> SceneRecord:
        """The record of a scene; :class:`SceneNotFoundError` if the app never made it."""
        self.check_id(scene_id)
        with self._connect() as connection:
            row = connection.execute(
                f"SELECT {_COLUMNS} FROM scenes WHERE id = ?", (scene_id,)
            ).fetchone()
        if row is None or not (self.folder(scene_id) / "recipe.json").is_file():
            raise SceneNotFoundError(
                f"no scene {scene_id!r} in the app's history",
                stage="app",
                hint="make one from a prompt, or pick one from the history",
            )
        return self._record(tuple(row))

    def history(self, limit: int = 50) -> list[SceneRecord]:
        """The latest scenes first."""
        with self._connect() as connection:
            rows = connection.execute(
                f"SELECT {_COLUMNS} FROM scenes ORDER BY created DESC, rowid DESC LIMIT ?",
                (max(1, min(limit, 500)),),
            ).fetchall()
        return [self._record(tuple(row)) for row in rows]

    def file(self, scene_id: str, relative: str) -> Path:
        """An existing file inside a scene's folder named by a request path.

        Absolute paths, ``..`` steps and symbolic links that lead outside the
        folder raise :class:`UnsafePathError`; a missing file
        :class:`SceneNotFoundError`.
        """
        folder = self.folder(scene_id).resolve()
        if "\x00" in relative or Path(relative).is_absolute() or relative.startswith(("/", "\\")):
            raise UnsafePathError(
                f"{relative[:80]!r} is not a path inside the scene's folder", stage="app"
            )
        target = (folder / relative).resolve()
        if not target.is_relative_to(folder):
            raise UnsafePathError(
                f"{relative[:80]!r} leads outside the scene's folder", stage="app"
            )
        if not target.is_file():
            raise SceneNotFoundError(f"scene {scene_id} has no file {relative[:80]!r}", stage="app")
        return target

    def zip_path(self, scene_id: str) -> Path:
        """Where the download of a scene's outputs is kept."""
        return self.zips_dir / f"agrirecipe-{self.check_id(scene_id)}.zip"
