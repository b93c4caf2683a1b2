"""Training examples: each dev prompt's record, filled from its ground truth."""

from __future__ import annotations

import pytest

from agrirecipe.evaluation import BenchmarkPrompt, load_benchmark
from agrirecipe.finetune import ExampleSet, build_examples, split_examples


@pytest.fixture(scope="module")
def benchmark_prompts() -> dict[str, BenchmarkPrompt]:
    return {p.id: p for p in load_benchmark().prompts}


@pytest.fixture(scope="module")
def example_set() -> ExampleSet:
    return build_examples()


def _lines(target: str) -> list[tuple[str, str]]:
    return [tuple(line.split(": ", 1)) for line in target.splitlines() if line]  # type: ignore[misc]


def test_the_paper_prompt_becomes_the_strategys_record(example_set: ExampleSet) -> None:
    examples = [e for e in example_set.examples if e.prompt_id == "sd-001"]
    assert [(e.context, e.target) for e in examples] == [
        (
            "Request: Generate a healthy Pink Lady apple orchard in summer\n",
            "Part 1: Generate a healthy Pink Lady apple orchard in summer\n"
            "Count: 1\n"
            "Crop: Apple\n"
            "Variety: Pink Lady\n"
            "Stage: none\n"
            "Season: Summer\n"
            "Health: Healthy\n",
        )
    ]


def test_a_prompt_of_two_fields_is_a_record_per_part_and_one_for_relations(
    benchmark_prompts: dict[str, BenchmarkPrompt],
) -> None:
    built = build_examples([benchmark_prompts["md-004"]])
    request = "Request: Golden Acre cabbage beside Golden Delicious apples\n"
    assert built.prompts == 1
    assert [(e.context, e.target) for e in built.examples] == [
        (
            request,
            "Part 1: Golden Acre cabbage\nCount: 1\nCrop: Cabbage\nVariety: Golden Acre\n"
            "Stage: none\nSeason: none\nHealth: none\n",
        ),
        (
            request,
            "Part 2: beside Golden Delicious apples\nCount: 1\nCrop: Apple\n"
            "Variety: Golden Delicious\nStage: none\nSeason: none\nHealth: none\n",
        ),
        (
            request,
            "Part 1: Golden Acre cabbage\nPart 2: beside Golden Delicious apples\n"
            "Relations: 1 next to 2\n",
        ),
    ]


def test_every_record_matches_its_ground_truth(
    example_set: ExampleSet, benchmark_prompts: dict[str, BenchmarkPrompt]
) -> None:
    assert example_set.prompts >= 400
    records: dict[str, list[str]] = {}
    for example in example_set.examples:
        assert example.context.startswith("Request: ") and example.context.endswith("\n")
        records.setdefault(example.prompt_id, []).append(example.target)
    for prompt_id, targets in records.items():
        truth = benchmark_prompts[prompt_id]
        assert not truth.invalid
        parts = [_lines(t) for t in targets if "\nCount: " in t]
        relations = [t for t in targets if "\nRelations: " in t]
        assert len(relations) == (1 if len(parts) > 1 else 0), prompt_id
        lines = [line for part in parts for line in part]
        assert [label for label, _ in lines if label.startswith("Part ")] == [
            f"Part {n}" for n in range(1, len(parts) + 1)
        ]
        crops = [value for label, value in lines if label == "Crop"]
        counts = [int(value) for label, value in lines if label == "Count"]
        # every truth field is one counted field of a part, with the truth's crop
        assert sum(counts) == len(truth.fields), prompt_id
        assert sorted(f.crop[0] for f in truth.fields if f.crop) == sorted(
            crop for crop, count in zip(crops, counts, strict=True) for _ in range(count)
        )
        if len(truth.fields) == 1:
            field = truth.fields[0]
            values = dict(lines)
            assert values["Variety"] == (field.variety[0] if field.variety else "none")
            for key in ("stage", "season", "health"):
                allowed = field.allowed(key)
                stated = allowed is not None and key not in field.inferred
                assert values[key.capitalize()] == (allowed[0] if stated else "none")


def test_skipped_prompts_are_counted_with_a_reason(
    example_set: ExampleSet, benchmark_prompts: dict[str, BenchmarkPrompt]
) -> None:
    assert sum(example_set.skipped.values()) + example_set.prompts == len(benchmark_prompts)
    # (a blind set waiting for its run is skipped as "not in the dev split")
    invalid = sum(p.invalid for p in benchmark_prompts.values() if p.split == "dev")
    assert example_set.skipped["invalid prompt (an error, not a record)"] == invalid


def test_only_the_dev_split_is_read(benchmark_prompts: dict[str, BenchmarkPrompt]) -> None:
    blind = benchmark_prompts["sd-001"].model_copy(update={"split": "heldout"})
    built = build_examples([blind, benchmark_prompts["sd-002"]])
    assert [e.prompt_id for e in built.examples] == ["sd-002"]
    assert built.skipped == {"not in the dev split": 1}


def test_a_limit_reads_a_seeded_sample_of_prompts(
    benchmark_prompts: dict[str, BenchmarkPrompt],
) -> None:
    prompts = list(benchmark_prompts.values())[:3000]
    sample = build_examples(prompts, limit=40, seed=0)
    again = build_examples(list(reversed(prompts)), limit=40, seed=0)
    other = build_examples(prompts, limit=40, seed=1)
    assert sample.prompts == 40 and sample.digest == again.digest
    assert {e.prompt_id for e in other.examples} != {e.prompt_id for e in sample.examples}
    assert sum(sample.skipped.values()) + sample.prompts == len(prompts)
    assert sample.skipped["not read (the limit of 40 prompts was reached)"] > 2000


def test_split_is_seeded_disjoint_and_by_prompt(example_set: ExampleSet) -> None:
    train, heldout = split_examples(example_set.examples, heldout_fraction=0.15, seed=0)
    again_train, again_heldout = split_examples(
        list(reversed(example_set.examples)), heldout_fraction=0.15, seed=0
    )
    assert heldout == again_heldout and train == again_train
    assert len(train) + len(heldout) == len(example_set.examples)
    assert not {e.prompt_id for e in train} & {e.prompt_id for e in heldout}
    assert len({e.prompt_id for e in heldout}) == round(0.15 * example_set.prompts)
    assert any(e.target.count("Relations: ") for e in heldout)  # whole prompts held out
    other, _ = split_examples(example_set.examples, heldout_fraction=0.15, seed=1)
    assert {e.prompt_id for e in other} != {e.prompt_id for e in train}
    assert len(example_set.digest) == 64
