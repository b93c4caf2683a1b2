"""Grammars generated from the hierarchy and the recipe schema: only hierarchy values are reachable.

The structural tests enumerate the language of each generated grammar with a
small GBNF reader (below) and compare it with the hierarchy; the llama.cpp
tests compile every grammar with the real engine and ask it whether strings
are accepted.
"""

from __future__ import annotations

import itertools
import re
from collections.abc import Iterator
from pathlib import Path

import pytest
import yaml

from agrirecipe import HierarchyError
from agrirecipe.hierarchy import Hierarchy, default_hierarchy, load_hierarchy
from agrirecipe.localmodels import LlamaCppModel, default_language_model
from agrirecipe.recipe import SceneRecipe
from agrirecipe.resolve._grammar import (
    ANY_PREFIX,
    NONE,
    OTHER,
    GrammarBuilder,
    HierarchyGrammars,
    choice_grammar,
    gbnf_literal,
    prompt_words,
    schema_enums,
)

# --- a reader for the finite GBNF subset the generator writes ----------------------

_TOKEN = re.compile(r'\s*("(?:[^"\\]|\\.)*"|[a-z][a-z0-9-]*|\{\d+,\d+\}|[()|?*+])')
_UNESCAPE = {"n": "\n", "r": "\r", "t": "\t", "\\": "\\", '"': '"', "[": "[", "]": "]"}


def _unquote(literal: str) -> str:
    body = literal[1:-1]
    out, index = [], 0
    while index < len(body):
        char = body[index]
        if char == "\\":
            nxt = body[index + 1]
            if nxt == "x":
                out.append(chr(int(body[index + 2 : index + 4], 16)))
                index += 4
                continue
            out.append(_UNESCAPE[nxt])
            index += 2
            continue
        out.append(char)
        index += 1
    return "".join(out)


def language(grammar: str, limit: int = 200_000) -> set[str]:
    """Every string ``grammar`` accepts (the grammar must be finite)."""
    rules: dict[str, list[str]] = {}
    for line in grammar.strip().splitlines():
        name, _, body = line.partition(" ::= ")
        tokens = _TOKEN.findall(body)
        assert "".join(tokens).replace(" ", "") == body.replace(" ", ""), f"unread: {body}"
        rules[name.strip()] = tokens
    memo: dict[str, set[str]] = {}

    def rule(name: str, stack: tuple[str, ...]) -> set[str]:
        assert name not in stack, f"recursive rule {name}"
        if name not in memo:
            values, rest = alternatives(rules[name], (*stack, name))
            assert not rest
            memo[name] = values
        return memo[name]

    def alternatives(tokens: list[str], stack: tuple[str, ...]) -> tuple[set[str], list[str]]:
        result, tokens = sequence(tokens, stack)
        while tokens and tokens[0] == "|":
            more, tokens = sequence(tokens[1:], stack)
            result |= more
        return result, tokens

    def sequence(tokens: list[str], stack: tuple[str, ...]) -> tuple[set[str], list[str]]:
        result = {""}
        while tokens and tokens[0] not in ("|", ")"):
            token, tokens = tokens[0], tokens[1:]
            if token.startswith('"'):
                atom = {_unquote(token)}
            elif token == "(":
                atom, tokens = alternatives(tokens, stack)
                assert tokens[0] == ")"
                tokens = tokens[1:]
            else:
                atom = rule(token, stack)
            if tokens and tokens[0] == "?":
                atom, tokens = atom | {""}, tokens[1:]
            elif tokens and tokens[0].startswith("{"):
                low, high = map(int, tokens[0][1:-1].split(","))
                repeated: set[str] = set()
                assert len(atom) ** high <= limit, "language too large to enumerate"
                for count in range(low, high + 1):
                    repeated |= {"".join(p) for p in itertools.product(sorted(atom), repeat=count)}
                atom, tokens = repeated, tokens[1:]
            assert tokens[:1] not in (["*"], ["+"]), "unbounded repetition"
            result = {a + b for a in result for b in atom}
            assert len(result) <= limit
        return result, tokens

    return rule("root", ())


def answers(grammar: str) -> set[str]:
    """A choice grammar's answers without the leading space and the newline."""
    values = language(grammar)
    assert all(v.startswith(" ") and v.endswith("\n") for v in values)
    return {v[1:-1] for v in values}


# --- hierarchies -----------------------------------------------------------------


@pytest.fixture(scope="module")
def mango_hierarchy(tmp_path_factory: pytest.TempPathFactory) -> Hierarchy:
    """The shipped hierarchy plus a crop it does not have: Mango (Alphonso, Kent)."""
    source = Path(default_hierarchy().source)
    data = yaml.safe_load(source.read_text(encoding="utf-8"))
    data["categories"]["Fruits"]["crops"]["Mango"] = {
        "aliases": ["mangoes"],
        "varieties": [{"name": "Alphonso"}, {"name": "Kent"}],
    }
    path = tmp_path_factory.mktemp("hierarchy") / "hierarchy.yaml"
    path.write_text(yaml.safe_dump(data), encoding="utf-8")
    return load_hierarchy(path)


def hierarchy_values(hierarchy: Hierarchy) -> set[str]:
    return (
        set(hierarchy.crops)
        | {ANY_PREFIX + c for c in hierarchy.categories}
        | {v.name for v in hierarchy.varieties}
        | set(hierarchy.stages)
        | set(hierarchy.seasons)
        | set(hierarchy.health)
    )


def all_enum_grammars(grammars: HierarchyGrammars) -> Iterator[str]:
    yield grammars.crop_grammar()
    for crop in grammars.crops:
        yield grammars.variety_grammar(crop)
    for attribute in ("stage", "season", "health"):
        yield grammars.state_grammar(attribute)


# --- structure -------------------------------------------------------------------


@pytest.mark.parametrize("which", ["default", "custom"])
def test_every_enum_answer_is_a_hierarchy_value(which: str, mango_hierarchy: Hierarchy) -> None:
    hierarchy = default_hierarchy() if which == "default" else mango_hierarchy
    grammars = HierarchyGrammars(hierarchy)
    allowed = hierarchy_values(hierarchy) | {NONE, OTHER}
    reached: set[str] = set()
    for grammar in all_enum_grammars(grammars):
        values = answers(grammar)
        assert values <= allowed, values - allowed
        reached |= values
    # ...and every hierarchy value is reachable by some grammar.
    assert reached == allowed


def test_crop_enum_follows_the_hierarchy_object(mango_hierarchy: Hierarchy) -> None:
    default = answers(HierarchyGrammars(default_hierarchy()).crop_grammar())
    custom = answers(HierarchyGrammars(mango_hierarchy).crop_grammar())
    assert "Mango" not in default
    assert custom - default == {"Mango"}
    mango = answers(HierarchyGrammars(mango_hierarchy).variety_grammar("Mango"))
    assert mango == {"Alphonso", "Kent", NONE}


def test_variety_enum_holds_only_that_crop_s_varieties() -> None:
    grammars = HierarchyGrammars(default_hierarchy())
    pear = answers(grammars.variety_grammar("Pear"))
    assert pear == {v.name for v in default_hierarchy().crops["Pear"].varieties} | {NONE}
    assert "Gala" not in pear


def test_narrowed_enums_refuse_names_outside_the_hierarchy() -> None:
    grammars = HierarchyGrammars(default_hierarchy())
    assert answers(grammars.crop_grammar(["Apple", "any Fruits", OTHER])) == {
        "Apple",
        "any Fruits",
        OTHER,
    }
    with pytest.raises(HierarchyError):
        grammars.crop_grammar(["Apple", "Mango"])
    with pytest.raises(ValueError, match="category"):
        grammars.crop_grammar(["any Nuts"])
    with pytest.raises(HierarchyError):
        grammars.variety_grammar("Pear", ["Conference", "Gala"])
    with pytest.raises(ValueError, match="not a stage"):
        grammars.state_grammar("stage", ["Ripe"])
    with pytest.raises(ValueError, match="relation kind"):
        grammars.relations_grammar(2, ["inside_of"])


def test_state_enums_come_from_the_recipe_schema() -> None:
    schema = SceneRecipe.model_json_schema()["$defs"]
    enums = schema_enums()
    assert enums["stage"] == tuple(schema["FieldSpec"]["properties"]["stage"]["enum"])
    assert enums["season"] == tuple(schema["FieldSpec"]["properties"]["season"]["enum"])
    assert enums["health"] == tuple(schema["FieldSpec"]["properties"]["health"]["enum"])
    assert enums["relation"] == tuple(schema["Relation"]["properties"]["kind"]["enum"])
    grammars = HierarchyGrammars(default_hierarchy())
    assert answers(grammars.state_grammar("season")) == {*enums["season"], NONE}


def _runs(count: int) -> set[str]:
    """Every way to pick ordered, non-overlapping runs of ``count`` words (w0, w1, ...)."""
    words = [f"w{i}" for i in range(count)]
    result = set()
    spans = [(a, b) for a in range(count) for b in range(a, count)]
    for size in range(1, count + 1):
        for combo in itertools.combinations(spans, size):
            if all(x[1] < y[0] for x, y in itertools.pairwise(combo)):
                result.add(" | ".join(" ".join(words[a : b + 1]) for a, b in combo))
    return result


def test_decomposition_offers_exactly_the_prompt_s_runs_in_order() -> None:
    grammars = HierarchyGrammars(default_hierarchy())
    words = [f"w{i}" for i in range(4)]
    assert answers(grammars.parts_grammar(words)) == _runs(4) | {NONE}


def test_relations_use_part_numbers_and_schema_kinds() -> None:
    grammars = HierarchyGrammars(default_hierarchy())
    values = answers(grammars.relations_grammar(2))
    assert "1 north of 2" in values and "2 next to 1" in values and NONE in values
    kinds = set(schema_enums()["relation"])
    relations = {r for value in values - {NONE} for r in value.split(", ")}
    for relation in relations:
        first, *kind, second = relation.split(" ")
        assert {first, second} <= {"1", "2"}
        assert "_".join(kind) in kinds
    narrowed = answers(grammars.relations_grammar(2, ["north_of"]))
    assert NONE not in narrowed and "1 north of 2" in narrowed
    assert all("next to" not in v for v in narrowed)


def test_literals_escape_everything_a_prompt_may_hold() -> None:
    text = 'a "quoted" [field] \\ of\tapples\n'
    builder = GrammarBuilder()
    builder.add("root", gbnf_literal(text))
    assert language(builder.render()) == {text}


def test_prompt_words_drop_edge_punctuation_only() -> None:
    assert prompt_words('Gala apples, "Conference" pears (ripe).') == (
        "Gala",
        "apples",
        "Conference",
        "pears",
        "ripe",
    )
    assert prompt_words("a 2.5 ha field") == ("a", "2.5", "ha", "field")


# --- llama.cpp -------------------------------------------------------------------


@pytest.fixture(scope="module")
def model() -> LlamaCppModel:
    return default_language_model()


@pytest.mark.slow
@pytest.mark.parametrize("which", ["default", "custom"])
def test_llama_cpp_compiles_every_generated_grammar(
    which: str, mango_hierarchy: Hierarchy, model: LlamaCppModel
) -> None:
    hierarchy = default_hierarchy() if which == "default" else mango_hierarchy
    grammars = HierarchyGrammars(hierarchy)
    words = prompt_words('a fi"eld of [Gala] apples \\ next to 2.5 ha of pears')
    generated = [
        *all_enum_grammars(grammars),
        grammars.parts_grammar(words),
        grammars.span_grammar(words),
        grammars.relations_grammar(3),
        grammars.relations_grammar(4, ["between", "north_of"]),
        choice_grammar(["50 x 100 m", "2 ha"]),
    ]
    for grammar in generated:
        model.check_grammar(grammar)
    parts = grammars.parts_grammar(words)
    assert model.accepts(parts, ' a fi"eld of [Gala] apples | 2.5 ha of pears\n')
    assert model.accepts(parts, " \\ next to\n")
    assert not model.accepts(parts, " pears | apples\n")  # backwards
    assert not model.accepts(parts, " mango plantation\n")  # not the prompt's words


@pytest.mark.slow
def test_llama_cpp_refuses_values_outside_the_hierarchy(
    mango_hierarchy: Hierarchy, model: LlamaCppModel
) -> None:
    default = HierarchyGrammars(default_hierarchy())
    custom = HierarchyGrammars(mango_hierarchy)
    assert not model.accepts(default.crop_grammar(), " Mango\n")
    assert model.accepts(custom.crop_grammar(), " Mango\n")
    assert model.accepts(default.crop_grammar(), " Apple\n")
    assert not model.accepts(default.crop_grammar(), " apple\n")
    assert not model.accepts(default.variety_grammar("Pear"), " Gala\n")
    assert not model.accepts(default.state_grammar("stage"), " Ripe\n")
    assert not model.accepts(custom.variety_grammar("Mango"), " Haden\n")
