"""The embedding and hybrid strategies with the real local sentence-transformers model.

The model and the indexes load once for this module (one resolver of each
kind, reused), into a temporary cache folder.
"""

from __future__ import annotations

from collections.abc import Iterator
from pathlib import Path

import pytest

from agrirecipe import UnknownCropError
from agrirecipe.hierarchy import default_hierarchy
from agrirecipe.knowledge import default_knowledge_base
from agrirecipe.resolve import ResolveContext, get_resolver, resolve
from agrirecipe.resolve._embedding import CropIndex, EmbeddingResolver
from agrirecipe.resolve._hybrid import HybridResolver

pytest.importorskip("sentence_transformers")
pytestmark = pytest.mark.slow


@pytest.fixture(scope="module")
def cache(tmp_path_factory: pytest.TempPathFactory) -> Iterator[Path]:
    folder = tmp_path_factory.mktemp("agrirecipe-cache")
    with pytest.MonkeyPatch.context() as patch:
        patch.setenv("AGRIRECIPE_CACHE_DIR", str(folder))
        yield folder


@pytest.fixture(scope="module")
def embedding(cache: Path) -> EmbeddingResolver:
    return EmbeddingResolver()


@pytest.fixture(scope="module")
def hybrid(cache: Path, embedding: EmbeddingResolver) -> HybridResolver:
    return HybridResolver(embedding.embedder)


@pytest.mark.parametrize(
    ("prompt", "expected"),
    [
        ("a healthy Pink Lady apple orchard in summer", [("Apple", "Pink Lady")]),
        ("young nantes carrots in spring", [("Carrot", "Nantes")]),
        ("a field of cherry tomatoes", [("Tomato", "Cherry")]),
        ("winter wheat in spring", [("Wheat", "Winter Wheat")]),
        (
            "Golden Acre cabbage beside Golden Delicious apples",
            [("Cabbage", "Golden Acre"), ("Apple", "Golden Delicious")],
        ),
        ("Riesling grapes, ripe", [("Grape", "Riesling")]),
    ],
)
def test_embedding_strategy_finds_names_by_retrieval(
    embedding: EmbeddingResolver, prompt: str, expected: list[tuple[str, str]]
) -> None:
    recipe = resolve(prompt, resolver=embedding, explain=True).recipe
    assert [(f.crop, f.variety) for f in recipe.fields] == expected
    assert recipe.resolver == "embedding"


def test_embedding_strategy_explains_its_retrieval(embedding: EmbeddingResolver) -> None:
    resolution = resolve("Bintje potatoes flowering", resolver=embedding, explain=True)
    assert resolution.explanation is not None
    text = resolution.explanation.render()
    assert "[retrieve]" in text and "embedding" in text and "Potato/Bintje" in text


def test_the_index_is_cached_on_disk_by_hierarchy_and_model(
    embedding: EmbeddingResolver, cache: Path
) -> None:
    context = ResolveContext(default_hierarchy(), default_knowledge_base())
    embedding.index(context)
    files = sorted((cache / "indexes").glob("crop-names-*.npy"))
    assert len(files) == 1
    name = files[0].name
    assert default_hierarchy().digest() in name and embedding.embedder.model_id in name
    stamp = files[0].stat().st_mtime_ns
    again = CropIndex(default_hierarchy(), default_knowledge_base(), embedding.embedder)
    assert files[0].stat().st_mtime_ns == stamp  # read back, not rebuilt
    assert len(again.names) == len(embedding.index(context).names)


def test_hybrid_needs_no_model_for_known_names(cache: Path) -> None:
    fresh = HybridResolver()
    recipe = resolve("two cherry tomato fields next to a vineyard", resolver=fresh).recipe
    assert len(recipe.fields) == 3
    assert fresh._embedder is None  # the model was never loaded


@pytest.mark.parametrize(
    ("prompt", "requested", "near"),
    [
        ("a field of rutabaga", "rutabaga", "Cabbage"),
        ("a mango plantation", "mango", "Banana"),
        ("a field of barley", "barley", "Wheat"),
    ],
)
def test_hybrid_lists_the_nearest_known_crops_by_meaning(
    hybrid: HybridResolver, prompt: str, requested: str, near: str
) -> None:
    with pytest.raises(UnknownCropError) as caught:
        resolve(prompt, resolver=hybrid)
    assert caught.value.requested == requested
    assert near in caught.value.nearest


@pytest.mark.parametrize(
    "prompt", ["a durian orchard", "a Honeycrisp apple orchard", "a field of zorblax"]
)
def test_hybrid_never_substitutes_an_unknown_crop(hybrid: HybridResolver, prompt: str) -> None:
    with pytest.raises(UnknownCropError):
        resolve(prompt, resolver=hybrid)


def test_hybrid_reads_the_language_like_rules(hybrid: HybridResolver) -> None:
    prompt = "Two orchards: one of Gala, one of Fuji, next to three tomato fields with blight"
    ours = resolve(prompt, resolver=hybrid).recipe
    rules = resolve(prompt, resolver="rules").recipe
    assert [(f.crop, f.variety, f.health) for f in ours.fields] == [
        (f.crop, f.variety, f.health) for f in rules.fields
    ]
    assert ours.resolver == "hybrid"


def test_auto_is_hybrid_when_the_embedding_stack_is_installed() -> None:
    assert get_resolver("auto").name == "hybrid"
    assert get_resolver("auto") is get_resolver("hybrid")  # one instance per process


# Each language feature of issue 3 once more, read with retrieval instead of the lexicon.
_FEATURES = [
    ("an apple orchard next to two carrot fields", ["Apple", "Carrot", "Carrot"], 2),
    ("three tomato fields with blight", ["Tomato"] * 3, 0),
    ("Two orchards: one of Gala, one of Fuji", ["Apple", "Apple"], 0),
    ("a pear orchard and a cherry orchard, all in autumn", ["Pear", "Cherry"], 0),
    ("a 2 ha Granny Smith orchard north of a 50 by 100 m field of Bintje potatoes", None, 1),
    ("a wheat field between an apple orchard and a pear orchard", ["Wheat", "Apple", "Pear"], 1),
    ("Cripps Pink apples, ripe, in October", ["Apple"], 0),
    ("blood oranges in bloom", ["Orange"], 0),
]


@pytest.mark.parametrize(("prompt", "crops", "relations"), _FEATURES)
def test_language_features_with_retrieval(
    embedding: EmbeddingResolver, prompt: str, crops: list[str] | None, relations: int
) -> None:
    ours = resolve(prompt, resolver=embedding).recipe
    rules = resolve(prompt, resolver="rules").recipe
    assert [f.model_dump(exclude={"agronomy"}) for f in ours.fields] == [
        f.model_dump(exclude={"agronomy"}) for f in rules.fields
    ]
    if crops is not None:
        assert [f.crop for f in ours.fields] == crops
    assert len(ours.relations) == relations


@pytest.mark.parametrize("seed", range(3))
def test_generic_requests_with_retrieval(embedding: EmbeddingResolver, seed: int) -> None:
    recipe = resolve("a mixed farm with three different vegetables", resolver=embedding, seed=seed)
    assert len({f.crop for f in recipe.recipe.fields}) == 3
    assert {f.category for f in recipe.recipe.fields} == {"Vegetables"}


@pytest.mark.parametrize(
    "prompt", ["build a parking lot", "", "a healthy diseased orchard", "a mango plantation"]
)
def test_invalid_prompts_with_retrieval(embedding: EmbeddingResolver, prompt: str) -> None:
    from agrirecipe import PromptError

    with pytest.raises(PromptError):
        resolve(prompt, resolver=embedding)
