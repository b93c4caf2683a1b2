"""Helpers for the evaluation tests: truth prompts and predicted scenes built by hand."""

from __future__ import annotations

from typing import Any

import pytest

from agrirecipe.hierarchy import default_hierarchy


@pytest.fixture
def hierarchy() -> Any:
    """The shipped hierarchy."""
    return default_hierarchy()
