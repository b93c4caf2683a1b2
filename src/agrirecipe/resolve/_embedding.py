"""The "embedding" strategy: crop and variety names found by meaning (the paper's RAG).

A FAISS index (:class:`~agrirecipe.localmodels.VectorIndex`, cached on disk,
keyed by the hierarchy and the model) holds one row per crop or variety name
and alias of the hierarchy, and a second one a short descriptor per crop
("orange, an evergreen tree grown for fruits") for suggesting the known crops
nearest in meaning to an unknown one. The sentence-transformers model loads on
first use and is reused for every later call in the process.

The strategy reads stage, season, health, sizes and structure with the same
vocabulary as "rules"; only crop and variety mentions go through retrieval.
"""

from __future__ import annotations

import threading
from collections.abc import Callable, Sequence
from dataclasses import dataclass

from agrirecipe.hierarchy import Hierarchy
from agrirecipe.knowledge import KnowledgeBase
from agrirecipe.localmodels import Embedder, VectorIndex, default_embedder
from agrirecipe.resolve._intent import Candidate, ResolveContext, TraceStep
from agrirecipe.resolve._lexicon import Item, Lexicon, Sense, normalise, vocabulary
from agrirecipe.resolve._rules import LexicalResolver, fuzzy_unknown_words, nearest_by_spelling

__all__ = ["CropIndex", "EmbeddingResolver", "Match", "runs_where"]

#: Cosine similarity a span needs to be read as a crop or variety name.
ACCEPT_SIMILARITY = 0.75
_SEEN_LIMIT = 4096
# How much worse than its best single word a multi-word span may fit and still win.
_SPAN_TOLERANCE = 0.02
#: Longest span of words tried as one name.
_MAX_SPAN = 3
# Words of a name may also be vocabulary ("winter" in Winter Wheat, "acre" in Golden
# Acre, "plum" in plum tomato), but never these, which always structure the sentence.
_STRUCTURE_KINDS = frozenset(
    {"separator", "conjunction", "relation", "relation_trailer", "of", "plot", "category"}
)


@dataclass(frozen=True, slots=True)
class Match:
    """A span's best name in the index."""

    crop: str
    variety: str | None
    text: str
    score: float


class CropIndex:
    """Vector indexes over a hierarchy's names and crop descriptors."""

    def __init__(self, hierarchy: Hierarchy, knowledge: KnowledgeBase, embedder: Embedder) -> None:
        self.embedder = embedder
        # Spans already looked up: prompts repeat words, and a lookup costs a model call.
        self._seen: dict[str, Match] = {}
        self._nearest: dict[tuple[str, int], list[tuple[str, float]]] = {}
        self._lock = threading.Lock()
        texts: list[str] = []
        self.rows: list[tuple[str, str | None]] = []
        for crop in hierarchy.crops.values():
            for phrase in (crop.name, *crop.aliases):
                texts.append(normalise(phrase))
                self.rows.append((crop.name, None))
            for variety in crop.varieties:
                for phrase in (variety.name, *variety.aliases):
                    # The name alone ("jonagold") and with its crop ("jonagold apple"):
                    # people type both, and a bare name embeds far from "name + crop".
                    name = normalise(phrase)
                    crop_word = normalise(crop.name)
                    for text in dict.fromkeys((name, f"{name} {crop_word}")):
                        if text != name and crop_word in name:
                            continue
                        texts.append(text)
                        self.rows.append((crop.name, variety.name))
        self.names = VectorIndex.build(texts, embedder, name=f"crop-names-{hierarchy.digest()}")
        self.crops = list(hierarchy.crops)
        descriptors = []
        for name in self.crops:
            entry = knowledge.crop_file(name)
            category = hierarchy.crops[name].category.lower()
            descriptors.append(
                f"{name.lower()}, a {entry.leaf_habit} {entry.growth_form.replace('_', ' ')} "
                f"grown for {category}"
            )
        self.descriptors = VectorIndex.build(
            descriptors, embedder, name=f"crop-descriptors-{knowledge.digest()}"
        )

    def match(self, spans: Sequence[str]) -> list[Match]:
        """The best name for each span (one embedding batch for the spans not seen before)."""
        with self._lock:
            return self._match(spans)

    def _match(self, spans: Sequence[str]) -> list[Match]:
        new = [span for span in dict.fromkeys(spans) if span not in self._seen]
        if new:
            # SentenceTransformerEmbedder runs short batches on one torch thread.
            vectors = self.embedder.encode(new)
            scores, rows = self.names.search(vectors, 1)
            if len(self._seen) + len(new) > _SEEN_LIMIT:
                self._seen.clear()
            for span, score, row in zip(new, scores[:, 0], rows[:, 0], strict=True):
                crop, variety = self.rows[int(row)]
                self._seen[span] = Match(crop, variety, span, float(score))
        return [self._seen[span] for span in spans]

    def nearest(self, name: str, limit: int = 3) -> list[tuple[str, float]]:
        """Known crops nearest in meaning to an unknown plant name, best first."""
        key = (normalise(name), limit)
        with self._lock:
            return self._nearest_to(key)

    def _nearest_to(self, key: tuple[str, int]) -> list[tuple[str, float]]:
        name, limit = key
        if key not in self._nearest:
            vectors = self.embedder.encode([f"{name} plant"])
            scores, rows = self.descriptors.search(vectors, limit)
            if len(self._nearest) >= _SEEN_LIMIT:
                self._nearest.clear()
            self._nearest[key] = [
                (self.crops[int(row)], float(score))
                for score, row in zip(scores[0], rows[0], strict=True)
                if row >= 0
            ]
        return self._nearest[key]


class _IndexCache:
    """One :class:`CropIndex` per (hierarchy, knowledge, model), built on first use."""

    def __init__(self) -> None:
        self._indexes: dict[tuple[str, str, str], CropIndex] = {}
        # Digests hash whole files: compute them once per object (kept alive here so
        # that its id is not reused).
        self._by_object: dict[tuple[int, int, int], tuple[object, CropIndex]] = {}
        self._lock = threading.Lock()

    def get(self, context: ResolveContext, embedder: Embedder) -> CropIndex:
        objects = (context.hierarchy, context.knowledge, embedder)
        fast = (id(objects[0]), id(objects[1]), id(objects[2]))
        with self._lock:
            known = self._by_object.get(fast)
            if known is not None:
                return known[1]
            key = (context.hierarchy.digest(), context.knowledge.digest(), embedder.model_id)
            index = self._indexes.get(key)
            if index is None:
                index = CropIndex(context.hierarchy, context.knowledge, embedder)
                self._indexes[key] = index
            self._by_object[fast] = (objects, index)
            return index


def _name_words(hierarchy: Hierarchy) -> frozenset[str]:
    words: set[str] = set()
    for crop in hierarchy.crops.values():
        for phrase in (crop.name, *crop.aliases):
            words.update(normalise(phrase).split())
        for variety in crop.varieties:
            for phrase in (variety.name, *variety.aliases):
                words.update(normalise(phrase).split())
    return frozenset(words)


class EmbeddingResolver(LexicalResolver):
    """Crop and variety mentions by nearest neighbour in the local embedding model's space."""

    name = "embedding"
    lexicon_has_crop_names = False
    accept_similarity = ACCEPT_SIMILARITY

    def __init__(self, embedder: Embedder | None = None) -> None:
        self._embedder = embedder
        self._indexes = _IndexCache()
        self._name_words: dict[str, frozenset[str]] = {}

    @property
    def embedder(self) -> Embedder:
        """The embedding model (the process-wide default unless one was given)."""
        if self._embedder is None:
            self._embedder = default_embedder()
        return self._embedder

    def index(self, context: ResolveContext) -> CropIndex:
        """The crop index for this context (built or loaded from the cache on first use)."""
        return self._indexes.get(context, self.embedder)

    def _words(self, context: ResolveContext) -> frozenset[str]:
        key = context.hierarchy.digest()
        if key not in self._name_words:
            self._name_words[key] = _name_words(context.hierarchy)
        return self._name_words[key]

    def read_unknown_words(
        self, items: list[Item], lexicon: Lexicon, context: ResolveContext
    ) -> tuple[list[Item], list[TraceStep]]:
        """Typos of vocabulary words by rapidfuzz; crop and variety names by retrieval."""
        items, steps = fuzzy_unknown_words(items, lexicon)
        words = self._words(context)
        runs = _runs(items, words)
        if not runs:
            return items, steps
        return self._retrieve(items, runs, context, steps)

    def _retrieve(
        self,
        items: list[Item],
        runs: list[tuple[int, int]],
        context: ResolveContext,
        steps: list[TraceStep],
    ) -> tuple[list[Item], list[TraceStep]]:
        spans: list[tuple[int, int]] = []
        for start, end in runs:
            for width in range(min(_MAX_SPAN, end - start), 0, -1):
                spans += [
                    (s, s + width)
                    for s in range(start, end - width + 1)
                    if any(_open(item) for item in items[s : s + width])
                ]
        if not spans:
            return items, steps
        texts = [" ".join(item.norm for item in items[s:e]) for s, e in spans]
        matches = self.index(context).match(texts)
        best: dict[tuple[int, int], Match] = dict(zip(spans, matches, strict=True))
        weak_words = {normalise(w) for w in vocabulary()["weak_variety_words"]}
        replaced: dict[int, Item] = {}
        taken: set[int] = set()
        # Longest spans first: "cherry tomatoes" is one name, not "cherry" + "tomatoes".
        for (start, end), match in sorted(
            best.items(), key=lambda kv: (-(kv[0][1] - kv[0][0]), -kv[1].score, kv[0][0])
        ):
            if match.score < self.accept_similarity or taken & set(range(start, end)):
                continue
            # A span is one name only if it fits at least as well as the names its words
            # make alone: "gala pear" is Gala beside Pear, not a poor match for "gala apple".
            alone = [
                best[(p, p + 1)].score
                for p in range(start, end)
                if end - start > 1
                and (p, p + 1) in best
                and best[(p, p + 1)].score >= self.accept_similarity
            ]
            if alone and match.score < min(alone) - _SPAN_TOLERANCE:
                continue
            tokens = tuple(t for item in items[start:end] for t in item.tokens)
            weak = all(t.norm in weak_words for t in tokens)
            senses = [Sense("crop", match.crop)] if match.variety is None else []
            if match.variety is not None:
                senses.append(Sense("variety", match.variety, crop=match.crop, weak=weak))
            item = Item(tokens, tuple(senses), fuzzy_score=round(100 * match.score, 1))
            item.data["source"] = "embedding"
            replaced[start] = item
            taken.update(range(start + 1, end))
            taken.add(start)
            steps.append(
                TraceStep(
                    stage="retrieve",
                    subject=item.raw,
                    detail=f"nearest name: {match.variety or ''} {match.crop}".replace("  ", " "),
                    candidates=(
                        Candidate(
                            value=f"{match.crop}/{match.variety}" if match.variety else match.crop,
                            score=round(100 * match.score, 1),
                            source="embedding",
                        ),
                    ),
                )
            )
        out: list[Item] = []
        for position, item in enumerate(items):
            if position in replaced:
                out.append(replaced[position])
            elif position not in taken:
                out.append(item)
        return out, steps

    def nearest_crops(
        self, name: str, like: Sequence[str], context: ResolveContext
    ) -> tuple[str, ...]:
        """Known crops nearest in meaning (curated list first, then the embedding index)."""
        if like:
            return tuple(like[:3])
        nearest = self.index(context).nearest(name)
        if nearest and nearest[0][1] >= 0.3:
            return tuple(crop for crop, _ in nearest)
        return nearest_by_spelling(context, name, like)


def _open(item: Item) -> bool:
    """An unknown word, or a word that means nothing but a name (not "winter", "in")."""
    return not item.senses or all(s.kind == "filler" for s in item.senses)


def runs_where(items: Sequence[Item], accept: Callable[[Item], bool]) -> list[tuple[int, int]]:
    """``(start, end)`` of every maximal run of items that ``accept``."""
    runs: list[tuple[int, int]] = []
    start: int | None = None
    for position, item in enumerate(items):
        if accept(item) and start is None:
            start = position
        elif not accept(item) and start is not None:
            runs.append((start, position))
            start = None
    if start is not None:
        runs.append((start, len(items)))
    return runs


def _runs(items: Sequence[Item], name_words: frozenset[str]) -> list[tuple[int, int]]:
    """Maximal runs of items that may be (part of) a crop or variety name."""

    def candidate(item: Item) -> bool:
        return item.norm.replace(" ", "").isalpha() and (
            not item.senses
            or (
                not any(s.kind in _STRUCTURE_KINDS for s in item.senses)
                and all(t.norm in name_words for t in item.tokens)
            )
        )

    return runs_where(items, candidate)
