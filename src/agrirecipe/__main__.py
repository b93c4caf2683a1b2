"""``python -m agrirecipe`` runs the command-line interface."""

from agrirecipe.cli import main

raise SystemExit(main())
