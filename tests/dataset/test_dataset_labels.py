"""Label encoding: COCO RLE read back by pycocotools, boxes, AOV decoding, fog."""

from __future__ import annotations

import numpy as np
import pytest

from agrirecipe.dataset import SEMANTIC_BASE, boxes_from_instances, coco_rle, decode_labels, fog


@pytest.mark.parametrize("seed", range(6))
def test_rle_is_decoded_by_pycocotools(seed: int) -> None:
    mask_api = pytest.importorskip("pycocotools.mask")
    rng = np.random.default_rng(seed)
    shape = (int(rng.integers(1, 40)), int(rng.integers(1, 40)))
    mask = rng.random(shape) < rng.random()
    if seed == 0:
        mask[:] = True  # starts with ones: an empty first run
    if seed == 1:
        mask[:] = False
    rle = coco_rle(mask)
    assert rle["size"] == list(shape)
    decoded = mask_api.decode({"size": rle["size"], "counts": rle["counts"].encode()})
    assert np.array_equal(decoded.astype(bool), mask)
    reference = mask_api.encode(np.asfortranarray(mask.astype(np.uint8)))
    assert reference["counts"].decode() == rle["counts"]


@pytest.mark.parametrize("seed", range(4))
def test_rle_of_a_window_is_the_rle_of_the_whole_mask(seed: int) -> None:
    mask_api = pytest.importorskip("pycocotools.mask")
    rng = np.random.default_rng(seed)
    image = np.zeros((30, 40), dtype=bool)
    x0, y0 = int(rng.integers(0, 20)), int(rng.integers(0, 15))
    window = rng.random((int(rng.integers(1, 15)), int(rng.integers(1, 20)))) < 0.5
    image[y0 : y0 + window.shape[0], x0 : x0 + window.shape[1]] = window
    rle = coco_rle(window, origin=(x0, y0), size=(30, 40))
    assert rle == coco_rle(image)
    decoded = mask_api.decode({"size": rle["size"], "counts": rle["counts"].encode()})
    assert np.array_equal(decoded.astype(bool), image)


def test_boxes_cover_each_instance_exactly() -> None:
    instance = np.zeros((10, 12), dtype=np.uint32)
    instance[2:5, 3:7] = 7
    instance[8, 11] = 9
    boxes = boxes_from_instances(instance)
    assert boxes == {7: (3, 2, 7, 5, 12), 9: (11, 8, 12, 9, 1)}


def test_aovs_become_plants_csv_rows_and_classes() -> None:
    field = np.array([[0, 1, 2, -1]], dtype=np.float32)
    plant = np.array([[0, 4, 0, 2]], dtype=np.float32)
    ground = np.array([[1, 0, 0, 0]], dtype=np.float32)
    depth = np.array([[3.0, 2.0, 1.0, 5.0]], dtype=np.float32)
    labels = decode_labels(
        {"agr_field": field, "agr_plant": plant, "agr_ground": ground, "depth": depth},
        field_offsets=[0, 10],
        field_classes=[4, 5],
        weed_first_id=31,
    )
    # field 1 plant 4 -> row 5; field 2 plant 0 -> row 11; weed 2 -> 33
    assert labels.instance.tolist() == [[0, 5, 11, 33]]
    assert labels.semantic.tolist() == [[SEMANTIC_BASE["soil"], 4, 5, SEMANTIC_BASE["weed"]]]
    assert labels.instance.dtype == np.uint32 and labels.semantic.dtype == np.uint8
    sky = decode_labels(
        {
            "agr_field": np.zeros((1, 1), np.float32),
            "agr_plant": np.zeros((1, 1), np.float32),
            "agr_ground": np.zeros((1, 1), np.float32),
            "depth": np.full((1, 1), 1e10, np.float32),
        },
        field_offsets=[0],
        field_classes=[4],
        weed_first_id=1,
    )
    assert sky.semantic[0, 0] == SEMANTIC_BASE["sky"] and sky.depth_m[0, 0] == 0.0


def test_fog_fades_with_distance_to_the_fog_colour() -> None:
    rgb = np.zeros((1, 3, 3), dtype=np.uint8)
    depth = np.array([[1.0, 100.0, 0.0]], dtype=np.float32)
    foggy = fog(rgb, depth, visibility_m=100.0, colour=(1.0, 1.0, 1.0))
    near, far, sky = foggy[0, :, 0]
    assert near == round(255 * (1 - np.exp(-3.912 / 100.0)))
    assert far == round(255 * (1 - 0.02)) and sky == 255  # 2 % contrast at the visibility
