"""The README's quick start runs, and its set-up commands are the ones CI and make use."""

from __future__ import annotations

import re
from pathlib import Path

from agrirecipe import Scene, SceneRecipe


def _readme(repo_root: Path) -> str:
    return (repo_root / "README.md").read_text(encoding="utf-8")


def _section(text: str, heading: str) -> str:
    start = text.index(f"## {heading}")
    end = text.find("\n## ", start + 1)
    return text[start : end if end != -1 else None]


def test_quick_start_runs_and_gives_the_promised_recipe(repo_root: Path) -> None:
    section = _section(_readme(repo_root), "Quick start")
    blocks = re.findall(r"```python\n(.*?)```", section, flags=re.S)
    assert len(blocks) == 1, "the quick start is one python block"
    code = blocks[0]
    assert code.count("import") == 1, "the quick start is one import and one call"
    namespace: dict[str, object] = {}
    exec(compile(code, "README.md", "exec"), namespace)
    scene = namespace["scene"]
    assert isinstance(scene, Scene)
    recipe = scene.recipe
    assert isinstance(recipe, SceneRecipe)
    by_crop = {field.crop: field for field in recipe.fields}
    assert set(by_crop) == {"Apple", "Carrot"}
    apple, carrot = by_crop["Apple"], by_crop["Carrot"]
    assert (apple.variety, apple.season, apple.health) == ("Pink Lady", "Summer", "Healthy")
    assert (carrot.variety, carrot.stage) == ("Nantes", "Vegetative")
    assert apple.asset_path.startswith("/Game/Agriculture/Fruits/Apple/PinkLady/")
    assert "unreal.ScopedEditorTransaction" in scene.script("unreal")


def test_setup_is_two_commands_and_ci_runs_the_test_one(repo_root: Path) -> None:
    section = _section(_readme(repo_root), "Set-up (a fresh Debian machine with Python 3.11)")
    block = re.findall(r"```bash\n(.*?)```", section, flags=re.S)[0]
    commands = [line.split("#")[0].strip() for line in block.splitlines() if line.strip()]
    assert commands == ["make demo", "make test"]
    ci = (repo_root / ".ci" / "run").read_text(encoding="utf-8")
    ci_commands = [
        line.strip()
        for line in ci.splitlines()
        if line.strip() and not line.startswith("#") and not line.startswith(("set ", "cd "))
    ]
    assert ci_commands == ["make test"]
    makefile = (repo_root / "Makefile").read_text(encoding="utf-8")
    assert re.search(r"^demo: install\n\t\.venv/bin/agrirecipe generate ", makefile, re.M)
    assert re.search(r"^test: install\n\tbash scripts/test.sh", makefile, re.M)
