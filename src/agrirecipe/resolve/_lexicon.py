"""Tokens and the phrase lexicon: what each word or phrase of a prompt can mean.

The lexicon joins three sources: the hierarchy (crop, variety and category
names and aliases), the knowledge base (disease names, read as "Ill"), and
the vocabulary files under ``resolve/data/`` (stages, seasons, health,
months, numbers, units, relations, plot nouns, places, crops we do not hold).
Matching is exact on normalised tokens, longest phrase first; fuzzy matching
of typos (rapidfuzz) is a separate, explicit step (:meth:`Lexicon.fuzzy`). The
lexicon is built from those sources in ``_lexicon_build``.
"""

from __future__ import annotations

import functools
import re
import unicodedata
from collections.abc import Iterable, Sequence
from dataclasses import dataclass, field
from pathlib import Path
from typing import TYPE_CHECKING, Any, Literal

import yaml

from agrirecipe.resolve._sounds import sound_key

if TYPE_CHECKING:
    from agrirecipe.hierarchy import Hierarchy

__all__ = [
    "Item",
    "Lexicon",
    "Sense",
    "Token",
    "load_data",
    "normalise",
    "plot_nouns_pattern",
    "plurals",
    "reader_words",
    "singular",
    "tokenize",
    "vocabulary",
]

DATA_DIR = Path(__file__).resolve().parent / "data"

SenseKind = Literal[
    "crop",
    "variety",
    "category",
    "other_crop",
    "plot",
    "container",
    "stage",
    "season",
    "season_modifier",
    "month",
    "health",
    "negation",
    "number",
    "quantity",
    "fraction",
    "area_unit",
    "length_unit",
    "dimension_joiner",
    "side",
    "relation",
    "relation_trailer",
    "conjunction",
    "separator",
    "reference",
    "correction",
    "all",
    "distinct",
    "other",
    "of",
    "hemisphere",
    "place",
    "non_agricultural",
    "geometry",
    "zone",
    "same_size",
    "same_spacing",
    "cue",
    "scenery",
    "filler",
]


@dataclass(frozen=True, slots=True)
class Sense:
    """One meaning of a phrase; ``value`` depends on ``kind`` (a crop, a stage, a number...)."""

    kind: SenseKind
    value: Any = None
    crop: str | None = None
    weak: bool = False


@dataclass(frozen=True, slots=True)
class Token:
    """A word, number or punctuation mark of the prompt, with its place in the original text."""

    norm: str
    raw: str
    start: int
    end: int

    @property
    def capitalised(self) -> bool:
        """Written with a capital first letter (a hint that it is a name)."""
        return self.raw[:1].isupper()


@dataclass(slots=True)
class Item:
    """A run of tokens read as one phrase, with every sense the lexicon knows for it."""

    tokens: tuple[Token, ...]
    senses: tuple[Sense, ...]
    fuzzy_score: float | None = None
    fuzzy_phrase: str | None = None
    role: str = ""
    data: dict[str, Any] = field(default_factory=dict)

    @property
    def norm(self) -> str:
        """The normalised words."""
        return " ".join(token.norm for token in self.tokens)

    @property
    def raw(self) -> str:
        """The words as typed."""
        return " ".join(token.raw for token in self.tokens)

    @property
    def start(self) -> int:
        """Character offset of the first token in the prompt."""
        return self.tokens[0].start

    @property
    def end(self) -> int:
        """Character offset just past the last token."""
        return self.tokens[-1].end

    @property
    def scenery(self) -> bool:
        """A word for scenery ("tracks", "tractors", "sheds"), not for plants or plots."""
        return self.role in ("filler", "non_agricultural") and bool(
            self.data.get("scenery") or self.senses_of("scenery")
        )

    def senses_of(self, *kinds: str) -> list[Sense]:
        """The senses of the given kinds, in lexicon order."""
        return [sense for sense in self.senses if sense.kind in kinds]

    def has(self, *kinds: str) -> bool:
        """Whether any sense is of one of ``kinds``."""
        return any(sense.kind in kinds for sense in self.senses)


def normalise(text: str) -> str:
    """Lower case with accents folded to ASCII: ``"Doyenné"`` -> ``"doyenne"``."""
    folded = unicodedata.normalize("NFKD", text)
    return "".join(c for c in folded if not unicodedata.combining(c)).lower()


# Numbers (with a decimal point or comma), words, and single punctuation marks.
# Hyphens and apostrophes inside words are dropped so "harvest-ready" == "harvest ready";
# a hyphen between spaces is a dash ("two orchards - Gala and Fuji"), and one written
# onto a number is a minus sign ("-2 ha", not the dash of "50-100").
_TOKEN = re.compile(r"\d+(?:[.,]\d+)*|[^\W\d_]+|[^\w\s'’\-]|(?<=\s)-(?=\s)|(?<![\w.])[-−](?=\d)")


#: Marks that separate the members of a list as commas do.
_LIST_MARKS = frozenset({"|", "•", "·", "¦"})


def tokenize(prompt: str) -> list[Token]:
    """The prompt's tokens; ``"50x100m"`` is ``50``, ``x``, ``100``, ``m``."""
    text = prompt.replace("²", "2")
    tokens: list[Token] = []
    for match in _TOKEN.finditer(text):
        raw = match.group()
        norm = normalise(raw)
        if re.fullmatch(r"\d+(?:[.,]\d+)*", raw):
            norm = _number_text(raw)
        if raw in _LIST_MARKS:
            norm = ","  # "Sturon | Stuttgarter Riesen | Walla Walla": a list's commas
        if (
            norm == "k"
            and tokens
            and tokens[-1].end == match.start()
            and number_value(tokens[-1].norm) is not None
        ):
            # "the 70k plot", "1.2k trees": thousands
            thousands = float(tokens[-1].norm) * 1000
            start = tokens[-1].start
            text = f"{thousands:f}".rstrip("0").rstrip(".")
            tokens[-1] = Token(text, prompt[start : match.end()], start, match.end())
            continue
        tokens.append(Token(norm, prompt[match.start() : match.end()], match.start(), match.end()))
    return tokens


def _number_text(raw: str) -> str:
    """``"10,000"`` -> ``"10000"``, ``"2,5"`` -> ``"2.5"``: a comma before 3 digits groups."""
    parts = re.split(r"([.,])", raw)
    digits = parts[0]
    for index in range(1, len(parts), 2):
        mark, group = parts[index], parts[index + 1]
        if mark == "," and len(group) == 3 and "." not in digits:
            digits += group
        else:
            digits += "." + group
    return digits


def number_value(text: str) -> float | None:
    """The value of a numeric token's normalised text, or None."""
    try:
        return float(text)
    except ValueError:
        return None


@functools.lru_cache(maxsize=4)
def load_data(name: str) -> dict[str, Any]:
    """One YAML file of ``resolve/data/`` (cached)."""
    data = yaml.safe_load((DATA_DIR / name).read_text(encoding="utf-8"))
    assert isinstance(data, dict), name
    return data


def vocabulary() -> dict[str, Any]:
    """The parsed ``vocabulary.yaml``."""
    return load_data("vocabulary.yaml")


@functools.cache
def plot_nouns_pattern() -> str:
    """The plot nouns of vocabulary.yaml as one regular-expression alternation, longest
    first (for the text passes that look for a word before or after a plot noun)."""
    nouns = sorted((str(n) for n in vocabulary()["plot_nouns"]), key=len, reverse=True)
    return "|".join(re.escape(n) for n in nouns)


@functools.cache
def reader_words(name: str) -> frozenset[str]:
    """A list of words one reading pass looks for (``reader_words`` in vocabulary.yaml)."""
    return frozenset(str(word) for word in vocabulary()["reader_words"][name])


@functools.cache
def scenery_words(*groups: str) -> tuple[str, ...]:
    """The phrases of these groups of ``scenery.yaml``, longest first."""
    data = load_data("scenery.yaml")
    phrases = {str(p) for group in groups for p in data[group]}
    return tuple(sorted(phrases, key=len, reverse=True))


def plurals(phrase: str) -> list[str]:
    """Plural forms of a phrase's last word (``"cherry tomato"`` -> ``"cherry tomatoes"``)."""
    head, _, last = phrase.rpartition(" ")
    prefix = f"{head} " if head else ""
    if not last.isalpha() or len(last) < 3:
        return []
    forms = [last + "s"]
    if last.endswith(("s", "x", "ch", "sh", "o")):
        forms.append(last + "es")
    if last.endswith("y") and last[-2] not in "aeiou":
        forms.append(last[:-1] + "ies")
    return [prefix + form for form in forms]


def singular(word: str) -> str:
    """A plural word's singular, undoing :func:`plurals` ("potatoes" -> "potato",
    "strawberries" -> "strawberry", "tunnels" -> "tunnel"); other words unchanged (and
    words of three letters or fewer, which :func:`plurals` never forms: "is", "gas")."""
    if len(word) <= 3:
        return word
    if word.endswith("ies") and len(word) > 4:
        return word[:-3] + "y"
    if word.endswith(("oes", "xes", "ches", "shes", "sses")):
        return word[:-2]
    if word.endswith("s") and not word.endswith("ss"):
        return word[:-1]
    return word


class Lexicon:
    """Phrases (tuples of normalised words) and their senses."""

    def __init__(self) -> None:
        self.phrases: dict[tuple[str, ...], list[Sense]] = {}
        self.max_words = 1
        self.fuzzy_choices: list[str] = []
        self._fuzzy_senses: dict[str, tuple[Sense, ...]] = {}
        self._sounds: dict[str, list[str]] = {}

    def add(self, phrase: str, sense: Sense, *, derived: bool = False) -> None:
        """Add a sense to a phrase; a derived form (a plural) never shadows a real entry."""
        # Split as prompts are, so "hawke's bay" matches what a user types.
        words = tuple(token.norm for token in tokenize(phrase)) or tuple(
            normalise(phrase).split()  # a lone dash is a token only between spaces
        )
        if not words:
            return
        senses = self.phrases.setdefault(words, [])
        if derived and any(s.kind == sense.kind for s in senses):
            return
        if derived and sense.kind == "other_crop" and any(s.kind == "scenery" for s in senses):
            return  # "palms behind" is scenery; "a palm plantation" is still refused
        if sense not in senses:
            senses.append(sense)
        self.max_words = max(self.max_words, len(words))

    def add_with_plurals(self, phrase: str, sense: Sense) -> None:
        """Add a phrase and the plural forms of its last word."""
        self.add(phrase, sense)
        for plural in plurals(normalise(phrase)):
            self.add(plural, sense, derived=True)

    def lookup(self, words: Sequence[str]) -> list[Sense]:
        """Senses of exactly these words (empty when unknown)."""
        return self.phrases.get(tuple(words), [])

    def tag(self, tokens: Sequence[Token]) -> list[Item]:
        """Greedy longest-match of the tokens against the lexicon; unknown words get no sense."""
        items: list[Item] = []
        index = 0
        while index < len(tokens):
            for width in range(min(self.max_words, len(tokens) - index), 0, -1):
                words = [t.norm for t in tokens[index : index + width]]
                senses = self.phrases.get(tuple(words))
                if senses:
                    items.append(Item(tuple(tokens[index : index + width]), tuple(senses)))
                    index += width
                    break
            else:
                items.append(Item((tokens[index],), ()))
                index += 1
        return items

    def prepare_fuzzy(self, kinds: Iterable[str]) -> None:
        """Choose which phrases typos may be matched to (only phrases of 4+ letters)."""
        wanted = set(kinds)
        choices: dict[str, tuple[Sense, ...]] = {}
        for words, senses in self.phrases.items():
            text = " ".join(words)
            kept = tuple(s for s in senses if s.kind in wanted)
            if (
                kept
                and len(text.replace(" ", "")) >= 4
                and not any(s.kind == "filler" for s in senses)
            ):
                choices[text] = kept
        self.fuzzy_choices = sorted(choices)
        self._fuzzy_senses = choices
        self._sounds = {}
        for text in self.fuzzy_choices:
            if " " not in text and len(text) >= 5:
                self._sounds.setdefault(text[0] + sound_key(text), []).append(text)

    def fuzzy(self, text: str) -> tuple[str, float, tuple[Sense, ...]] | None:
        """The phrase a possibly misspelt ``text`` most likely means, or None.

        Scored with rapidfuzz's normalised Damerau-Levenshtein similarity (0-100);
        words under four letters are never guessed.
        """
        from rapidfuzz import process
        from rapidfuzz.distance import DamerauLevenshtein

        letters = len(text.replace(" ", ""))
        if letters < 4 or not self.fuzzy_choices:
            return None
        if " " not in text and _everyday(text):
            return None  # "train" is a word of its own, not a misspelt "grain"
        # Damerau-Levenshtein counts a swapped pair of letters ("appel", "whaet") as one
        # edit; one edit in five letters is the most a short word may differ by, two in
        # nine a long one ("chantaney" is Chantenay; "chantney", eight letters typed, two
        # edits from the nine of Chantenay).
        # (one word only: "fruit fat" is no misspelt "fruit set")
        long_word = letters >= 9 or (letters == 8 and " " not in text)
        cutoff = 0.77 if long_word else 0.79  # (0.78, 0.8 themselves: float-safe)
        # (the nearest few, best first: "grand nane" is nearest "grande naine", refused
        # below for changing the word "grand", and next nearest "grand nain")
        matches = process.extract(
            text,
            self.fuzzy_choices,
            scorer=DamerauLevenshtein.normalized_similarity,
            score_cutoff=cutoff,
            limit=3,
        )
        if not matches:
            return self._sounds_like(text)
        phrase, score = str(matches[0][0]), 100.0 * float(matches[0][1])
        if text.startswith(phrase) and text[len(phrase) :] in _DERIVING_ENDINGS:
            return None  # "blocky" fruit is a word made from "block", not a misspelt one
        said = text.split()
        for match in matches:
            phrase, score = str(match[0]), 100.0 * float(match[1])
            if text[1:] == phrase and text[0] != text[1]:
                continue  # "a fox trotting across": a word of its own, not "rotting" mistyped
            known = phrase.split()
            if len(said) == len(known) and any(
                a != b
                and a in everyday_words()
                and not _doubled(a, b)
                # ("Pinto Noir vines": two letters swapped beside a word said right)
                and not (_swapped(a, b) and len(said) > 1)
                for a, b in zip(said, known, strict=True)
            ):
                # "fire blight on some shoots" is no misspelt "side shoots" ("Red Barron"
                # is Red Baron: a letter doubled is a typo even of a word of its own)
                continue
            return phrase, score, self._fuzzy_senses[phrase]
        return None

    def variety_of(self, text: str, crops: set[str]) -> tuple[str, float, tuple[Sense, ...]] | None:
        """The variety of one of ``crops`` that a word of six letters or more, said right
        before the crop, misspells by one edit ("fontaine potatoes": Fontane), even when the
        word is an everyday one elsewhere; else None."""
        from rapidfuzz import process
        from rapidfuzz.distance import DamerauLevenshtein

        if len(text) < 6 or " " in text:
            return None
        # (one edit away, found the way fuzzy() finds its guesses; then only that crop's)
        near = process.extract(
            text, self.fuzzy_choices, scorer=DamerauLevenshtein.distance, score_cutoff=1, limit=None
        )
        found = [
            str(phrase)
            for phrase, edits, _ in near
            if edits == 1
            and any(s.kind == "variety" and s.crop in crops for s in self._fuzzy_senses[phrase])
        ]
        if len(found) != 1:
            return None
        score = 100.0 * DamerauLevenshtein.normalized_similarity(text, found[0])
        return found[0], score, self._fuzzy_senses[found[0]]

    def _sounds_like(self, text: str) -> tuple[str, float, tuple[Sense, ...]] | None:
        """The one phrase a word of five letters or more, spelt by ear, sounds like
        ("lettus": lettuce), scored by its edit similarity; None when none or several."""
        from rapidfuzz.distance import DamerauLevenshtein

        if " " in text or len(text) < 5 or text.rstrip("s") in everyday_words():
            return None
        found = self._sounds.get(text[0] + sound_key(text), [])
        # (two edits at most: "canes" sounds like no "cayenne")
        found = [p for p in found if DamerauLevenshtein.distance(text, p) <= 2]
        if len({self._fuzzy_senses[p] for p in found}) != 1:
            return None
        phrase = found[0]
        score = 100.0 * DamerauLevenshtein.normalized_similarity(text, phrase)
        return phrase, score, self._fuzzy_senses[phrase]


_DOUBLE = re.compile(r"(.)\1+")


def _doubled(said: str, known: str) -> bool:
    """Whether two words differ only in a letter said once or twice ("barron", "baron")."""
    return _DOUBLE.sub(r"\1", said) == _DOUBLE.sub(r"\1", known)


def _swapped(said: str, known: str) -> bool:
    """Whether two words differ only in two neighbouring letters swapped ("pinto", "pinot")."""
    if len(said) != len(known):
        return False
    differ = [i for i, (a, b) in enumerate(zip(said, known, strict=True)) if a != b]
    return (
        len(differ) == 2
        and differ[1] == differ[0] + 1
        and said[differ[0]] == known[differ[1]]
        and said[differ[1]] == known[differ[0]]
    )


#: Endings that make a new word of a known one ("blocky", "reddish", "ridged").
_DERIVING_ENDINGS = frozenset({"y", "ish", "ed", "ing", "er", "ers", "ly"})


#: Verb endings of a word the vocabulary holds only in its plain form ("dusted": "dust").
_VERB_ENDINGS = ("ed", "ing")


def _everyday(word: str) -> bool:
    """Whether ``word`` is an everyday word, or one with a verb ending ("tramlines dusted
    white" is not a misspelt "rusted"; "spotted": "spot")."""
    words = everyday_words()
    if word in words:
        return True
    for ending in _VERB_ENDINGS:
        stem = word.removesuffix(ending)
        if stem != word and len(stem) >= 4:
            doubled = len(stem) > 4 and stem[-1] == stem[-2]
            if stem in words or stem + "e" in words or (doubled and stem[:-1] in words):
                return True
    return False


@functools.lru_cache(maxsize=1)
def everyday_words() -> frozenset[str]:
    """Common English words, never read as typos of a crop or vocabulary phrase.

    The whole words of the WordPiece vocabulary shipped with the embedding model
    (about 20,000 of its 30,522 entries: "train", "brain", "book", "weather"), which
    ordinary typos ("aple", "tomatos", "whet", "carot") are not. Empty when no such
    vocabulary is installed; typo reading then relies on the edit distance alone.
    """
    from agrirecipe._errors import ConfigurationError
    from agrirecipe.localmodels import default_embedding_model_path

    try:
        path = default_embedding_model_path() / "vocab.txt"
    except ConfigurationError:
        return frozenset()
    if not path.is_file():
        return frozenset()
    words = path.read_text(encoding="utf-8").split()
    return frozenset(w for w in words if len(w) >= 4 and w.isascii() and w.isalpha())


@dataclass(frozen=True, slots=True)
class OtherCrop:
    """A crop people ask for that the hierarchy does not hold."""

    name: str
    category: str
    like: tuple[str, ...]
    #: For a variety the hierarchy does not hold ("Braeburn"), the crop it belongs to.
    variety_of: str | None = None


def other_crops(hierarchy: Hierarchy) -> dict[str, OtherCrop]:
    """``other_crops.yaml`` less the crops and varieties this hierarchy does hold."""
    known = {normalise(name) for name in hierarchy.crops}
    known |= {normalise(alias) for crop in hierarchy.crops.values() for alias in crop.aliases}
    data = load_data("other_crops.yaml")
    result = {}
    for name, entry in data["crops"].items():
        if normalise(name) in known or normalise(name) + "s" in known:
            continue
        like = tuple(crop for crop in entry.get("like", ()) if crop in hierarchy.crops)
        result[name] = OtherCrop(name, str(entry["category"]), like)
    held = {
        normalise(name)
        for crop in hierarchy.crops.values()
        for variety in crop.varieties
        for name in (variety.name, *variety.aliases)
    }
    for crop_name, names in data.get("varieties", {}).items():
        if crop_name not in hierarchy.crops:
            continue
        crop = hierarchy.crops[crop_name]
        for name in names:
            if normalise(name) not in held:
                result[name] = OtherCrop(name, crop.category, (crop_name,), variety_of=crop_name)
    return result
