"""Fixtures of the Unreal backend tests: the API stub index and the recording fake."""

from __future__ import annotations

import pytest
from unreal_stub_index import StubIndex, load_stub_index


@pytest.fixture(scope="session")
def stub_index() -> StubIndex:
    """The UE 5.6 API stub (PyPI ``unreal-stub``), indexed once per test session."""
    return load_stub_index()
