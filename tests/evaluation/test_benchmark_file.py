"""Loading benchmark files: errors name the entry; names are checked against the hierarchy."""

from __future__ import annotations

from pathlib import Path

import pytest

from agrirecipe import AgrirecipeError
from agrirecipe.evaluation import BenchmarkError, load_benchmark, load_knowledge_queries

HEADER = "version: 1\ndefaults: {health: Healthy}\nprompts:\n"


def _write(tmp_path: Path, body: str, header: str = HEADER) -> Path:
    path = tmp_path / "prompts.yaml"
    path.write_text(header + body, encoding="utf-8")
    return path


def test_a_small_valid_file_loads_with_defaults_and_categories(tmp_path: Path) -> None:
    path = _write(
        tmp_path,
        "- id: a-1\n  type: single_generic\n  prompt: an orchard\n"
        "  fields: [{crop: [Apple, Pear]}]\n"
        "- {id: a-2, type: invalid, prompt: '', error: PromptError}\n",
    )
    benchmark = load_benchmark(path)
    assert [p.id for p in benchmark.prompts] == ["a-1", "a-2"]
    truth = benchmark.prompts[0].fields[0]
    assert truth.category == ("Fruits",)
    assert truth.health == ("Healthy",)
    assert truth.inferred == ("health",)
    assert benchmark.prompts[1].invalid


@pytest.mark.parametrize(
    ("body", "message"),
    [
        (
            "- {id: b-1, type: single_detailed, prompt: x, fields: [{crop: Mango}]}\n",
            "'Mango' is not a crop",
        ),
        (
            "- {id: b-1, type: single_detailed, prompt: x, "
            "fields: [{crop: Apple, variety: Cripps Pink}]}\n",
            "not a canonical variety",
        ),
        (
            "- {id: b-1, type: single_detailed, prompt: x, "
            "fields: [{crop: Pear, variety: Gala}]}\n",
            "not a variety of Pear",
        ),
        (
            "- {id: b-1, type: single_detailed, prompt: x, "
            "fields: [{category: Cereals, crop: Apple}]}\n",
            "not in category",
        ),
        (
            "- {id: b-1, type: single_detailed, prompt: x, fields: [{stage: Ripe}]}\n",
            "b-1",
        ),
        ("- {id: b-1, type: invalid, prompt: x}\n", "needs 'error'"),
        (
            "- {id: b-1, type: single_detailed, prompt: x, "
            "fields: [{crop: Apple}, {crop: Pear}]}\n",
            "exactly one field",
        ),
        (
            "- {id: b-1, type: multi_generic, prompt: x, fields: [{crop: Apple}, {crop: Pear}],"
            " relations: [{kind: next_to, subject: a, objects: [b]}]}\n",
            "unknown ref",
        ),
        (
            "- {id: b-1, type: single_generic, prompt: x, fields: [{crop: Apple}]}\n"
            "- {id: b-1, type: single_generic, prompt: y, fields: [{crop: Pear}]}\n",
            "duplicate prompt id",
        ),
        (
            "- {id: g-1, type: single_generic, prompt: x, fields: [{crop: Maize, rows: -4}]}\n",
            r"g-1.*rows: Input should be greater than 0",
        ),
        (
            "- {id: g-1, type: single_generic, prompt: x, fields: [{crop: Maize, rows: 4.5}]}\n",
            r"g-1.*rows",
        ),
        (
            "- {id: g-1, type: single_generic, prompt: x, fields: [{crop: Maize, beds: 0}]}\n",
            r"g-1.*beds",
        ),
        (
            "- {id: g-1, type: single_generic, prompt: x, "
            "fields: [{crop: Maize, row_spacing_m: 0}]}\n",
            r"g-1.*row_spacing_m",
        ),
        (
            "- {id: g-1, type: single_generic, prompt: x, "
            "fields: [{crop: Maize, headland_m: -1}]}\n",
            r"g-1.*headland_m",
        ),
        (
            "- {id: g-1, type: single_generic, prompt: x, "
            "fields: [{crop: Maize, row_bearing_deg: 180}]}\n",
            r"g-1.*row_bearing_deg",
        ),
        (
            "- {id: g-1, type: single_generic, prompt: x, "
            "fields: [{crop: Maize, plant_count: true}]}\n",
            r"g-1.*plant_count",
        ),
        (
            "- {id: g-1, type: single_generic, prompt: x, "
            "fields: [{crop: Strawberry, rows: 10, beds: 4, rows_per_bed: 2}]}\n",
            "rows 10 is not beds 4 x rows_per_bed 2",
        ),
        (
            "- {id: g-1, type: single_generic, prompt: x, "
            "fields: [{crop: Maize, row_count: 10}]}\n",
            r"g-1.*row_count.*Extra inputs",
        ),
        (
            "- {id: g-1, type: single_generic, tags: [genre], prompt: x, "
            "fields: [{crop: Maize}]}\n",
            r"g-1.*tags",
        ),
    ],
)
def test_malformed_entries_raise_a_benchmark_error_naming_them(
    tmp_path: Path, body: str, message: str
) -> None:
    with pytest.raises(BenchmarkError, match=message) as caught:
        load_benchmark(_write(tmp_path, body))
    assert isinstance(caught.value, AgrirecipeError)


def test_missing_and_unparsable_files(tmp_path: Path) -> None:
    with pytest.raises(BenchmarkError, match="does not exist"):
        load_benchmark(tmp_path / "nope.yaml")
    with pytest.raises(BenchmarkError, match="not valid YAML"):
        load_benchmark(_write(tmp_path, "- {id: [unclosed\n"))


def test_select_by_type_tag_id_and_limit_covers_every_type() -> None:
    benchmark = load_benchmark()
    assert {p.type for p in benchmark.select(types=["invalid"]).prompts} == {"invalid"}
    typos = benchmark.select(tags=["typo"])
    assert len(typos) >= 15 and all("typo" in p.tags for p in typos.prompts)
    assert [p.id for p in benchmark.select(ids=["md-005"]).prompts] == ["md-005"]
    small = benchmark.select(limit=5)
    assert len(small) == 5
    assert {p.type for p in small.prompts} == {
        "single_detailed",
        "single_generic",
        "multi_detailed",
        "multi_generic",
        "invalid",
    }
    assert len(benchmark.select(limit=len(benchmark) + 1)) == len(benchmark)
    assert len(benchmark.select(limit=len(benchmark) - 1)) == len(benchmark) - 1


def test_knowledge_query_errors(tmp_path: Path) -> None:
    path = tmp_path / "q.yaml"
    path.write_text(
        "version: 1\nqueries:\n- query: ripe gala\n"
        "  key: {crop: Apple, variety: Gala, stage: Ripe, season: Fall, health: Healthy}\n",
        encoding="utf-8",
    )
    with pytest.raises(BenchmarkError, match="ripe gala"):
        load_knowledge_queries(path)
    path.write_text("version: 1\nqueries:\n- query: x\n", encoding="utf-8")
    with pytest.raises(BenchmarkError, match=r"queries\[0\]"):
        load_knowledge_queries(path)


def test_several_files_load_with_their_split_and_ids_stay_unique(tmp_path: Path) -> None:
    dev = _write(
        tmp_path, "- {id: d-1, type: single_generic, prompt: pears, fields: [{crop: Pear}]}\n"
    )
    heldout = tmp_path / "heldout.yaml"
    heldout.write_text(
        "version: 1\nsplit: heldout\nprompts:\n"
        "- {id: h-1, type: single_generic, prompt: apples, fields: [{crop: Apple}]}\n",
        encoding="utf-8",
    )
    benchmark = load_benchmark([dev, heldout])
    assert [(p.id, p.split) for p in benchmark.prompts] == [("d-1", "dev"), ("h-1", "heldout")]
    assert [p.id for p in benchmark.select(splits=["heldout"]).prompts] == ["h-1"]
    heldout.write_text(
        "version: 1\nsplit: heldout\nprompts:\n"
        "- {id: d-1, type: single_generic, prompt: apples, fields: [{crop: Apple}]}\n",
        encoding="utf-8",
    )
    with pytest.raises(BenchmarkError, match=r"duplicate prompt id 'd-1'.*also in"):
        load_benchmark([dev, heldout])


def test_round_robin_takes_each_group_in_turn() -> None:
    from agrirecipe.evaluation import round_robin

    items = ["a1", "a2", "a3", "b1", "c1", "c2"]
    assert round_robin(items, lambda s: s[0], 4) == ["a1", "b1", "c1", "a2"]
    assert round_robin(items, lambda s: s[0], 100) == ["a1", "b1", "c1", "a2", "c2", "a3"]
    assert round_robin([], lambda s: s, 3) == []


GEOMETRY_FILE = """\
- id: eng-1
  type: single_generic
  tags: [engineering, geometry, scenery]
  prompt: 10 rows of maize, 80 m long, 30-inch rows running east-west, 5 m headland
  fields:
  - crop: Maize
    rows: 10
    beds: 10
    rows_per_bed: 1
    row_length_m: 80
    row_spacing_m: 0.762
    in_row_spacing_m: 0.2
    plants_per_ha: 65000
    plant_count: 4000
    headland_m: 5
    row_bearing_deg: 90
- id: eng-2
  type: single_generic
  tags: [photo, cue, casual, farm]
  prompt: strawberries on beds 1.5 m apart, two rows per bed
  fields: [{crop: Strawberry, bed_width_m: 1.5, rows_per_bed: 2, headland_m: 0}]
"""


def test_a_file_with_the_stated_geometry_keys_and_genre_tags_loads(tmp_path: Path) -> None:
    from agrirecipe.evaluation import GEOMETRY_KEYS

    benchmark = load_benchmark(_write(tmp_path, GEOMETRY_FILE))
    maize = benchmark.prompts[0].fields[0]
    assert benchmark.prompts[0].tags == ("engineering", "geometry", "scenery")
    assert benchmark.prompts[1].tags == ("photo", "cue", "casual", "farm")
    assert (maize.rows, maize.beds, maize.rows_per_bed, maize.plant_count) == (10, 10, 1, 4000)
    assert maize.row_spacing_m == pytest.approx(0.762)
    assert maize.row_bearing_deg == 90.0
    assert maize.health == ("Healthy",)  # the defaults still apply
    assert set(maize.geometry()) == set(GEOMETRY_KEYS) - {"bed_width_m"}
    assert maize.describe() == (
        "Maize, Healthy, 10 rows, 10 beds, 1 per bed, rows 80 m, 0.762 m apart, "
        "a plant every 0.2 m, 65000 plants/ha, 4000 plants, 5 m headland, rows at 90 deg"
    )
    beds = benchmark.prompts[1].fields[0]
    assert beds.geometry() == {"rows_per_bed": 2, "bed_width_m": 1.5, "headland_m": 0.0}
    assert beds.describe() == "Strawberry, Healthy, 2 per bed, beds on 1.5 m, 0 m headland"
    assert benchmark.select(tags=["photo"]).prompts == (benchmark.prompts[1],)
    plain = load_benchmark(
        _write(tmp_path, "- {id: p-1, type: single_generic, prompt: x, fields: [{crop: Pear}]}\n")
    )
    assert plain.prompts[0].fields[0].geometry() == {}


def test_new_tags_follow_the_existing_ones_in_order() -> None:
    from agrirecipe.evaluation import GENRE_TAGS, TAGS

    assert TAGS == (
        "paper",
        "paraphrase",
        "alias",
        "typo",
        "ambiguous",
        "size_relation",
        "month_season",
        "implausible",
        "photo",
        "engineering",
        "casual",
        "farm",
        "geometry",
        "scenery",
        "cue",
    )
    assert GENRE_TAGS == ("photo", "engineering", "casual", "farm")


def _prompt_file(path: Path, ident: str, crop: str, split: str = "heldout") -> Path:
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(
        f"version: 1\nsplit: {split}\nprompts:\n"
        f"- {{id: {ident}, type: single_generic, prompt: {ident}, fields: [{{crop: {crop}}}]}}\n",
        encoding="utf-8",
    )
    return path


def test_shipped_files_are_the_two_files_then_every_heldout_set_sorted(tmp_path: Path) -> None:
    from agrirecipe.evaluation import SHIPPED_PROMPT_FILES, shipped_prompt_files

    assert SHIPPED_PROMPT_FILES == ("prompts.yaml", "prompts_heldout.yaml", "heldout/*.yaml")
    assert shipped_prompt_files(tmp_path) == ()
    dev = _prompt_file(tmp_path / "prompts.yaml", "d-1", "Pear", split="dev")
    assert shipped_prompt_files(tmp_path) == (dev,)
    late = _prompt_file(tmp_path / "heldout" / "h.yaml", "h-photo-01", "Apple")
    early = _prompt_file(tmp_path / "heldout" / "g.yaml", "g-farm-01", "Cherry")
    (tmp_path / "heldout" / "notes.md").write_text("not a prompt file", encoding="utf-8")
    (tmp_path / "heldout" / "old.yaml.bak").write_text("", encoding="utf-8")
    assert shipped_prompt_files(tmp_path) == (dev, early, late)
    heldout = _prompt_file(tmp_path / "prompts_heldout.yaml", "f-1", "Grape")
    files = shipped_prompt_files(tmp_path)
    assert files == (dev, heldout, early, late)
    benchmark = load_benchmark(files)
    assert [(p.id, p.split) for p in benchmark.prompts] == [
        ("d-1", "dev"),
        ("f-1", "heldout"),
        ("g-farm-01", "heldout"),
        ("h-photo-01", "heldout"),
    ]
    # Ids stay unique across every file, the genre sets included.
    _prompt_file(late, "g-farm-01", "Apple")
    with pytest.raises(BenchmarkError, match=r"duplicate prompt id 'g-farm-01'.*h\.yaml.*g\.yaml"):
        load_benchmark(shipped_prompt_files(tmp_path))


def test_the_default_benchmark_loads_exactly_the_shipped_files() -> None:
    from agrirecipe.evaluation import shipped_prompt_files

    files = shipped_prompt_files()
    assert files[0].name == "prompts.yaml"
    assert load_benchmark().source == ", ".join(str(f) for f in files)
