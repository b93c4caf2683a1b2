"""The finetuned strategy asks local records: every question it asks is a prefix of a
training example, and it reads far fewer tokens than the whole record."""

from __future__ import annotations

import pytest

from agrirecipe.evaluation import load_benchmark
from agrirecipe.finetune import FinetunedResolver, TrainingExample, build_examples
from agrirecipe.hierarchy import default_hierarchy
from agrirecipe.knowledge import default_knowledge_base
from agrirecipe.resolve import ResolveContext
from agrirecipe.resolve.llm import LlmResolver


class _Teacher:
    """A language model that answers each question with the training examples' value for it.

    A question whose context is not the start of an example's line has no answer:
    the test fails there (the strategy asked something it was not trained on).
    """

    model_id = "teacher"

    def __init__(self, examples: list[TrainingExample]) -> None:
        self.texts = [example.context + example.target for example in examples]
        self.asked: list[str] = []

    def complete(self, prompt: str, *, grammar: str, max_tokens: int = 256) -> str:
        self.asked.append(prompt)
        for text in self.texts:
            if text.startswith(prompt):
                return text[len(prompt) :].split("\n", 1)[0] + "\n"
        raise AssertionError(f"no training example starts with the question {prompt!r}")


class _Whole(LlmResolver):
    """The llm strategy's whole record without the few-shot document (for comparison)."""

    prefix = ""


@pytest.fixture(scope="module")
def context() -> ResolveContext:
    return ResolveContext(default_hierarchy(), default_knowledge_base())


def test_every_question_is_the_start_of_a_training_line(context: ResolveContext) -> None:
    prompts = {p.id: p for p in load_benchmark().prompts}
    built = build_examples(limit=80, seed=3)
    by_prompt: dict[str, list[TrainingExample]] = {}
    for example in built.examples:
        by_prompt.setdefault(example.prompt_id, []).append(example)
    asked = 0
    for prompt_id, examples in by_prompt.items():
        teacher = _Teacher(examples)
        resolver = FinetunedResolver(adapter="unused.gguf")
        resolver._tuned = teacher  # type: ignore[assignment]
        intent = resolver.resolve_intent(prompts[prompt_id].prompt, context)
        truth = prompts[prompt_id]
        assert len(intent.fields) == len(truth.fields), prompt_id
        assert sorted(f.crop or "" for f in intent.fields) == sorted(
            f.crop[0] for f in truth.fields if f.crop
        ), prompt_id
        asked += len(teacher.asked)
    assert asked >= 5  # the model was asked: the check above is not empty


def test_the_relations_question_reads_the_parts_words_only(context: ResolveContext) -> None:
    prompt = "Gala apples north of Nantes carrots, young, in summer, with a barn behind"
    examples = [
        TrainingExample(
            "x",
            f"Request: {prompt}\n",
            "Part 1: Gala apples\nPart 2: north of Nantes carrots\nRelations: 1 north of 2\n",
        )
    ]
    local, whole = _Teacher(examples), _Teacher(examples)
    resolver = FinetunedResolver(adapter="unused.gguf")
    resolver._tuned = local  # type: ignore[assignment]
    intent = resolver.resolve_intent(prompt, context)
    assert local.asked == [
        f"Request: {prompt}\nPart 1: Gala apples\nPart 2: north of Nantes carrots\nRelations:"
    ]
    assert [(r.kind, r.subject, r.objects) for r in intent.relations] == [("north_of", 0, (1,))]
    # the whole record asks the same question after every answer line of both parts
    with pytest.raises(AssertionError, match="no training example"):
        _Whole(whole).resolve_intent(prompt, context)
    assert whole.asked[0].count("Gala apples") == 3
    assert len(whole.asked[0]) > 2 * len(local.asked[0])
