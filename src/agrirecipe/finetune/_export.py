"""Write a LoRA adapter as a llama.cpp LoRA GGUF (with the ``gguf`` package), and read one back.

The format llama.cpp's adapter loader (``llama-adapter.cpp``) checks:

- ``general.type = "adapter"``, ``general.architecture`` equal to the base
  model's (``gemma3``), ``adapter.type = "lora"``, ``adapter.lora.alpha`` (f32;
  the applied scale is alpha / rank);
- for each adapted weight, two tensors named after the *base GGUF tensor*
  (``blk.0.attn_q.weight``) plus ``.lora_a`` / ``.lora_b``, with ggml shapes
  ``lora_a: [in, rank]`` and ``lora_b: [rank, out]``. ggml lists dimensions
  innermost first, the reverse of numpy, so the arrays are written in PEFT's
  own layout: ``lora_A.weight`` is ``(rank, in)``, ``lora_B.weight`` is
  ``(out, rank)``; no transposition.

Hugging Face module names are mapped to GGUF tensor names with the ``gguf``
package's own table (``gguf.get_tensor_name_map``); Gemma 3's projections are
stored unpermuted, so no row reordering is needed either.
"""

from __future__ import annotations

import json
from collections.abc import Mapping
from dataclasses import dataclass
from pathlib import Path
from typing import TYPE_CHECKING, Any

from agrirecipe._errors import ModelError

if TYPE_CHECKING:
    import numpy as np
    from numpy.typing import NDArray

__all__ = ["AdapterInfo", "export_lora_gguf", "lora_weights", "read_adapter"]

RECORD_KEY = "agrirecipe.finetune.record"
_PEFT_PREFIX = "base_model.model."


@dataclass(frozen=True, slots=True)
class AdapterInfo:
    """What a LoRA GGUF holds: type, architecture, alpha, tensor shapes, the training record."""

    general_type: str
    adapter_type: str
    architecture: str
    alpha: float
    tensors: dict[str, tuple[int, ...]]  # name -> numpy shape
    record: dict[str, Any]


def lora_weights(model: Any) -> dict[str, tuple[NDArray[np.float32], NDArray[np.float32]]]:
    """The adapter's (A, B) matrices by Hugging Face module name, from a PEFT model."""
    weights = {}
    for name, module in model.named_modules():
        lora_a = getattr(module, "lora_A", None)
        lora_b = getattr(module, "lora_B", None)
        if lora_a is None or lora_b is None or "default" not in lora_a:
            continue
        base = name.removeprefix(_PEFT_PREFIX)
        a = lora_a["default"].weight.detach().float().cpu().numpy()
        b = lora_b["default"].weight.detach().float().cpu().numpy()
        weights[base] = (a, b)
    return weights


def export_lora_gguf(
    weights: Mapping[str, tuple[NDArray[np.float32], NDArray[np.float32]]],
    path: str | Path,
    *,
    alpha: float,
    n_layers: int,
    architecture: str = "gemma3",
    name: str = "agrirecipe LoRA",
    record: Mapping[str, Any] | None = None,
) -> Path:
    """Write ``weights`` (HF module name -> (A, B)) as a llama.cpp LoRA adapter GGUF."""
    import gguf
    import numpy as np

    arch = next(
        (key for key, value in gguf.MODEL_ARCH_NAMES.items() if value == architecture), None
    )
    if arch is None:
        raise ModelError(f"gguf does not know the architecture {architecture!r}", stage="finetune")
    names = gguf.get_tensor_name_map(arch, n_layers)
    target = Path(path)
    target.parent.mkdir(parents=True, exist_ok=True)
    partial = target.with_suffix(target.suffix + ".partial")
    writer = gguf.GGUFWriter(str(partial), architecture)
    writer.add_type(gguf.GGUFType.ADAPTER)
    writer.add_string(gguf.Keys.Adapter.TYPE, "lora")
    writer.add_float32(gguf.Keys.Adapter.LORA_ALPHA, float(alpha))
    writer.add_name(name)
    if record is not None:
        writer.add_string(RECORD_KEY, json.dumps(record, sort_keys=True))
    for module, (a, b) in sorted(weights.items()):
        gguf_name = names.get_name(module + ".weight", try_suffixes=(".weight",))
        if gguf_name is None:
            raise ModelError(
                f"no GGUF tensor name for {module!r} ({architecture})", stage="finetune"
            )
        if a.ndim != 2 or b.ndim != 2 or a.shape[0] != b.shape[1]:
            raise ModelError(
                f"{module!r}: lora_A {a.shape} and lora_B {b.shape} do not share a rank",
                stage="finetune",
            )
        writer.add_tensor(gguf_name + ".lora_a", np.ascontiguousarray(a, dtype=np.float32))
        writer.add_tensor(gguf_name + ".lora_b", np.ascontiguousarray(b, dtype=np.float32))
    writer.write_header_to_file()
    writer.write_kv_data_to_file()
    writer.write_tensors_to_file()
    writer.close()
    partial.replace(target)
    return target


def read_adapter(path: str | Path) -> AdapterInfo:
    """Read a LoRA GGUF's metadata and tensor shapes (numpy order) back with the ``gguf`` reader."""
    import gguf

    try:
        reader = gguf.GGUFReader(str(path))
    except (OSError, ValueError) as exc:
        raise ModelError(f"cannot read the adapter {str(path)!r}: {exc}", stage="finetune") from exc

    def value(key: str, default: Any = None) -> Any:
        field = reader.fields.get(key)
        return field.contents() if field is not None else default

    tensors = {t.name: tuple(int(n) for n in reversed(t.shape.tolist())) for t in reader.tensors}
    record = value(RECORD_KEY)
    return AdapterInfo(
        general_type=str(value("general.type", "")),
        adapter_type=str(value("adapter.type", "")),
        architecture=str(value("general.architecture", "")),
        alpha=float(value("adapter.lora.alpha", 0.0)),
        tensors=tensors,
        record=json.loads(record) if record else {},
    )
