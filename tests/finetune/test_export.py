"""The llama.cpp LoRA GGUF: written with the gguf package, read back, loaded by llama.cpp."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from agrirecipe import ModelError, generate
from agrirecipe.finetune import FinetunedResolver, export_lora_gguf, read_adapter

gguf = pytest.importorskip("gguf")

RANK = 4
# Hugging Face module -> the GGUF tensor llama.cpp applies it to
MODULES = {
    "self_attn.q_proj": "attn_q",
    "self_attn.k_proj": "attn_k",
    "self_attn.v_proj": "attn_v",
    "self_attn.o_proj": "attn_output",
    "mlp.gate_proj": "ffn_gate",
    "mlp.up_proj": "ffn_up",
    "mlp.down_proj": "ffn_down",
}


def _base_shapes(base: Path) -> tuple[int, dict[str, tuple[int, int]]]:
    """Layers and (in, out) features of every adapted weight of the base GGUF."""
    reader = gguf.GGUFReader(str(base))
    shapes = {
        t.name: (int(t.shape[0]), int(t.shape[1])) for t in reader.tensors if len(t.shape) == 2
    }
    layers = int(reader.fields["gemma3.block_count"].contents())
    return layers, shapes


def _random_adapter(
    base: Path, target: Path, *, scale: float, seed: int = 0
) -> dict[str, tuple[np.ndarray, np.ndarray]]:
    layers, shapes = _base_shapes(base)
    rng = np.random.default_rng(seed)
    weights = {}
    for layer in range(layers):
        for module, name in MODULES.items():
            features_in, features_out = shapes[f"blk.{layer}.{name}.weight"]
            a = rng.normal(0, scale, (RANK, features_in)).astype(np.float32)
            b = rng.normal(0, scale, (features_out, RANK)).astype(np.float32)
            weights[f"model.layers.{layer}.{module}"] = (a, b)
    export_lora_gguf(weights, target, alpha=8, n_layers=layers, record={"smoke": True})
    return weights


def test_round_trip_keeps_type_alpha_names_and_shapes(tmp_path: Path) -> None:
    rng = np.random.default_rng(0)
    weights = {
        "model.layers.0.self_attn.o_proj": (
            rng.random((RANK, 1024), dtype=np.float32),
            rng.random((640, RANK), dtype=np.float32),
        ),
        "model.layers.1.mlp.down_proj": (
            rng.random((RANK, 2048), dtype=np.float32),
            rng.random((640, RANK), dtype=np.float32),
        ),
    }
    path = export_lora_gguf(weights, tmp_path / "a.gguf", alpha=16, n_layers=2, record={"seed": 3})
    info = read_adapter(path)
    assert (info.general_type, info.adapter_type, info.architecture) == (
        "adapter",
        "lora",
        "gemma3",
    )
    assert info.alpha == 16.0
    assert info.record == {"seed": 3}
    assert info.tensors == {
        "blk.0.attn_output.weight.lora_a": (RANK, 1024),
        "blk.0.attn_output.weight.lora_b": (640, RANK),
        "blk.1.ffn_down.weight.lora_a": (RANK, 2048),
        "blk.1.ffn_down.weight.lora_b": (640, RANK),
    }
    reader = gguf.GGUFReader(str(path))
    stored = {t.name: t for t in reader.tensors}
    # ggml lists dimensions innermost first: lora_a is [in, rank], lora_b [rank, out]
    assert stored["blk.0.attn_output.weight.lora_a"].shape.tolist() == [1024, RANK]
    assert stored["blk.0.attn_output.weight.lora_b"].shape.tolist() == [RANK, 640]
    data = np.asarray(stored["blk.1.ffn_down.weight.lora_b"].data).reshape(640, RANK)
    assert np.array_equal(data, weights["model.layers.1.mlp.down_proj"][1])


def test_mismatched_ranks_and_unknown_modules_are_refused(tmp_path: Path) -> None:
    a, b = np.zeros((4, 640), np.float32), np.zeros((1024, 8), np.float32)
    with pytest.raises(ModelError, match="do not share a rank"):
        export_lora_gguf(
            {"model.layers.0.self_attn.q_proj": (a, b)}, tmp_path / "x.gguf", alpha=8, n_layers=1
        )
    with pytest.raises(ModelError, match="no GGUF tensor name"):
        export_lora_gguf(
            {"model.layers.0.mystery": (a, a.T.copy())}, tmp_path / "y.gguf", alpha=8, n_layers=1
        )


def test_the_strategy_is_registered_but_not_auto() -> None:
    from agrirecipe.resolve import available_resolvers, get_resolver, resolve_resolver_name

    assert "finetuned" in available_resolvers()
    resolver = get_resolver("finetuned")
    assert isinstance(resolver, FinetunedResolver) and resolver.name == "finetuned"
    assert resolve_resolver_name("auto") != "finetuned"


def test_without_an_adapter_the_strategy_says_how_to_train_one(
    monkeypatch: pytest.MonkeyPatch, tmp_path: Path
) -> None:
    import agrirecipe._resources

    (tmp_path / "manifest.yaml").write_text("llm: {}\n", encoding="utf-8")
    monkeypatch.delenv("AGRIRECIPE_LORA", raising=False)
    monkeypatch.setattr(agrirecipe._resources, "data_path", lambda name: tmp_path)
    with pytest.raises(ModelError, match="agrirecipe finetune"):
        FinetunedResolver().model  # noqa: B018 - the property loads the adapter


def test_the_shipped_adapter_matches_its_manifest_entry(monkeypatch: pytest.MonkeyPatch) -> None:
    from agrirecipe.finetune import read_adapter
    from agrirecipe.finetune._strategy import default_adapter_path

    monkeypatch.delenv("AGRIRECIPE_LORA", raising=False)
    path = default_adapter_path()  # checks the SHA-256 of models/manifest.yaml
    adapter = read_adapter(path)
    assert (adapter.general_type, adapter.adapter_type, adapter.alpha) == ("adapter", "lora", 16)
    assert len(adapter.tensors) == 252
    record = adapter.record
    assert record["settings"]["train"]["epochs"] == 2
    assert record["steps"] == record["steps_planned"]
    # trained on the local records the finetuned strategy asks, from 700 dev prompts
    assert record["data"]["records"] == "local"
    assert record["data"]["prompts"] == record["settings"]["data"]["max_prompts"] == 700
    assert not any(i.startswith("g57-") for i in record["data"]["heldout_ids"])


def test_a_changed_adapter_file_is_refused(monkeypatch: pytest.MonkeyPatch, tmp_path: Path) -> None:
    import agrirecipe._resources
    from agrirecipe.finetune._strategy import default_adapter_path

    (tmp_path / "manifest.yaml").write_text(
        "finetuned: {file: a.gguf, sha256: '00'}\n", encoding="utf-8"
    )
    (tmp_path / "a.gguf").write_bytes(b"not the adapter")
    monkeypatch.delenv("AGRIRECIPE_LORA", raising=False)
    monkeypatch.setattr(agrirecipe._resources, "data_path", lambda name: tmp_path)
    with pytest.raises(ModelError, match="does not match its SHA-256"):
        default_adapter_path()


@pytest.mark.slow
def test_llama_cpp_applies_the_adapter_over_the_real_base_model(tmp_path: Path) -> None:
    import llama_cpp

    from agrirecipe.localmodels import LlamaCppModel, default_gguf_path
    from agrirecipe.resolve._grammar import choice_grammar

    base = default_gguf_path()
    prompt = "Request: a Gala apple orchard\nCrop:"

    def last_logits(lora: Path | None) -> np.ndarray:
        llama = llama_cpp.Llama(
            model_path=str(base),
            n_ctx=128,
            n_threads=2,
            verbose=False,
            lora_path=str(lora) if lora else None,
        )
        tokens = llama.tokenize(prompt.encode(), add_bos=True, special=False)
        llama.eval(tokens)
        pointer = llama_cpp.llama_get_logits_ith(llama._ctx.ctx, -1)
        logits = np.ctypeslib.as_array(pointer, shape=(llama.n_vocab(),)).copy()
        llama.close()
        return logits

    silent = tmp_path / "silent.gguf"
    weights = _random_adapter(base, silent, scale=0.05)
    export_lora_gguf(
        {name: (a, np.zeros_like(b)) for name, (a, b) in weights.items()},
        silent,
        alpha=8,
        n_layers=len(weights) // len(MODULES),
    )
    loud = tmp_path / "loud.gguf"
    _random_adapter(base, loud, scale=0.05)
    plain = last_logits(None)
    assert np.allclose(last_logits(silent), plain, atol=1e-3)  # B = 0: no change
    assert not np.allclose(last_logits(loud), plain, atol=0.5)  # the adapter is applied

    model = LlamaCppModel(base, lora_path=loud)
    answer = model.complete(prompt, grammar=choice_grammar(["Apple", "Pear"]), max_tokens=6)
    assert answer in {" Apple\n", " Pear\n"}
    assert model.model_id.endswith("+loud.gguf-" + str(loud.stat().st_size))
    model.close()


@pytest.mark.slow
def test_finetuned_strategy_answers_under_the_grammars(tmp_path: Path) -> None:
    from agrirecipe.localmodels import default_gguf_path

    adapter = tmp_path / "smoke.gguf"
    _random_adapter(default_gguf_path(), adapter, scale=0.01)
    resolver = FinetunedResolver(adapter=adapter)
    scene = generate("a healthy Pink Lady apple orchard in summer", resolver=resolver)
    (field,) = scene.recipe.fields
    assert (field.crop, field.variety, field.season, field.health) == (
        "Apple",
        "Pink Lady",
        "Summer",
        "Healthy",
    )
    assert scene.recipe.resolver == "finetuned"
    resolver.model.close()  # type: ignore[attr-defined]


@pytest.mark.slow
def test_the_shipped_adapter_reads_the_paper_prompt(monkeypatch: pytest.MonkeyPatch) -> None:
    """The committed adapter over the real base model, through ``resolver="finetuned"``."""
    monkeypatch.delenv("AGRIRECIPE_LORA", raising=False)
    scene = generate(
        "a healthy Pink Lady apple orchard in summer next to young Nantes carrots",
        resolver="finetuned",
    )
    assert [(f.crop, f.variety, f.health) for f in scene.recipe.fields] == [
        ("Apple", "Pink Lady", "Healthy"),
        ("Carrot", "Nantes", "Healthy"),
    ]
    assert scene.recipe.fields[1].stage == "Vegetative"
    assert scene.recipe.resolver == "finetuned"
