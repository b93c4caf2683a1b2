"""Building the lexicon: the vocabulary files' phrases, then the hierarchy's crop,
variety and category names and aliases (with their plurals and colour forms), plot
nouns with the crops they hold, and the knowledge base's disease names.

:func:`build_lexicon` is cached per hierarchy and knowledge base.
"""

from __future__ import annotations

import functools
import re
from collections.abc import Callable
from typing import TYPE_CHECKING, Any

from agrirecipe.resolve._lexicon import (
    Lexicon,
    Sense,
    SenseKind,
    load_data,
    normalise,
    other_crops,
    plurals,
    vocabulary,
)

if TYPE_CHECKING:
    from agrirecipe.hierarchy import Hierarchy
    from agrirecipe.knowledge import KnowledgeBase

__all__ = ["build_lexicon"]

#: The nouns a scenery tree's name may stand before ("cypress trees", "a willow tree").
_TREE_NOUNS = ("tree", "trees", "hedge", "hedges", "hedgerow", "windbreak")

# vocabulary.yaml sections: lists of phrases with one sense each...
_PLAIN_LISTS: dict[str, SenseKind] = {
    "filler": "filler",
    "filler_phrases": "filler",
    "common_words": "filler",
    "negations": "negation",
    "dimension_joiners": "dimension_joiner",
    "conjunctions": "conjunction",
    "separators": "separator",
    "corrections": "correction",
    "all_words": "all",
    "distinct_words": "distinct",
    "other_words": "other",
    "of_words": "of",
    "same_size_words": "same_size",
    "same_spacing_words": "same_spacing",
}
# ...phrase -> value mappings...
_VALUED_PHRASES: dict[str, tuple[SenseKind, Callable[[Any], Any]]] = {
    "numbers": ("number", int),
    "quantities": ("quantity", int),
    "fractions": ("fraction", float),
    "area_units": ("area_unit", float),
    "length_units": ("length_unit", float),
    "references": ("reference", str),
}
# ...and value -> phrases groups (a stage and the words for it).
_GROUPED_PHRASES: dict[str, SenseKind] = {
    "stages": "stage",
    "health": "health",
    "side_words": "side",
    "relations": "relation",
    "relation_trailers": "relation_trailer",
}


def build_lexicon(
    hierarchy: Hierarchy,
    knowledge: KnowledgeBase,
    *,
    crop_names: bool = True,
) -> Lexicon:
    """The lexicon for a hierarchy and knowledge base (cached per pair).

    With ``crop_names=False`` the hierarchy's crop and variety names are left
    out, for strategies that map those by other means (embedding retrieval).
    """
    return _build_lexicon(hierarchy, knowledge, crop_names)


@functools.lru_cache(maxsize=8)
def _build_lexicon(hierarchy: Hierarchy, knowledge: KnowledgeBase, crop_names: bool) -> Lexicon:
    vocab = vocabulary()
    lexicon = Lexicon()
    add = lexicon.add
    weak_words = {normalise(w) for w in vocab["weak_variety_words"]}
    strong_plurals = {normalise(w) for w in vocab["strong_variety_plurals"]}

    # Vocabulary first, hierarchy names after: both senses are kept for a shared phrase.
    for key, kind in _PLAIN_LISTS.items():
        for phrase in vocab[key]:
            add(str(phrase), Sense(kind))
    for key, (kind, convert) in _VALUED_PHRASES.items():
        for phrase, value in vocab[key].items():
            add(str(phrase), Sense(kind, convert(value)))
    for key, kind in _GROUPED_PHRASES.items():
        for value, phrases in vocab[key].items():
            for phrase in phrases:
                add(phrase, Sense(kind, value))
    modifiers = vocab["season_modifiers"]
    weak_months = {normalise(m) for m in vocab["weak_months"]}
    for key, kind, convert in (("seasons", "season", str), ("months", "month", int)):
        for value, phrases in vocab[key].items():
            for phrase in phrases:
                weak = normalise(phrase) in weak_months if kind == "month" else False
                add(phrase, Sense(kind, convert(value), weak=weak))
                for modifier in modifiers:  # "late summer", "early June"
                    add(f"{modifier} {phrase}", Sense(kind, convert(value)))
    from agrirecipe.resolve._cues import add_cues  # the cue table reads the lexicon's words

    add_cues(lexicon)
    for group, phrases in load_data("scenery.yaml").items():
        if group != "version":
            for phrase in phrases:
                add(str(phrase), Sense("scenery", group))
                if group == "trees" and str(phrase).split()[-1] not in _TREE_NOUNS:
                    # "cypress trees on the ridge", "a line of poplar trees": still scenery
                    for noun in _TREE_NOUNS:
                        add(f"{phrase} {noun}", Sense("scenery", group))
    for crop in hierarchy.crops.values():
        disease = knowledge.crop_file(crop.name).disease.name
        for name in _disease_names(disease):
            add(name, Sense("health", "Ill"))
    for phrase, spec in vocab["plot_nouns"].items():
        add(phrase, Sense("plot", _plot_spec(phrase, spec or {}, hierarchy, knowledge)))
    for phrase in vocab["containers"]["words"]:
        add(phrase, Sense("container"))
    for phrase in vocab["non_agricultural"]:
        add(phrase, Sense("non_agricultural", phrase))
    places = load_data("places.yaml")
    for hemisphere, spec in places["hemispheres"].items():
        for phrase in spec["phrases"]:
            add(phrase, Sense("hemisphere", (hemisphere, float(spec["latitude_deg"]))))
    for phrase, latitude in places["places"].items():
        add(phrase, Sense("place", (phrase, float(latitude))))
    for name, other in other_crops(hierarchy).items():
        lexicon.add_with_plurals(name, Sense("other_crop", other))

    for category in hierarchy.categories.values():
        for phrase in (category.name, *category.aliases):
            lexicon.add_with_plurals(phrase, Sense("category", category.name))
    if crop_names:
        for crop in hierarchy.crops.values():
            for phrase in (crop.name, *crop.aliases):
                lexicon.add_with_plurals(phrase, Sense("crop", crop.name))
            for variety in crop.varieties:
                for phrase in (variety.name, *variety.aliases):
                    weak = normalise(phrase) in weak_words
                    sense = Sense("variety", variety.name, crop=crop.name, weak=weak)
                    if weak and normalise(phrase) in strong_plurals:
                        lexicon.add(phrase, sense)
                        for plural in plurals(normalise(phrase)):
                            lexicon.add(
                                plural,
                                Sense("variety", variety.name, crop=crop.name),
                                derived=True,
                            )
                    else:
                        lexicon.add_with_plurals(phrase, sense)
                # "Nantes carrots": the variety followed by its crop's name.
            _add_colour_varieties(lexicon, crop, vocab)
    lexicon.prepare_fuzzy(
        ("crop", "variety", "category", "plot", "stage", "season", "month", "health", "relation")
    )
    return lexicon


def _add_colour_varieties(lexicon: Lexicon, crop: Any, vocab: dict[str, Any]) -> None:
    """ "red onions" -> the onion variety named red ("Red Baron"), from the hierarchy's names.

    A colour names a variety only when exactly one variety of the crop has a word for
    that colour in its name or aliases; a phrase the lexicon already knows is kept.
    """
    for colour, name_words in vocab["variety_colours"].items():
        said = {normalise(str(w)) for w in name_words}
        matches = [
            variety
            for variety in crop.varieties
            if any(
                said & set(normalise(phrase).split()) for phrase in (variety.name, *variety.aliases)
            )
        ]
        if len(matches) != 1:
            continue
        sense = Sense("variety", matches[0].name, crop=crop.name)
        for adjective in vocab["colour_words"].get(colour, ()):
            for phrase in (crop.name, *crop.aliases):
                for form in (normalise(phrase), *plurals(normalise(phrase))):
                    text = f"{normalise(str(adjective))} {form}"
                    if not lexicon.lookup(text.split()):
                        lexicon.add(text, sense)


def _singular(word: str) -> str:
    if word.endswith(("ches", "shes")):
        return word[:-2]
    if word.endswith("s") and not word.endswith("ss"):
        return word[:-1]
    return word


def _disease_names(disease: str) -> list[str]:
    """``"citrus greening (HLB)"`` -> ``["citrus greening (hlb)", "citrus greening", "hlb"]``."""
    names = [disease]
    inner = re.findall(r"\(([^)]*)\)", disease)
    outer = re.sub(r"\([^)]*\)", "", disease).strip()
    names += [outer, *inner]
    return [name for name in names if name]


def _plot_spec(
    phrase: str, spec: dict[str, Any], hierarchy: Hierarchy, knowledge: KnowledgeBase
) -> dict[str, Any]:
    """A plot noun's meaning: its label noun, plurality and the crops it allows."""
    options: list[str] = [c for c in spec.get("crops", ()) if c in hierarchy.crops]
    forms = set(spec.get("growth_forms", ()))
    if forms:
        excluded = set(spec.get("exclude", ()))
        options += [
            crop
            for crop in hierarchy.crops
            if crop not in excluded
            and crop not in options
            and knowledge.crop_file(crop).growth_form in forms
        ]
    # Crops the noun's growth forms leave out but usage still puts there ("a banana orchard").
    tolerates = [c for c in spec.get("exclude", ()) if c in hierarchy.crops]
    category = spec.get("category")
    if category is not None and category not in hierarchy.categories:
        category = None
    return {
        # "tomato plants" names plants, not the plot: the field is named after its crop.
        "noun": spec.get("noun")
        or (None if spec.get("individual") else _singular(phrase.split()[-1])),
        "plural": bool(spec.get("plural", False)),
        "individual": bool(spec.get("individual", False)),
        # "strawberry beds": the plural names one field's beds unless counted
        "one_field": bool(spec.get("one_field", False)),
        "options": tuple(options),
        "tolerates": tuple(tolerates),
        "category": category,
        # ("vegetable garden": a plot whose name says its category holds no other crop)
        "strict": bool(spec.get("strict", False)) and category is not None,
        "narrows": bool(options) or category is not None,
    }
