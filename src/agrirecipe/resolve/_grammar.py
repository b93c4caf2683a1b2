"""GBNF grammars generated from the recipe schema and the crop hierarchy.

The llm strategy never lets the model write free text: every answer is
generated under one of these grammars, so an unknown crop, a variety of the
wrong crop or an invented asset cannot be emitted.

- the *values* come from the hierarchy object passed in (a custom hierarchy
  with an extra crop gets that crop) and from the recipe JSON schema's enums
  (stages, seasons, health states, relation kinds), intersected so that only
  values both accept are offered;
- *candidate lists* are narrowed per field by retrieval (:class:`FieldCandidates`):
  the crops and varieties the field's words point at, not all 66 varieties;
- *decomposition* is constrained to the prompt's own words: a part is a run of
  consecutive prompt words, parts come in prompt order and never overlap.

The answers use a line-per-attribute record (``Crop: Apple``) rather than
JSON. ``llama_cpp.llama_grammar.json_schema_to_gbnf`` could derive a JSON
grammar from the schema, but a JSON object costs the 270M model two to three
times the tokens (keys, quotes, braces) and a base model copies the line format
from few-shot examples far more reliably; the line grammar carries the same
enums and the same crop -> variety dependency.

A grammar is plain GBNF text (``root`` first), accepted by
``llama_cpp.LlamaGrammar.from_string`` and :meth:`LlamaCppModel.complete`.
"""

from __future__ import annotations

import re
from collections.abc import Iterable, Sequence
from functools import cached_property
from typing import TYPE_CHECKING, Any

if TYPE_CHECKING:
    from agrirecipe.hierarchy import Hierarchy

__all__ = [
    "ANY_PREFIX",
    "NONE",
    "OTHER",
    "GrammarBuilder",
    "HierarchyGrammars",
    "choice_grammar",
    "gbnf_literal",
    "prompt_words",
    "schema_enums",
]

#: Answer meaning "the prompt does not say".
NONE = "none"
#: Crop answer meaning "a plant that is not in the hierarchy".
OTHER = "other"
#: Prefix of a generic crop answer: ``"any Fruits"`` = some crop of that category.
ANY_PREFIX = "any "

_ESCAPES = {"\\": "\\\\", '"': '\\"', "\n": "\\n", "\r": "\\r", "\t": "\\t", "[": "\\[", "]": "\\]"}
_WORD_STRIP = ".,;:!?()\"'"


def gbnf_literal(text: str) -> str:
    """``text`` as a GBNF string literal (quotes, backslashes and control characters escaped)."""
    out = []
    for char in text:
        if char in _ESCAPES:
            out.append(_ESCAPES[char])
        elif ord(char) < 0x20 or ord(char) == 0x7F:
            out.append(f"\\x{ord(char):02X}")
        else:
            out.append(char)
    return '"' + "".join(out) + '"'


def _alternatives(options: Iterable[str]) -> str:
    unique = list(dict.fromkeys(options))
    if not unique:
        raise ValueError("a choice needs at least one option")
    return "(" + " | ".join(gbnf_literal(option) for option in unique) + ")"


class GrammarBuilder:
    """Collects named GBNF rules and renders them with ``root`` first."""

    def __init__(self) -> None:
        self._rules: dict[str, str] = {}

    def add(self, name: str, body: str) -> str:
        """Define rule ``name`` (letters, digits, dashes) and return its name."""
        if not re.fullmatch(r"[a-z][a-z0-9-]*", name):
            raise ValueError(f"invalid GBNF rule name {name!r}")
        if name in self._rules and self._rules[name] != body:
            raise ValueError(f"rule {name!r} defined twice")
        self._rules[name] = body
        return name

    def enum(self, name: str, options: Iterable[str]) -> str:
        """Define ``name ::= "a" | "b" | ...`` and return its name."""
        return self.add(name, _alternatives(options))

    def render(self) -> str:
        """The grammar text."""
        if "root" not in self._rules:
            raise ValueError("a grammar needs a root rule")
        order = ["root", *(name for name in self._rules if name != "root")]
        return "".join(f"{name} ::= {self._rules[name]}\n" for name in order)


def choice_grammar(options: Sequence[str], *, prefix: str = " ", suffix: str = "\n") -> str:
    """A grammar accepting exactly ``prefix + option + suffix`` for one of ``options``."""
    builder = GrammarBuilder()
    builder.enum("choice", options)
    builder.add("root", f"{gbnf_literal(prefix)} choice {gbnf_literal(suffix)}")
    return builder.render()


def prompt_words(text: str) -> tuple[str, ...]:
    """The prompt's words as the decomposition grammar offers them (edge punctuation removed)."""
    words = (word.strip(_WORD_STRIP) for word in text.split())
    return tuple(word for word in words if word)


def schema_enums() -> dict[str, tuple[str, ...]]:
    """The recipe JSON schema's enums: ``stage``, ``season``, ``health`` and ``relation``."""
    from agrirecipe.recipe import SceneRecipe

    schema: dict[str, Any] = SceneRecipe.model_json_schema()
    definitions = schema["$defs"]
    field_properties = definitions["FieldSpec"]["properties"]
    return {
        "stage": tuple(field_properties["stage"]["enum"]),
        "season": tuple(field_properties["season"]["enum"]),
        "health": tuple(field_properties["health"]["enum"]),
        "relation": tuple(definitions["Relation"]["properties"]["kind"]["enum"]),
    }


class HierarchyGrammars:
    """The grammars of the llm strategy for one hierarchy.

    Values come from ``hierarchy`` and the recipe schema; nothing about crops
    is hard-coded, so a custom hierarchy gets grammars over its own names.
    Every method checks the options it is given against the hierarchy, so a
    caller cannot smuggle an unknown name into a grammar either.
    """

    def __init__(self, hierarchy: Hierarchy) -> None:
        self.hierarchy = hierarchy
        enums = schema_enums()
        # A value must be accepted by both the schema and the hierarchy file.
        self.stages = tuple(v for v in enums["stage"] if v in hierarchy.stages)
        self.seasons = tuple(v for v in enums["season"] if v in hierarchy.seasons)
        self.health = tuple(v for v in enums["health"] if v in hierarchy.health)
        self.relation_kinds = enums["relation"]

    @cached_property
    def crops(self) -> tuple[str, ...]:
        """Every crop of the hierarchy."""
        return tuple(self.hierarchy.crops)

    @cached_property
    def categories(self) -> tuple[str, ...]:
        """Every category of the hierarchy."""
        return tuple(self.hierarchy.categories)

    def values(self, attribute: str) -> tuple[str, ...]:
        """The canonical values of ``"stage"``, ``"season"`` or ``"health"``."""
        table = {"stage": self.stages, "season": self.seasons, "health": self.health}
        try:
            return table[attribute]
        except KeyError:
            raise ValueError(
                f"unknown attribute {attribute!r}; expected one of {list(table)}"
            ) from None

    def crop_options(self) -> tuple[str, ...]:
        """Every answer of a ``Crop:`` line: crops, ``any <Category>`` and ``other``."""
        return (*self.crops, *(ANY_PREFIX + c for c in self.categories), OTHER)

    # --- grammars ---

    def crop_grammar(self, options: Sequence[str] | None = None) -> str:
        """`` <crop>\\n`` for one of ``options`` (default: every crop, category and "other").

        An option that is not a crop, ``any <Category>`` or ``other`` is refused
        (:class:`~agrirecipe.HierarchyError` / ``ValueError``).
        """
        chosen = tuple(options) if options is not None else self.crop_options()
        for option in chosen:
            if option == OTHER:
                continue
            if option.startswith(ANY_PREFIX):
                if option[len(ANY_PREFIX) :] not in self.hierarchy.categories:
                    raise ValueError(f"{option!r}: not a category of the hierarchy")
                continue
            self.hierarchy.crop(option)
        return choice_grammar(chosen)

    def variety_grammar(self, crop: str, options: Sequence[str] | None = None) -> str:
        """`` <variety>\\n`` for one of ``crop``'s varieties (default: all of them, and none)."""
        known = self.hierarchy.crop(crop)
        if options is None:
            options = (*(v.name for v in known.varieties), NONE)
        for option in options:
            if option != NONE:
                known.variety(option)
        return choice_grammar(options)

    def state_grammar(self, attribute: str, options: Sequence[str] | None = None) -> str:
        """`` <value>\\n`` for a stage, season or health value (default: all of them, and none)."""
        allowed = self.values(attribute)
        if options is None:
            options = (*allowed, NONE)
        for option in options:
            if option != NONE and option not in allowed:
                raise ValueError(f"{option!r} is not a {attribute}; accepted: {', '.join(allowed)}")
        return choice_grammar(options)

    def parts_grammar(self, words: Sequence[str]) -> str:
        """`` part | part | ...\\n`` or `` none\\n``: runs of consecutive ``words``, in order.

        Parts never overlap and never go backwards, so the answer always
        ends and always segments the prompt.
        """
        if not words:
            return choice_grammar((NONE,))
        builder = GrammarBuilder()
        count = len(words)
        for index, word in enumerate(words):
            # s-i: a part that includes word i and continues or ends there;
            # a-i: after a part ending at word i, stop or start a later part;
            # n-i: the next part starts at word i or later.
            if index + 1 < count:
                builder.add(f"s-{index}", f'{gbnf_literal(word)} (" " s-{index + 1} | a-{index})')
                builder.add(f"a-{index}", f'("" | " | " n-{index + 1})')
                builder.add(f"n-{index}", f"(s-{index} | n-{index + 1})")
            else:
                builder.add(f"s-{index}", gbnf_literal(word))
                builder.add(f"n-{index}", f"s-{index}")
        builder.add("root", '" " (n-0 | "none") "\\n"')
        return builder.render()

    def span_grammar(self, words: Sequence[str]) -> str:
        """`` <one run of consecutive words>\\n`` (the words naming an unknown plant)."""
        if not words:
            raise ValueError("a span needs words")
        builder = GrammarBuilder()
        count = len(words)
        for index, word in enumerate(words):
            tail = f' (" " w-{index + 1})?' if index + 1 < count else ""
            builder.add(f"w-{index}", f"{gbnf_literal(word)}{tail}")
        builder.add("span", "(" + " | ".join(f"w-{index}" for index in range(count)) + ")")
        builder.add("root", '" " span "\\n"')
        return builder.render()

    def relations_grammar(self, parts: int, kinds: Sequence[str] | None = None) -> str:
        """`` 1 next to 2, 3 between 1 and 2\\n`` over part numbers and relation kinds, or none.

        ``kinds`` narrows the schema's relation kinds (e.g. to those the prompt's
        words name); then "none" is not offered.
        """
        if parts < 2:
            return choice_grammar((NONE,))
        chosen = tuple(kinds) if kinds is not None else self.relation_kinds
        for kind in chosen:
            if kind not in self.relation_kinds:
                raise ValueError(f"{kind!r} is not a relation kind of the recipe schema")
        builder = GrammarBuilder()
        builder.enum("part", (str(number) for number in range(1, min(parts, 9) + 1)))
        alternatives = []
        pairwise = [kind.replace("_", " ") for kind in chosen if kind != "between"]
        if pairwise:
            builder.enum("kind", pairwise)
            alternatives.append('part " " kind " " part')
        if "between" in chosen and parts >= 3:
            alternatives.append('part " between " part " and " part')
        if not alternatives:
            return choice_grammar((NONE,))
        builder.add("relation", "(" + " | ".join(alternatives) + ")")
        most = min(parts * 2, 9)  # bounded, so an answer always ends
        repeat = f'relation (", " relation){{0,{most - 1}}}'
        body = f'({repeat} | "none")' if kinds is None else repeat
        builder.add("root", f'" " {body} "\\n"')
        return builder.render()
