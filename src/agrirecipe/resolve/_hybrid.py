"""The "hybrid" strategy ("auto"): rules first, the embedding model for what they leave open.

Measured on the benchmark (docs/EVALUATION.md), the lexicon with rapidfuzz
typo matching reads every name the hierarchy knows exactly and in a fraction
of a millisecond, so it goes first. The embedding model is consulted only for
unknown words standing where a crop or variety name belongs ("a kohlrabi
field", "Honeycrisp apples"): a very close match is read as that name, and
otherwise the request is refused with the known crops nearest *in meaning*.
Prompts without such words never load the model.

The local LLM ("llm" strategy) is slower by three to four orders of magnitude
(seconds per prompt on two cores), and on the benchmark rules and retrieval
leave no prompt for it to put right (docs/EVALUATION.md), so by default hybrid
does not call it. With ``use_llm=True`` it is asked when the lexical reading
found no field at all, the one case where its free reading can add something.
"""

from __future__ import annotations

from collections.abc import Sequence

from agrirecipe._errors import PromptError, UnknownCropError
from agrirecipe.localmodels import Embedder
from agrirecipe.resolve._embedding import EmbeddingResolver, runs_where
from agrirecipe.resolve._intent import ResolveContext, Resolver, SceneIntent, TraceStep
from agrirecipe.resolve._lexicon import Item, Lexicon
from agrirecipe.resolve._parse import NOTHING_FOUND
from agrirecipe.resolve._rules import fuzzy_unknown_words

__all__ = ["HybridResolver"]

#: Similarity for reading an unknown word as a hierarchy name: the lexicon has already
#: tried every exact and misspelt name, so only a near-synonym may pass.
HYBRID_ACCEPT_SIMILARITY = 0.85
_NAME_SENSES = ("crop", "variety", "category", "plot")


class HybridResolver(EmbeddingResolver):
    """Lexicon and rapidfuzz first; embedding retrieval for unknown names; LLM on request."""

    name = "hybrid"
    lexicon_has_crop_names = True
    accept_similarity = HYBRID_ACCEPT_SIMILARITY

    def __init__(
        self,
        embedder: Embedder | None = None,
        *,
        use_llm: bool = False,
        llm: Resolver | None = None,
    ) -> None:
        super().__init__(embedder)
        self.use_llm = use_llm
        self._llm = llm

    def read_unknown_words(
        self, items: list[Item], lexicon: Lexicon, context: ResolveContext
    ) -> tuple[list[Item], list[TraceStep]]:
        """Fuzzy typo matching; then retrieval for unknown words in a crop name's place."""
        items, steps = fuzzy_unknown_words(items, lexicon)
        runs = [run for run in runs_where(items, _unknown) if _names_a_crop(items, run)]
        if not runs:
            return items, steps
        return self._retrieve(items, runs, context, steps)

    def nearest_crops(
        self, name: str, like: Sequence[str], context: ResolveContext
    ) -> tuple[str, ...]:
        """Curated nearest crops, else nearest in meaning (loads the embedding model)."""
        return super().nearest_crops(name, like, context)

    def resolve_intent(self, prompt: str, context: ResolveContext) -> SceneIntent:
        """Rules and retrieval; the LLM only if enabled and nothing was found."""
        try:
            return super().resolve_intent(prompt, context)
        except UnknownCropError:
            raise
        except PromptError as exc:
            if not self.use_llm or not exc.message.startswith(NOTHING_FOUND):
                raise
        intent = self.llm.resolve_intent(prompt, context)
        return intent.model_copy(update={"resolver": self.name})

    @property
    def llm(self) -> Resolver:
        """The "llm" strategy (loaded on first use)."""
        if self._llm is None:
            from agrirecipe.resolve._registry import get_resolver

            self._llm = get_resolver("llm")
        return self._llm


def _unknown(item: Item) -> bool:
    return not item.senses and item.norm.isalpha()


def _names_a_crop(items: Sequence[Item], run: tuple[int, int]) -> bool:
    """Whether a run of unknown words stands where a crop name belongs.

    Right before a crop, variety, category or plot word ("kohlrabi field",
    "Honeycrisp apples"), or after "of"/"with" that follows a plot word ("a field
    of kohlrabi").
    """
    start, end = run
    if end < len(items) and items[end].has(*_NAME_SENSES):
        return True
    return start >= 2 and items[start - 1].has("of") and items[start - 2].has("plot")
