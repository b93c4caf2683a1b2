"""Hybrid's use of the LLM strategy: only when asked, only for prompts nothing else reads."""

from __future__ import annotations

import pytest

from agrirecipe import PromptError, UnknownCropError
from agrirecipe.resolve import FieldIntent, ResolveContext, Resolver, SceneIntent, resolve
from agrirecipe.resolve._hybrid import HybridResolver


class _RecordingLlm(Resolver):
    """Stands in for the LLM strategy and records what it was asked."""

    name = "llm"

    def __init__(self) -> None:
        self.prompts: list[str] = []

    def resolve_intent(self, prompt: str, context: ResolveContext) -> SceneIntent:
        self.prompts.append(prompt)
        field = FieldIntent(text=prompt, crop="Grape")
        return SceneIntent(prompt=prompt, fields=(field,), resolver=self.name)


def test_the_llm_is_not_called_by_default() -> None:
    llm = _RecordingLlm()
    with pytest.raises(PromptError):
        resolve("make it look nice please", resolver=HybridResolver(llm=llm))
    assert llm.prompts == []


def test_the_llm_reads_only_what_nothing_else_can() -> None:
    llm = _RecordingLlm()
    hybrid = HybridResolver(use_llm=True, llm=llm)
    recipe = resolve("a healthy apple orchard", resolver=hybrid).recipe
    assert recipe.fields[0].crop == "Apple" and llm.prompts == []
    with pytest.raises(UnknownCropError):  # an unknown crop is an answer, not a gap
        resolve("a mango plantation", resolver=hybrid)
    with pytest.raises(PromptError):  # so is a non-agricultural request
        resolve("build a parking lot", resolver=hybrid)
    assert llm.prompts == []
    recipe = resolve("something lovely with wine", resolver=hybrid).recipe
    assert llm.prompts == ["something lovely with wine"]
    assert (recipe.fields[0].crop, recipe.resolver) == ("Grape", "hybrid")


@pytest.mark.slow
def test_the_fallback_runs_the_real_gguf_model() -> None:
    pytest.importorskip("llama_cpp")
    hybrid = HybridResolver(use_llm=True)
    with pytest.raises(PromptError) as caught:
        resolve("make it look nice please", resolver=hybrid)
    # The LLM strategy's own refusal, not the lexical reader's.
    assert "no crop or field found" not in str(caught.value)
    assert hybrid.llm.name == "llm"
