"""Labels from the label render: depth, semantic and instance masks, boxes, COCO RLE, YOLO.

The label render (see ``_bpy_passes.py``) traces one ray per pixel with every
surface black and writes, per pixel, three value AOVs and the Z pass:

- ``agr_field``: the field's index + 1 for a crop plant, -1 for a weed, 0 else;
- ``agr_plant``: the plant's index in its field (kernel order, the order of
  ``plants.csv``), or the weed's index in ``weeds.csv``;
- ``agr_ground``: 1 on field soil, 2 on the grass base around the fields, 0 else;
- ``Depth.Z``: distance along the camera's optical axis, metres (Blender's
  "no hit" value, 1e10, for the sky).

One ray per pixel means every pixel holds the values of exactly one surface, so
labels are exact by construction: no blend of two plants along an edge.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from pathlib import Path
from typing import Any

import numpy as np
from numpy.typing import NDArray

from agrirecipe._errors import BackendError

__all__ = [
    "SEMANTIC_BASE",
    "LabelImages",
    "boxes_from_instances",
    "coco_rle",
    "decode_labels",
    "fog",
    "instance_regions",
    "read_label_exr",
]

#: Semantic class ids before the crops (crops follow from 4, in order of first appearance).
SEMANTIC_BASE = {"sky": 0, "soil": 1, "other": 2, "weed": 3}
_NO_HIT_M = 1e9


def read_label_exr(path: Path) -> dict[str, NDArray[np.float32]]:
    """The label render's channels by short name (``agr_field``, ``depth``...)."""
    try:
        import OpenEXR
    except ImportError as exc:  # pragma: no cover - an install problem
        raise BackendError(
            "reading the label render needs the OpenEXR module",
            stage="dataset",
            hint="pip install 'agrirecipe[dataset]'",
        ) from exc
    channels: dict[str, NDArray[np.float32]] = {}
    with OpenEXR.File(str(path)) as exr:
        for part in exr.parts:
            for name, channel in part.channels.items():
                short = name.split(".")[1] if name.count(".") >= 1 else name
                channels["depth" if short == "Depth" else short] = np.asarray(
                    channel.pixels, dtype=np.float32
                )
    missing = {"agr_field", "agr_plant", "agr_ground", "depth"} - set(channels)
    if missing:
        raise BackendError(
            f"the label render {path.name} lacks the passes {sorted(missing)}", stage="dataset"
        )
    return channels


class LabelImages:
    """Per-pixel labels of one view.

    ``instance`` (uint32) holds plant ids: the 1-based row of ``plants.csv`` for
    crops, ``weeds.csv``'s ``instance_id`` for weeds, 0 elsewhere. ``semantic``
    (uint8) holds class ids (:data:`SEMANTIC_BASE`, then crops). ``depth_m``
    (float32) is the distance along the optical axis; 0 where nothing was hit.
    """

    def __init__(
        self,
        instance: NDArray[np.uint32],
        semantic: NDArray[np.uint8],
        depth_m: NDArray[np.float32],
    ) -> None:
        self.instance = instance
        self.semantic = semantic
        self.depth_m = depth_m


def decode_labels(
    channels: Mapping[str, NDArray[np.float32]],
    *,
    field_offsets: Sequence[int],
    field_classes: Sequence[int],
    weed_first_id: int,
) -> LabelImages:
    """Turn the AOVs into instance ids and classes.

    ``field_offsets[i]`` is the number of ``plants.csv`` rows before field ``i``;
    ``field_classes[i]`` its crop's semantic class.
    """
    field = np.rint(channels["agr_field"]).astype(np.int64)
    plant = np.rint(channels["agr_plant"]).astype(np.int64)
    ground = np.rint(channels["agr_ground"]).astype(np.int64)
    depth = channels["depth"]
    offsets = np.asarray([0, *field_offsets], dtype=np.int64)
    classes = np.asarray([0, *field_classes], dtype=np.int64)
    if field.max(initial=0) >= len(offsets) or field.min(initial=0) < -1:
        raise BackendError("the label render holds an unknown field index", stage="dataset")
    crop = field > 0
    weed = field == -1
    instance = np.zeros(field.shape, dtype=np.int64)
    instance[crop] = offsets[field[crop]] + plant[crop] + 1
    instance[weed] = weed_first_id + plant[weed]
    semantic = np.zeros(field.shape, dtype=np.int64)
    semantic[ground == 1] = SEMANTIC_BASE["soil"]
    semantic[ground == 2] = SEMANTIC_BASE["other"]
    hit = depth < _NO_HIT_M
    semantic[hit & (ground == 0) & ~crop & ~weed] = SEMANTIC_BASE["other"]
    semantic[crop] = classes[field[crop]]
    semantic[weed] = SEMANTIC_BASE["weed"]
    return LabelImages(
        instance=instance.astype(np.uint32),
        semantic=semantic.astype(np.uint8),
        depth_m=np.where(hit, depth, 0.0).astype(np.float32),
    )


def instance_regions(
    instance: NDArray[np.uint32],
) -> dict[int, tuple[int, int, int, int, NDArray[np.bool_]]]:
    """Per instance id (ascending): ``(x_min, y_min, x_max, y_max, mask)``, max exclusive;
    ``mask`` is the instance's pixels inside that box (one pass over the image)."""
    flat = instance.ravel()
    width = instance.shape[1]
    order = np.argsort(flat, kind="stable")
    sorted_ids = flat[order]
    ids = np.unique(sorted_ids)
    ids = ids[ids != 0]
    starts = np.searchsorted(sorted_ids, ids, side="left")
    ends = np.searchsorted(sorted_ids, ids, side="right")
    regions = {}
    for value, start, end in zip(ids.tolist(), starts.tolist(), ends.tolist(), strict=True):
        ys, xs = np.divmod(order[start:end], width)
        x0, y0, x1, y1 = int(xs.min()), int(ys.min()), int(xs.max()) + 1, int(ys.max()) + 1
        mask = np.zeros((y1 - y0, x1 - x0), dtype=bool)
        mask[ys - y0, xs - x0] = True
        regions[int(value)] = (x0, y0, x1, y1, mask)
    return regions


def boxes_from_instances(
    instance: NDArray[np.uint32],
) -> dict[int, tuple[int, int, int, int, int]]:
    """Per instance id: ``(x_min, y_min, x_max, y_max, pixels)``, max exclusive (pixels)."""
    return {
        value: (x0, y0, x1, y1, int(mask.sum()))
        for value, (x0, y0, x1, y1, mask) in instance_regions(instance).items()
    }


def coco_rle(
    mask: NDArray[np.bool_],
    *,
    origin: tuple[int, int] = (0, 0),
    size: tuple[int, int] | None = None,
) -> dict[str, Any]:
    """COCO's compressed RLE of a binary mask (``{"size": [h, w], "counts": str}``).

    ``mask`` may be a window of a larger image: its top-left pixel at ``origin``
    (x, y) of an image of ``size`` (height, width). Runs are counted in
    column-major order starting with a run of zeros, then written with the COCO
    API's ``rleToString`` code (5-bit groups, differences to the run two back
    from the third run on), so ``pycocotools.mask.decode`` reads it back.
    """
    height, width = size if size is not None else mask.shape
    x0, y0 = origin
    columns = np.zeros((height, mask.shape[1]), dtype=np.uint8)
    columns[y0 : y0 + mask.shape[0]] = mask
    flat = columns.ravel(order="F")
    changes = np.flatnonzero(np.diff(flat)) + 1
    edges = np.concatenate(([0], changes, [flat.size]))
    runs = np.diff(edges).tolist()
    if flat.size and flat[0] == 1:
        runs = [0, *runs]
    # The columns left and right of the window are zeros.
    runs[0] += x0 * height
    after = (width - x0 - mask.shape[1]) * height
    if after:
        if len(runs) % 2 == 1:  # ends with a run of zeros
            runs[-1] += after
        else:
            runs.append(after)
    text = []
    for index, run in enumerate(runs):
        value = int(run) - (int(runs[index - 2]) if index > 2 else 0)
        more = True
        while more:
            chunk = value & 0x1F
            value >>= 5
            more = value != -1 if chunk & 0x10 else value != 0
            if more:
                chunk |= 0x20
            text.append(chr(chunk + 48))
    return {"size": [int(height), int(width)], "counts": "".join(text)}


def fog(
    rgb: NDArray[np.uint8],
    depth_m: NDArray[np.float32],
    *,
    visibility_m: float,
    colour: Sequence[float],
) -> NDArray[np.uint8]:
    """Koschmieder's law on the rendered image: ``I = J t + A (1 - t)``, ``t = exp(-b d)``.

    ``b = 3.912 / visibility`` (2 % contrast at the visibility distance); the
    sky (no depth) takes the fog colour ``A``. The same synthetic fog as
    Foggy Cityscapes (Sakaridis et al., 2018), applied in sRGB space.
    """
    beta = 3.912 / visibility_m
    transmission = np.where(depth_m > 0, np.exp(-beta * depth_m.astype(np.float64)), 0.0)
    airlight = np.asarray(colour, dtype=np.float64) * 255.0
    foggy = rgb.astype(np.float64) * transmission[..., None] + airlight * (
        1.0 - transmission[..., None]
    )
    clipped: NDArray[np.uint8] = np.clip(np.rint(foggy), 0, 255).astype(np.uint8)
    return clipped
