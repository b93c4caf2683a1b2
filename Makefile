# The two set-up commands of the README. Both install everything first
# (scripts/install.sh is idempotent and reuses pip's wheel cache).
PROMPT ?= a healthy Pink Lady apple orchard in summer next to young Nantes carrots
OUT ?= out/demo

.PHONY: install demo test bench
install:
	bash scripts/install.sh

demo: install
	.venv/bin/agrirecipe generate "$(PROMPT)" -o "$(OUT)"

test: install
	bash scripts/test.sh

bench: install
	.venv/bin/python bench/run_all.py
