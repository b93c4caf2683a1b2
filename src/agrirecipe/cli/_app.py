"""``agrirecipe app``: the local web application (prompt, field table, map, 3D view, render)."""

from __future__ import annotations

import argparse
import sys
from pathlib import Path
from typing import Any

from agrirecipe.cli._options import add_resolver_option

DEFAULT_PORT = 8765


def _port(text: str) -> int:
    try:
        port = int(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"{text!r} is not a port number") from None
    if not 0 < port < 65536:
        raise argparse.ArgumentTypeError(f"port {port} is not between 1 and 65535")
    return port


def register(subparsers: Any) -> None:
    """Add the ``app`` sub-command."""
    parser = subparsers.add_parser(
        "app",
        help="start the local web application (offline) and open it in the browser",
        description="Serve the agrirecipe page on this machine: type a request, see and edit "
        "its fields, the field map and a 3D view of the plants, refine it in words, render it "
        "in Blender and download every output. Everything it loads ships with agrirecipe; "
        "scenes and their history are kept in the cache folder (AGRIRECIPE_CACHE_DIR).",
    )
    parser.add_argument(
        "--host",
        default="127.0.0.1",
        help="address to listen on (default 127.0.0.1: this machine only; anything else "
        "lets other machines reach the app and prints a warning)",
    )
    parser.add_argument(
        "--port", type=_port, default=DEFAULT_PORT, help=f"port (default {DEFAULT_PORT})"
    )
    parser.add_argument(
        "--no-browser", action="store_true", help="do not open the page in a web browser"
    )
    parser.add_argument(
        "--data-dir",
        type=Path,
        default=None,
        help="folder for the app's scenes and history (default: the cache folder's app/)",
    )
    add_resolver_option(parser, "resolution strategy for prompts")
    parser.set_defaults(handler=run)


def loopback_warning(host: str) -> str | None:
    """The warning printed for a host other machines can reach, or None for loopback."""
    from agrirecipe.app import is_loopback

    if is_loopback(host):
        return None
    return (
        f"warning: listening on {host}: other machines on the network can reach the app, "
        "read its scenes and make it work; it has no login. Use the default 127.0.0.1 "
        "unless you mean this."
    )


def run(args: argparse.Namespace) -> int:
    """Start the server and block until it is stopped."""
    from agrirecipe._errors import ConfigurationError

    try:
        from agrirecipe.app import AppConfig, serve
    except ImportError as exc:
        raise ConfigurationError(
            f"the app needs packages that are not installed ({exc.name or exc})",
            stage="app",
            hint="pip install 'agrirecipe[app]'",
        ) from exc
    warning = loopback_warning(args.host)
    if warning is not None:
        print(warning, file=sys.stderr)
    serve(
        args.host,
        args.port,
        open_browser=not args.no_browser,
        config=AppConfig(root=args.data_dir, resolver=args.resolver),
    )
    return 0
