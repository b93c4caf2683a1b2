"""Whatever a user types, the resolver gives a recipe or an AgrirecipeError, never a crash."""

from __future__ import annotations

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from agrirecipe import AgrirecipeError, PromptError
from agrirecipe.resolve import MAX_PROMPT_CHARS, resolve
from agrirecipe.resolve._lexicon import vocabulary

_WORDS = sorted(
    {
        *(str(w) for w in vocabulary()["filler"][:80]),
        *(p for phrases in vocabulary()["stages"].values() for p in phrases[:6]),
        *(p for phrases in vocabulary()["seasons"].values() for p in phrases[:2]),
        *(p for phrases in vocabulary()["relations"].values() for p in phrases[:2]),
        "apple",
        "orchard",
        "carrots",
        "two",
        "three",
        "fields",
        "one",
        "of",
        "and",
        ",",
        ":",
        "Gala",
        "cherry",
        "tomatoes",
        "wheat",
        "vegetables",
        "fruit",
        "2",
        "ha",
        "by",
        "50",
        "m",
        "mango",
        "parking lot",
        "all",
        "both",
        "the",
        "them",
        "different",
        "between",
        "north of",
        "no",
        "blight",
        "healthy",
        "in",
        "March",
        "Chile",
        "-",
        "?",
        ".",
        "I mean",
    }
)


def _check(prompt: str) -> None:
    try:
        recipe = resolve(prompt, resolver="rules").recipe
    except AgrirecipeError:
        return
    assert 1 <= len(recipe.fields) <= 64


@settings(max_examples=400, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(st.lists(st.sampled_from(_WORDS), max_size=14).map(" ".join))
def test_word_salad_from_the_vocabulary(prompt: str) -> None:
    _check(prompt)


@settings(max_examples=100, deadline=None)
@given(st.text(max_size=60))
def test_arbitrary_text(prompt: str) -> None:
    _check(prompt)


# --- issue 8: bad numbers and long prompts are PromptErrors -----------------------------------


@pytest.mark.parametrize("strategy", ["rules", "embedding", "llm"])
@pytest.mark.parametrize(
    ("prompt", "number"),
    [
        ("a nan ha wheat field", "nan"),
        ("an inf by 20 m wheat field", "inf"),
        ("a wheat field of infinity hectares", "infinity"),
        ("nan wheat fields", "nan"),
    ],
)
def test_a_number_that_is_not_finite_is_a_prompt_error_naming_it(
    strategy: str, prompt: str, number: str
) -> None:
    with pytest.raises(PromptError, match=number):
        resolve(prompt, resolver=strategy)


def test_a_prompt_over_the_documented_length_is_refused_at_once() -> None:
    prompt = "a wheat field" + " and a wheat field" * 2000  # 36 kB: once 805 s
    assert len(prompt) > MAX_PROMPT_CHARS
    with pytest.raises(PromptError, match="4,000"):
        resolve(prompt, resolver="hybrid")
    # At the limit it is read (and refused for its 64-field cap, not its length).
    at_limit = ("a wheat field and " * 300)[:MAX_PROMPT_CHARS]
    with pytest.raises(PromptError, match="at most 64"):
        resolve(at_limit, resolver="hybrid")
