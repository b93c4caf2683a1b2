#!/usr/bin/env bash
# The test job: lint, type-check and the whole test suite with the real models
# and engines (embedding model, GGUF model, bpy, usd-core, unreal-stub).
set -euo pipefail
cd "$(dirname "$0")/.."
export HF_HUB_OFFLINE=1 TRANSFORMERS_OFFLINE=1
export AGRIRECIPE_CACHE_DIR="${AGRIRECIPE_CACHE_DIR:-$PWD/.cache/agrirecipe}"
.venv/bin/ruff check src tests
.venv/bin/mypy src
.venv/bin/python -m pytest -q -p no:cacheprovider "$@"
