"""``agrirecipe app``: a local web application over generate, edit, write and render.

A page on 127.0.0.1 takes a prompt, shows the interpretation as an editable
table of fields with the explanation of every stage, the field map and an
interactive 3D view of the plants, refines the scene by words, renders it in
Blender and downloads every output as a zip; a history of the scenes made is
kept in SQLite in the cache folder. Everything the page loads ships inside this
package (three.js included), so it works offline. Needs the ``app`` extra
(``pip install 'agrirecipe[app]'``: FastAPI and uvicorn).
"""

from agrirecipe.app._history import SceneNotFoundError, SceneRecord, SceneStore, UnsafePathError
from agrirecipe.app._render import RenderJob, RenderJobs
from agrirecipe.app._server import LOOPBACK_HOSTS, create_app, is_loopback, serve
from agrirecipe.app._service import AppConfig, AppService

__all__ = [
    "LOOPBACK_HOSTS",
    "AppConfig",
    "AppService",
    "RenderJob",
    "RenderJobs",
    "SceneNotFoundError",
    "SceneRecord",
    "SceneStore",
    "UnsafePathError",
    "create_app",
    "is_loopback",
    "serve",
]
