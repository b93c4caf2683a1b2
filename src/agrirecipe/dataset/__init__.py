"""Synthetic training data: variants x camera views of a scene, with exact labels.

:func:`dataset` renders, for every variant (a layout seed, and optionally
drawn light and weather) and camera view (a ground robot between rows, a drone,
or the overview), an RGB image, depth in metres, semantic and instance masks
(instance ids are ``plants.csv`` rows), 2D boxes, COCO and YOLO labels, and the
camera's intrinsics and extrinsics, in Blender (Cycles on the CPU) through a
local process pool or Ray. Labels come from a second, one-ray-per-pixel render
whose shaders write each plant's field and index, so they are exact.
"""

from agrirecipe.dataset._config import (
    CAMERA_KINDS,
    CameraKind,
    CameraRigs,
    DroneRig,
    OverviewRig,
    RobotRig,
    dataset_defaults,
    parse_weed_density,
    weeds_in_prompt,
)
from agrirecipe.dataset._labels import (
    SEMANTIC_BASE,
    LabelImages,
    boxes_from_instances,
    coco_rle,
    decode_labels,
    fog,
    instance_regions,
    read_label_exr,
)
from agrirecipe.dataset._plan import (
    WEED_COLUMNS,
    plan_conditions,
    plan_views,
    plan_weeds,
    stream,
    sun_position,
    variant_seed,
    weeds_csv,
)
from agrirecipe.dataset._render import MARKER, job_digest, render_variant
from agrirecipe.dataset._run import EXECUTORS, DatasetReport, ExecutorName, dataset
from agrirecipe.dataset._variation import VARIABLE_ATTRIBUTES, check_attributes, vary_recipe

__all__ = [
    "CAMERA_KINDS",
    "EXECUTORS",
    "MARKER",
    "SEMANTIC_BASE",
    "VARIABLE_ATTRIBUTES",
    "WEED_COLUMNS",
    "CameraKind",
    "CameraRigs",
    "DatasetReport",
    "DroneRig",
    "ExecutorName",
    "LabelImages",
    "OverviewRig",
    "RobotRig",
    "boxes_from_instances",
    "check_attributes",
    "coco_rle",
    "dataset",
    "dataset_defaults",
    "decode_labels",
    "fog",
    "instance_regions",
    "job_digest",
    "parse_weed_density",
    "plan_conditions",
    "plan_views",
    "plan_weeds",
    "read_label_exr",
    "render_variant",
    "stream",
    "sun_position",
    "variant_seed",
    "vary_recipe",
    "weeds_csv",
    "weeds_in_prompt",
]
