"""``agrirecipe app``: its options, the loopback warning, and a real start."""

from __future__ import annotations

import os
import socket
import subprocess
import sys
import time
import urllib.request
from typing import Any

import pytest

from agrirecipe.cli import build_parser, main

pytest.importorskip("fastapi", reason="the app extra is not installed: pip install '.[app]'")


def test_defaults_are_loopback_and_open_the_browser() -> None:
    args = build_parser().parse_args(["app"])
    assert (args.host, args.port, args.no_browser) == ("127.0.0.1", 8765, False)


def test_options_are_parsed() -> None:
    args = build_parser().parse_args(["app", "--host", "::1", "--port", "9001", "--no-browser"])
    assert (args.host, args.port, args.no_browser) == ("::1", 9001, True)


@pytest.mark.parametrize("port", ["0", "70000", "http"])
def test_a_bad_port_is_refused(port: str, capsys: pytest.CaptureFixture[str]) -> None:
    with pytest.raises(SystemExit) as exited:
        build_parser().parse_args(["app", "--port", port])
    assert exited.value.code == 2
    assert "port" in capsys.readouterr().err


def test_help_lists_the_options(capsys: pytest.CaptureFixture[str]) -> None:
    with pytest.raises(SystemExit):
        main(["app", "--help"])
    out = capsys.readouterr().out
    for option in ("--host", "--port", "--no-browser", "--data-dir"):
        assert option in out


@pytest.fixture
def served(monkeypatch: pytest.MonkeyPatch) -> list[dict[str, Any]]:
    """Calls of ``agrirecipe.app.serve`` (replaced: nothing is started)."""
    import agrirecipe.app

    calls: list[dict[str, Any]] = []

    def fake_serve(host: str, port: int, *, open_browser: bool, config: Any) -> None:
        calls.append({"host": host, "port": port, "open_browser": open_browser, "config": config})

    monkeypatch.setattr(agrirecipe.app, "serve", fake_serve)
    return calls


@pytest.mark.parametrize("host", ["0.0.0.0", "192.168.1.20", "example.lan"])
def test_a_host_other_than_loopback_prints_a_warning(
    host: str, served: list[dict[str, Any]], capsys: pytest.CaptureFixture[str]
) -> None:
    assert main(["app", "--host", host, "--port", "9002", "--no-browser"]) == 0
    err = capsys.readouterr().err
    assert "warning" in err and host in err
    assert served == [
        {"host": host, "port": 9002, "open_browser": False, "config": served[0]["config"]}
    ]


@pytest.mark.parametrize("host", ["127.0.0.1", "localhost", "::1", "127.0.0.2"])
def test_loopback_prints_no_warning(
    host: str, served: list[dict[str, Any]], capsys: pytest.CaptureFixture[str]
) -> None:
    assert main(["app", "--host", host]) == 0
    assert "warning" not in capsys.readouterr().err
    assert served[0]["open_browser"] is True


def test_the_app_starts_and_serves_its_page(tmp_path: Any) -> None:
    with socket.socket() as probe:
        probe.bind(("127.0.0.1", 0))
        port = probe.getsockname()[1]
    env = {**os.environ, "AGRIRECIPE_CACHE_DIR": str(tmp_path)}
    process = subprocess.Popen(
        [sys.executable, "-m", "agrirecipe", "app", "--no-browser", "--port", str(port)],
        stdout=subprocess.PIPE,
        stderr=subprocess.PIPE,
        text=True,
        env=env,
    )
    try:
        page = ""
        deadline = time.monotonic() + 60
        while time.monotonic() < deadline and process.poll() is None:
            try:
                with urllib.request.urlopen(f"http://127.0.0.1:{port}/", timeout=5) as answer:
                    page = answer.read().decode()
                break
            except OSError:
                time.sleep(0.2)
        assert "<title>agrirecipe</title>" in page
        assert (tmp_path / "app" / "history.sqlite3").is_file()  # the cache folder is used
    finally:
        process.terminate()
        out, _ = process.communicate(timeout=30)
    assert f"http://127.0.0.1:{port}/" in out
