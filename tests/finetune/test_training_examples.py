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
    example = next(e for e in example_set.examples if e.prompt_id == "sd-001")
    assert example.context == "Request: Generate a healthy Pink Lady apple orchard in summer\n"
    assert example.target == (
        "Parts: Generate a healthy Pink Lady apple orchard in summer\n"
        "Part 1: Generate a healthy Pink Lady apple orchard in summer\n"
        "Count: 1\n"
        "Crop: Apple\n"
        "Variety: Pink Lady\n"
        "Stage: none\n"
        "Season: Summer\n"
        "Health: Healthy\n"
        "\n"
    )


def test_every_record_matches_its_ground_truth(
    example_set: ExampleSet, benchmark_prompts: dict[str, BenchmarkPrompt]
) -> None:
    assert len(example_set.examples) >= 400
    for example in example_set.examples:
        truth = benchmark_prompts[example.prompt_id]
        assert not truth.invalid
        lines = _lines(example.target)
        labels = [label for label, _ in lines]
        assert labels[0] == "Parts" and labels[1] == "Part 1", example.prompt_id
        crops = [value for label, value in lines if label == "Crop"]
        counts = [int(value) for label, value in lines if label == "Count"]
        # every truth field is one counted field of a part, with the truth's crop
        assert sum(counts) == len(truth.fields), example.prompt_id
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
    assert sum(example_set.skipped.values()) + len(example_set.examples) == len(benchmark_prompts)
    # (a blind set waiting for its run is skipped as "not in the dev split")
    invalid = sum(p.invalid for p in benchmark_prompts.values() if p.split == "dev")
    assert example_set.skipped["invalid prompt (an error, not a record)"] == invalid


def test_only_the_dev_split_is_read(benchmark_prompts: dict[str, BenchmarkPrompt]) -> None:
    blind = benchmark_prompts["sd-001"].model_copy(update={"split": "heldout"})
    built = build_examples([blind, benchmark_prompts["sd-002"]])
    assert [e.prompt_id for e in built.examples] == ["sd-002"]
    assert built.skipped == {"not in the dev split": 1}


def test_split_is_seeded_and_disjoint(example_set: ExampleSet) -> None:
    train, heldout = split_examples(example_set.examples, heldout_fraction=0.15, seed=0)
    again_train, again_heldout = split_examples(
        list(reversed(example_set.examples)), heldout_fraction=0.15, seed=0
    )
    assert [e.prompt_id for e in heldout] == [e.prompt_id for e in again_heldout]
    assert {e.prompt_id for e in train} == {e.prompt_id for e in again_train}
    assert not {e.prompt_id for e in train} & {e.prompt_id for e in heldout}
    assert len(heldout) == round(0.15 * len(example_set.examples))
    other, _ = split_examples(example_set.examples, heldout_fraction=0.15, seed=1)
    assert {e.prompt_id for e in other} != {e.prompt_id for e in train}
    assert len(example_set.digest) == 64
