"""One real training step of Gemma 3 270M through the CLI, then the adapter in llama.cpp."""

from __future__ import annotations

from pathlib import Path

import pytest

from agrirecipe import generate
from agrirecipe.cli import main
from agrirecipe.finetune import FinetunedResolver, read_adapter

pytest.importorskip("peft")
pytest.importorskip("gguf")

pytestmark = pytest.mark.slow

SETTINGS = """\
version: 1
seed: 0
data: {heldout_fraction: 0.01, max_tokens: 128}
lora: {rank: 8, alpha: 16, dropout: 0.0}
train: {epochs: 1, batch_size: 2, learning_rate: 1.0e-4, warmup_steps: 0, checkpoint_every: 1}
"""


def test_one_cli_step_gives_an_adapter_llama_cpp_runs(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    settings = tmp_path / "settings.yaml"
    settings.write_text(SETTINGS, encoding="utf-8")
    run = tmp_path / "run"
    arguments = ["finetune", "-o", str(run), "--max-steps", "1", "--settings", str(settings)]
    code = main([*arguments, "--no-progress", "--threads", "2"])
    assert code == 0
    assert "adapter:" in capsys.readouterr().out

    adapter = read_adapter(run / "adapter.gguf")
    assert (adapter.general_type, adapter.adapter_type, adapter.alpha) == ("adapter", "lora", 16.0)
    assert len(adapter.tensors) == 18 * 7 * 2  # every projection of every layer, A and B
    assert adapter.tensors["blk.0.attn_q.weight.lora_a"] == (8, 640)
    assert adapter.tensors["blk.0.attn_q.weight.lora_b"] == (1024, 8)
    assert adapter.tensors["blk.17.ffn_down.weight.lora_a"] == (8, 2048)
    assert adapter.tensors["blk.17.ffn_down.weight.lora_b"] == (640, 8)
    record = adapter.record
    assert record["steps"] == 1 and record["base_sha256"]
    assert record["heldout_at_stop"]["loss"] > 0
    assert (run / "checkpoint.pt").is_file() and (run / "training.json").is_file()

    resolver = FinetunedResolver(adapter=run / "adapter.gguf")
    scene = generate("Bing cherries ready for harvest in summer", resolver=resolver)
    (field,) = scene.recipe.fields
    assert (field.crop, field.variety, field.stage, field.season) == (
        "Cherry",
        "Bing",
        "Maturation",
        "Summer",
    )
    assert scene.recipe.resolver == "finetuned"
    resolver.model.close()  # type: ignore[attr-defined]
