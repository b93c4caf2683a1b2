"""The ``crops/*.yaml`` files: every number sourced, and malformed files rejected clearly."""

from __future__ import annotations

import shutil
from collections.abc import Callable, Iterator
from pathlib import Path
from typing import Any

import pytest
import yaml

from agrirecipe import KnowledgeBaseError
from agrirecipe.knowledge import default_knowledge_base, load_knowledge_base

CROPS = Path(__file__).resolve().parents[2] / "crops"
# Source keys of reference/crops.md: its words, and the numbers of its page list.
SOURCE_WORDS = {"F11", "F12", "AQ", "est.", "n/a", "crops.md A", "crops.md B", "crops.md C"}
PAGES = {
    *range(1, 14), *range(15, 22), *range(23, 34), *range(35, 39), 40, 41, 42,
    *range(44, 55), 56, 57, *range(59, 66), 67, 68,
}  # fmt: skip
# Plain counts fixed by the planting pattern, not measurements.
UNSOURCED_NUMBERS = {"rows_per_bed"}


def _raw(name: str) -> dict[str, Any]:
    data: dict[str, Any] = yaml.safe_load((CROPS / name).read_text(encoding="utf-8"))
    return data


def _numbers_outside_sourced_values(node: Any, path: str) -> Iterator[str]:
    if isinstance(node, dict):
        if "value" in node:
            assert "source" in node, f"{path}: a value without a source"
            return
        for name, child in node.items():
            if name not in UNSOURCED_NUMBERS:
                yield from _numbers_outside_sourced_values(child, f"{path}.{name}")
    elif isinstance(node, list):
        for index, child in enumerate(node):
            yield from _numbers_outside_sourced_values(child, f"{path}[{index}]")
    elif isinstance(node, int | float) and not isinstance(node, bool):
        yield path


def _sources(node: Any) -> Iterator[str]:
    if isinstance(node, dict):
        if isinstance(node.get("source"), str):
            yield node["source"]
        for child in node.values():
            yield from _sources(child)


def _sourced_values(node: Any) -> Iterator[dict[str, Any]]:
    if isinstance(node, dict):
        if "value" in node:
            yield node
        for child in node.values():
            yield from _sourced_values(child)


FILES = sorted(path.name for path in CROPS.glob("*.yaml"))


def test_one_file_per_crop() -> None:
    assert len(FILES) == 16


@pytest.mark.parametrize("name", FILES)
def test_every_number_carries_a_source(name: str) -> None:
    assert list(_numbers_outside_sourced_values(_raw(name), name.removesuffix(".yaml"))) == []


@pytest.mark.parametrize("name", FILES)
def test_sources_are_keys_of_the_reference(name: str) -> None:
    for source in _sources(_raw(name)):
        for part in (part.strip() for part in source.split(",")):
            assert part in SOURCE_WORDS or int(part) in PAGES, f"{name}: unknown source {part!r}"


@pytest.mark.parametrize("name", FILES)
def test_ranges_hold_their_values(name: str) -> None:
    for sourced in _sourced_values(_raw(name)):
        if sourced.get("range") is not None:
            low, high = sourced["range"]
            assert low <= sourced["value"] <= high, sourced


@pytest.mark.parametrize("name", FILES)
def test_colours_are_rgb_estimates(name: str) -> None:
    raw = _raw(name)
    blocks = [raw["colours"]] + [
        override["colours"]
        for override in (raw.get("varieties") or {}).values()
        if override and "colours" in override
    ]
    for block in blocks:
        for colour in block.values():
            if colour is None:
                continue
            assert colour["source"] == "est."
            assert len(colour["value"]) == 3 and all(0 <= c <= 1 for c in colour["value"])


# --- malformed files -------------------------------------------------------------

Edit = Callable[[Path], None]


def _edit_yaml(name: str, change: Callable[[dict[str, Any]], None]) -> Edit:
    def edit(folder: Path) -> None:
        path = folder / name
        data = yaml.safe_load(path.read_text(encoding="utf-8"))
        change(data)
        path.write_text(yaml.safe_dump(data), encoding="utf-8")

    return edit


def _delete(name: str) -> Edit:
    return lambda folder: (folder / name).unlink()


def _rename(name: str, new: str) -> Edit:
    return lambda folder: (folder / name).rename(folder / new)


def _write(name: str, text: str) -> Edit:
    return lambda folder: (folder / name).write_text(text, encoding="utf-8")


def _set(*path: str, value: Any) -> Callable[[dict[str, Any]], None]:
    def change(data: dict[str, Any]) -> None:
        for part in path[:-1]:
            data = data[part]
        data[path[-1]] = value

    return change


def _drop(*path: str) -> Callable[[dict[str, Any]], None]:
    def change(data: dict[str, Any]) -> None:
        for part in path[:-1]:
            data = data[part]
        del data[path[-1]]

    return change


MALFORMED: list[tuple[str, Edit, str]] = [
    ("missing crop file", _delete("wheat.yaml"), "no knowledge file for crop(s) Wheat"),
    (
        "file named after another crop",
        _rename("pear.yaml", "poire.yaml"),
        "poire.yaml describes crop 'Pear'; name the file after its crop",
    ),
    ("invalid YAML", _write("onion.yaml", "crop: Onion\nseasons: [\n"), "is not valid YAML"),
    ("not a mapping", _write("onion.yaml", "- Onion\n"), "must be a mapping with a 'crop' name"),
    (
        "unknown source key",
        _edit_yaml("pear.yaml", _set("kc_mid", value={"value": 0.95, "source": "wikipedia"})),
        "unknown source key 'wikipedia'",
    ),
    (
        "number without a source",
        _edit_yaml("pear.yaml", _set("kc_mid", value=0.95)),
        "Pear (Conference): kc_mid",
    ),
    (
        "override of an unknown variety",
        _edit_yaml("apple.yaml", _set("varieties", "Honeycrisp", value={})),
        "Apple: overrides for unknown varieties Honeycrisp",
    ),
    (
        "default variety not in the hierarchy",
        _edit_yaml(
            "cherry.yaml", _set("default_variety", value={"value": "Stella", "source": "est."})
        ),
        "Cherry: default_variety 'Stella' is not a variety of the hierarchy",
    ),
    (
        "missing season",
        _edit_yaml("grape.yaml", _drop("seasons", "Winter")),
        "missing seasons: Winter",
    ),
    (
        "missing stage height",
        _edit_yaml("grape.yaml", _drop("stage_height_fraction", "Maturation")),
        "missing stages: Maturation",
    ),
    (
        "unknown planting pattern",
        _edit_yaml("maize.yaml", _set("planting", "pattern", value="broadcast")),
        "planting.pattern",
    ),
    (
        "unknown flowering season",
        _edit_yaml("apple.yaml", _set("flowering", "seasons", value=["Autumn"])),
        "flowering.seasons",
    ),
    (
        "unknown key",
        _edit_yaml("apple.yaml", _set("colour", value="red")),
        "colour: Extra inputs are not permitted",
    ),
]


@pytest.mark.parametrize(
    ("edit", "fragment"), [case[1:] for case in MALFORMED], ids=[case[0] for case in MALFORMED]
)
def test_malformed_crop_files(tmp_path: Path, edit: Edit, fragment: str) -> None:
    folder = tmp_path / "crops"
    shutil.copytree(CROPS, folder)
    edit(folder)
    with pytest.raises(KnowledgeBaseError) as caught:
        load_knowledge_base(folder)
    assert fragment in str(caught.value)


def test_missing_folder(tmp_path: Path) -> None:
    with pytest.raises(KnowledgeBaseError, match="does not exist"):
        load_knowledge_base(tmp_path / "nowhere")


def test_digest_follows_the_files(tmp_path: Path) -> None:
    folder = tmp_path / "crops"
    shutil.copytree(CROPS, folder)
    shipped = default_knowledge_base()
    assert load_knowledge_base(folder).digest() == shipped.digest()
    _edit_yaml("apple.yaml", _set("kc_mid", value={"value": 1.2, "source": "F12"}))(folder)
    changed = load_knowledge_base(folder)
    assert changed.digest() != shipped.digest()
    assert changed.crop_file("Apple").kc_mid.value == 1.2
