"""Whatever a user types, the resolver gives a recipe or an AgrirecipeError, never a crash."""

from __future__ import annotations

from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from agrirecipe import AgrirecipeError
from agrirecipe.resolve import resolve
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
