"""Loading benchmark files: errors name the entry; names are checked against the hierarchy."""

from __future__ import annotations

from pathlib import Path

import pytest

from agrirecipe import AgrirecipeError
from agrirecipe.evaluation import BenchmarkError, load_benchmark, load_knowledge_queries

HEADER = "version: 1\ndefaults: {health: Healthy}\nprompts:\n"


def _write(tmp_path: Path, body: str, header: str = HEADER) -> Path:
    path = tmp_path / "prompts.yaml"
    path.write_text(header + body, encoding="utf-8")
    return path


def test_a_small_valid_file_loads_with_defaults_and_categories(tmp_path: Path) -> None:
    path = _write(
        tmp_path,
        "- id: a-1\n  type: single_generic\n  prompt: an orchard\n"
        "  fields: [{crop: [Apple, Pear]}]\n"
        "- {id: a-2, type: invalid, prompt: '', error: PromptError}\n",
    )
    benchmark = load_benchmark(path)
    assert [p.id for p in benchmark.prompts] == ["a-1", "a-2"]
    truth = benchmark.prompts[0].fields[0]
    assert truth.category == ("Fruits",)
    assert truth.health == ("Healthy",)
    assert truth.inferred == ("health",)
    assert benchmark.prompts[1].invalid


@pytest.mark.parametrize(
    ("body", "message"),
    [
        (
            "- {id: b-1, type: single_detailed, prompt: x, fields: [{crop: Mango}]}\n",
            "'Mango' is not a crop",
        ),
        (
            "- {id: b-1, type: single_detailed, prompt: x, "
            "fields: [{crop: Apple, variety: Cripps Pink}]}\n",
            "not a canonical variety",
        ),
        (
            "- {id: b-1, type: single_detailed, prompt: x, "
            "fields: [{crop: Pear, variety: Gala}]}\n",
            "not a variety of Pear",
        ),
        (
            "- {id: b-1, type: single_detailed, prompt: x, "
            "fields: [{category: Cereals, crop: Apple}]}\n",
            "not in category",
        ),
        (
            "- {id: b-1, type: single_detailed, prompt: x, fields: [{stage: Ripe}]}\n",
            "b-1",
        ),
        ("- {id: b-1, type: invalid, prompt: x}\n", "needs 'error'"),
        (
            "- {id: b-1, type: single_detailed, prompt: x, "
            "fields: [{crop: Apple}, {crop: Pear}]}\n",
            "exactly one field",
        ),
        (
            "- {id: b-1, type: multi_generic, prompt: x, fields: [{crop: Apple}, {crop: Pear}],"
            " relations: [{kind: next_to, subject: a, objects: [b]}]}\n",
            "unknown ref",
        ),
        (
            "- {id: b-1, type: single_generic, prompt: x, fields: [{crop: Apple}]}\n"
            "- {id: b-1, type: single_generic, prompt: y, fields: [{crop: Pear}]}\n",
            "duplicate prompt id",
        ),
    ],
)
def test_malformed_entries_raise_a_benchmark_error_naming_them(
    tmp_path: Path, body: str, message: str
) -> None:
    with pytest.raises(BenchmarkError, match=message) as caught:
        load_benchmark(_write(tmp_path, body))
    assert isinstance(caught.value, AgrirecipeError)


def test_missing_and_unparsable_files(tmp_path: Path) -> None:
    with pytest.raises(BenchmarkError, match="does not exist"):
        load_benchmark(tmp_path / "nope.yaml")
    with pytest.raises(BenchmarkError, match="not valid YAML"):
        load_benchmark(_write(tmp_path, "- {id: [unclosed\n"))


def test_select_by_type_tag_id_and_limit_covers_every_type() -> None:
    benchmark = load_benchmark()
    assert {p.type for p in benchmark.select(types=["invalid"]).prompts} == {"invalid"}
    typos = benchmark.select(tags=["typo"])
    assert len(typos) >= 15 and all("typo" in p.tags for p in typos.prompts)
    assert [p.id for p in benchmark.select(ids=["md-005"]).prompts] == ["md-005"]
    small = benchmark.select(limit=5)
    assert len(small) == 5
    assert {p.type for p in small.prompts} == {
        "single_detailed",
        "single_generic",
        "multi_detailed",
        "multi_generic",
        "invalid",
    }
    assert len(benchmark.select(limit=10_000)) == len(benchmark)


def test_knowledge_query_errors(tmp_path: Path) -> None:
    path = tmp_path / "q.yaml"
    path.write_text(
        "version: 1\nqueries:\n- query: ripe gala\n"
        "  key: {crop: Apple, variety: Gala, stage: Ripe, season: Fall, health: Healthy}\n",
        encoding="utf-8",
    )
    with pytest.raises(BenchmarkError, match="ripe gala"):
        load_knowledge_queries(path)
    path.write_text("version: 1\nqueries:\n- query: x\n", encoding="utf-8")
    with pytest.raises(BenchmarkError, match=r"queries\[0\]"):
        load_knowledge_queries(path)


def test_several_files_load_with_their_split_and_ids_stay_unique(tmp_path: Path) -> None:
    dev = _write(
        tmp_path, "- {id: d-1, type: single_generic, prompt: pears, fields: [{crop: Pear}]}\n"
    )
    heldout = tmp_path / "heldout.yaml"
    heldout.write_text(
        "version: 1\nsplit: heldout\nprompts:\n"
        "- {id: h-1, type: single_generic, prompt: apples, fields: [{crop: Apple}]}\n",
        encoding="utf-8",
    )
    benchmark = load_benchmark([dev, heldout])
    assert [(p.id, p.split) for p in benchmark.prompts] == [("d-1", "dev"), ("h-1", "heldout")]
    assert [p.id for p in benchmark.select(splits=["heldout"]).prompts] == ["h-1"]
    heldout.write_text(
        "version: 1\nsplit: heldout\nprompts:\n"
        "- {id: d-1, type: single_generic, prompt: apples, fields: [{crop: Apple}]}\n",
        encoding="utf-8",
    )
    with pytest.raises(BenchmarkError, match=r"duplicate prompt id 'd-1'.*also in"):
        load_benchmark([dev, heldout])


def test_round_robin_takes_each_group_in_turn() -> None:
    from agrirecipe.evaluation import round_robin

    items = ["a1", "a2", "a3", "b1", "c1", "c2"]
    assert round_robin(items, lambda s: s[0], 4) == ["a1", "b1", "c1", "a2"]
    assert round_robin(items, lambda s: s[0], 100) == ["a1", "b1", "c1", "a2", "c2", "a3"]
    assert round_robin([], lambda s: s, 3) == []
