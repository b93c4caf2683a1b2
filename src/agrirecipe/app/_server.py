"""The web server of ``agrirecipe app``: FastAPI routes over :class:`AppService`.

Every route that does real work runs it on a worker thread, so the event loop
keeps serving other tabs (and the render progress) meanwhile. Errors a user can
cause come back as JSON ``{"error": {"type", "message", "hint", "stage", "path",
"problems"}}``: 404 for an unknown scene or file, 403 for a path outside the
scene's folder, 413 for a body over the limit, 422 for everything else a user
can get wrong, 500 for a pipeline failure; never a stack trace.

The page and its scripts (three.js included) are files of this package, served
from ``/static``: nothing is fetched from another host.
"""

from __future__ import annotations

import json
import threading
import webbrowser
from collections.abc import AsyncIterator
from contextlib import asynccontextmanager
from importlib import resources
from pathlib import Path
from typing import Any, Literal

from fastapi import FastAPI, Request
from fastapi.exceptions import RequestValidationError
from fastapi.responses import FileResponse, JSONResponse, Response
from fastapi.staticfiles import StaticFiles
from pydantic import BaseModel, ConfigDict, Field
from starlette.concurrency import run_in_threadpool
from starlette.middleware.gzip import GZipMiddleware
from starlette.types import ASGIApp, Message, Receive, Scope, Send

from agrirecipe._errors import (
    AgrirecipeError,
    ConfigurationError,
    PipelineError,
    RecipeValidationError,
    UnknownCropError,
    UserInputError,
)
from agrirecipe.app._history import SceneNotFoundError, UnsafePathError
from agrirecipe.app._service import AppConfig, AppService

__all__ = ["LOOPBACK_HOSTS", "create_app", "is_loopback", "serve"]

#: Hosts that only this machine can reach.
LOOPBACK_HOSTS = ("127.0.0.1", "localhost", "::1")
STATIC_DIR = Path(str(resources.files("agrirecipe.app").joinpath("static")))
# Bodies over the limit up to this size are read before the 413 is sent.
_DRAIN_LIMIT = 64_000_000
_SCENE_FILE_TYPES = {
    ".png": "image/png",
    ".glb": "model/gltf-binary",
    ".json": "application/json",
    ".geojson": "application/geo+json",
    ".csv": "text/csv",
    ".py": "text/x-python",
    ".usda": "text/plain",
}


def is_loopback(host: str) -> bool:
    """True for an address only this machine reaches (127.x.y.z, ::1, localhost)."""
    return host in LOOPBACK_HOSTS or host.startswith("127.")


class _Strict(BaseModel):
    model_config = ConfigDict(extra="forbid")


class PromptRequest(_Strict):
    """``POST /api/scenes``: a prompt to interpret."""

    prompt: str
    seed: int | None = Field(default=None, ge=0, lt=2**63)
    resolver: Literal["auto", "rules", "embedding", "llm", "hybrid"] | None = None


class RefineRequest(_Strict):
    """``POST /api/scenes/{id}/refine``: an instruction in words."""

    instruction: str


class FieldEdit(_Strict):
    """``POST /api/scenes/{id}/fields/{field_id}``: attributes and size to change."""

    crop: str | None = None
    variety: str | None = None
    stage: str | None = None
    season: str | None = None
    health: str | None = None
    size_m: tuple[float, float] | None = None


class RelationsEdit(_Strict):
    """``PUT /api/scenes/{id}/relations``: the full new list of relations."""

    relations: list[dict[str, Any]]


class UploadRequest(_Strict):
    """``POST /api/scenes/upload``: the text of a recipe file."""

    recipe: str


class RenderRequest(_Strict):
    """``POST /api/scenes/{id}/render``: Blender settings (CPU, Cycles)."""

    width: int = Field(default=960, ge=64, le=3840)
    height: int = Field(default=540, ge=64, le=2160)
    samples: int = Field(default=16, ge=1, le=1024)
    view: Literal["overview", "ground"] = "overview"


def _error_body(exc: AgrirecipeError) -> dict[str, Any]:
    body: dict[str, Any] = {
        "type": type(exc).__name__,
        "message": exc.message,
        "hint": exc.hint,
        "stage": exc.stage,
        "path": exc.path,
    }
    if isinstance(exc, RecipeValidationError):
        body["problems"] = [list(p) for p in exc.problems]
    if isinstance(exc, UnknownCropError):
        body["nearest"] = list(exc.nearest)
    return {"error": body}


def _status(exc: AgrirecipeError) -> int:
    if isinstance(exc, SceneNotFoundError):
        return 404
    if isinstance(exc, UnsafePathError):
        return 403
    if isinstance(exc, PipelineError):
        return 500
    return 422


def _simple_error(status: int, message: str, hint: str | None = None) -> JSONResponse:
    return JSONResponse(
        {"error": {"type": "RequestError", "message": message, "hint": hint}}, status_code=status
    )


class _BodyLimit:
    """ASGI middleware: a request body over ``limit`` bytes gets a 413 JSON answer.

    A stated ``Content-Length`` is refused at once; a chunked body is counted as
    it arrives and cut off when it goes over.
    """

    def __init__(self, app: ASGIApp, limit: int) -> None:
        self.app = app
        self.limit = limit

    async def __call__(self, scope: Scope, receive: Receive, send: Send) -> None:
        if scope["type"] != "http":
            await self.app(scope, receive, send)
            return
        headers = dict(scope.get("headers") or [])
        length = headers.get(b"content-length")
        too_large = _simple_error(
            413,
            f"the request body is larger than {self.limit:,} bytes",
            "send a shorter prompt or a smaller recipe",
        )
        if length is not None and (not length.isdigit() or int(length) > self.limit):
            # Read (and drop) a body of reasonable size first: a client still sending
            # when the answer comes would see a reset connection instead of the 413.
            if length.isdigit() and int(length) <= _DRAIN_LIMIT:
                while (await receive()).get("more_body", False):
                    pass
            await too_large(scope, receive, send)
            return
        received = 0
        started = False

        async def limited_receive() -> Message:
            nonlocal received
            message = await receive()
            if message["type"] == "http.request":
                received += len(message.get("body", b""))
                if received > self.limit:
                    raise _TooLargeError
            return message

        async def tracking_send(message: Message) -> None:
            nonlocal started
            started = started or message["type"] == "http.response.start"
            await send(message)

        try:
            await self.app(scope, limited_receive, tracking_send)
        except _TooLargeError:
            if not started:
                await too_large(scope, receive, send)


class _TooLargeError(UserInputError):
    """Raised inside the body-limit middleware when a chunked body goes over the limit."""

    def __init__(self) -> None:
        super().__init__("the request body is too large", stage="app")


def create_app(config: AppConfig | None = None, service: AppService | None = None) -> FastAPI:
    """The app: the page, its static files and the JSON API over one :class:`AppService`."""
    service = service or AppService(config)
    settings = service.config

    @asynccontextmanager
    async def lifespan(app: FastAPI) -> AsyncIterator[None]:
        yield
        await run_in_threadpool(service.close)

    app = FastAPI(
        lifespan=lifespan,
        title="agrirecipe",
        description="Farm requests in words to scenes for Unreal, Blender and USD, offline.",
        docs_url=None,
        redoc_url=None,
        openapi_url=None,
    )
    app.state.service = service
    app.add_middleware(GZipMiddleware, minimum_size=2048)
    app.add_middleware(_BodyLimit, limit=settings.max_body_bytes)
    app.mount("/static", StaticFiles(directory=STATIC_DIR), name="static")

    @app.exception_handler(AgrirecipeError)
    async def agrirecipe_error(request: Request, exc: AgrirecipeError) -> JSONResponse:
        return JSONResponse(_error_body(exc), status_code=_status(exc))

    @app.exception_handler(RequestValidationError)
    async def request_error(request: Request, exc: RequestValidationError) -> JSONResponse:
        problems = [
            [".".join(str(p) for p in error.get("loc", ())), str(error.get("msg", ""))]
            for error in exc.errors()
        ]
        message = "; ".join(f"{path}: {msg}" for path, msg in problems) or "invalid request"
        return JSONResponse(
            {
                "error": {
                    "type": "RequestError",
                    "message": f"the request is not valid: {message}",
                    "hint": "the page sends JSON bodies; see the API in agrirecipe.app",
                    "problems": problems,
                }
            },
            status_code=422,
        )

    @app.middleware("http")
    async def same_origin(request: Request, call_next: Any) -> Response:
        # Another site open in the browser must not drive the app: a request that
        # changes something must come from the app's own page.
        if request.method not in ("GET", "HEAD", "OPTIONS"):
            origin = request.headers.get("origin")
            host = request.headers.get("host", "")
            if origin is not None and origin.split("://", 1)[-1] != host:
                return _simple_error(403, f"requests from {origin[:80]} are not accepted")
            kind = request.headers.get("content-type", "")
            has_body = request.headers.get("content-length", "0") != "0" or (
                "transfer-encoding" in request.headers
            )
            if has_body and not kind.startswith("application/json"):
                return _simple_error(415, "the API takes JSON bodies (application/json)")
        response: Response = await call_next(request)
        return response

    @app.get("/", include_in_schema=False)
    async def index() -> FileResponse:
        return FileResponse(STATIC_DIR / "index.html", headers={"Cache-Control": "no-cache"})

    @app.get("/api/choices")
    async def choices() -> dict[str, Any]:
        return service.choices()

    @app.get("/api/examples")
    async def examples() -> Any:
        return json.loads((STATIC_DIR / "examples.json").read_text(encoding="utf-8"))

    @app.get("/api/history")
    async def history(limit: int = 50) -> dict[str, Any]:
        records = await run_in_threadpool(service.store.history, limit)
        return {"scenes": [record.public() for record in records]}

    @app.post("/api/scenes")
    async def interpret(body: PromptRequest) -> dict[str, Any]:
        record = await run_in_threadpool(
            service.interpret, body.prompt, seed=body.seed, resolver=body.resolver
        )
        return await run_in_threadpool(service.describe, record.id)

    @app.post("/api/scenes/upload")
    async def upload(body: UploadRequest) -> dict[str, Any]:
        record = await run_in_threadpool(service.upload, body.recipe)
        return await run_in_threadpool(service.describe, record.id)

    @app.get("/api/scenes/{scene_id}")
    async def describe(scene_id: str) -> dict[str, Any]:
        return await run_in_threadpool(service.describe, scene_id)

    @app.post("/api/scenes/{scene_id}/refine")
    async def refine(scene_id: str, body: RefineRequest) -> dict[str, Any]:
        try:
            record = await run_in_threadpool(service.refine, scene_id, body.instruction)
        except ImportError as exc:  # the edit package is not installed
            raise ConfigurationError(
                f"editing by words is not available here ({exc})",
                stage="app",
                hint="reinstall agrirecipe; edit the field table instead",
            ) from exc
        return await run_in_threadpool(service.describe, record.id)

    @app.post("/api/scenes/{scene_id}/fields/{field_id}")
    async def edit_field(scene_id: str, field_id: str, body: FieldEdit) -> dict[str, Any]:
        updates = body.model_dump(exclude_none=True)
        record = await run_in_threadpool(service.edit_field, scene_id, field_id, updates)
        return await run_in_threadpool(service.describe, record.id)

    @app.put("/api/scenes/{scene_id}/relations")
    async def edit_relations(scene_id: str, body: RelationsEdit) -> dict[str, Any]:
        record = await run_in_threadpool(service.edit_relations, scene_id, body.relations)
        return await run_in_threadpool(service.describe, record.id)

    @app.get("/api/scenes/{scene_id}/view")
    async def view(scene_id: str, max_plants: int | None = None) -> dict[str, Any]:
        return await run_in_threadpool(service.view, scene_id, max_plants)

    @app.get("/api/scenes/{scene_id}/plants.bin")
    async def plants(scene_id: str, max_plants: int | None = None) -> Response:
        data = await run_in_threadpool(service.plants, scene_id, max_plants)
        return Response(data, media_type="application/octet-stream")

    @app.get("/api/scenes/{scene_id}/files/{relative:path}")
    async def scene_file(scene_id: str, relative: str) -> FileResponse:
        path = await run_in_threadpool(service.store.file, scene_id, relative)
        media = _SCENE_FILE_TYPES.get(path.suffix.lower(), "application/octet-stream")
        return FileResponse(path, media_type=media)

    @app.get("/api/scenes/{scene_id}/download")
    async def download(scene_id: str) -> FileResponse:
        path = await run_in_threadpool(service.zip_outputs, scene_id)
        return FileResponse(path, media_type="application/zip", filename=path.name)

    @app.post("/api/scenes/{scene_id}/render")
    async def render(scene_id: str, body: RenderRequest) -> dict[str, Any]:
        scene = await run_in_threadpool(service.scene, scene_id)
        job = await run_in_threadpool(
            service.renders.start,
            scene,
            service.store.folder(scene_id),
            scene_id,
            resolution=(body.width, body.height),
            samples=body.samples,
            view=body.view,
        )
        return job.public()

    @app.get("/api/renders/{job_id}")
    async def render_state(job_id: str) -> dict[str, Any]:
        return service.renders.get(job_id).public()

    @app.post("/api/renders/{job_id}/cancel")
    async def render_cancel(job_id: str) -> dict[str, Any]:
        return service.renders.cancel(job_id).public()

    return app


def serve(
    host: str = "127.0.0.1",
    port: int = 8765,
    *,
    open_browser: bool = True,
    config: AppConfig | None = None,
) -> None:
    """Run the app until interrupted; open the page in the browser unless told not to."""
    import uvicorn

    app = create_app(config)
    shown = f"[{host}]" if ":" in host else host
    url = f"http://{'127.0.0.1' if host in ('0.0.0.0', '::') else shown}:{port}/"
    print(f"agrirecipe app: {url} (Ctrl+C to stop)", flush=True)
    if open_browser:
        threading.Timer(1.0, webbrowser.open, args=(url,)).start()
    uvicorn.run(app, host=host, port=port, log_level="warning")
