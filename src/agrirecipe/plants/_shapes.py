"""Shape programs: one per plant archetype, from a :class:`PlantSpec` to geometry.

Each program draws the plant in metres from the knowledge base's height ``H`` and
canopy width ``W`` and the numbers of ``data/shapes.yaml``, with a seeded random
generator for the variation between shape variants. The foliage state (leafless,
budding, leafy, flowering, fruiting, autumn, senescent) decides what is drawn:
bare branches in winter, blossom, unripe or ripe fruit, ripe ears. An ill plant
draws a share of its leaves in the disease's colour (chlorotic or necrotic) and
lets its leaves droop. :func:`draw` then scales the result to exactly ``H`` tall and
``W`` wide (a vine keeps its length along the row: the trellis wires span it).
"""

from __future__ import annotations

from collections.abc import Callable

import numpy as np

from agrirecipe.plants._mesh import Material, PlantMesh, tube
from agrirecipe.plants._painter import (
    GOLDEN,
    Floats,
    Painter,
    PlantSpec,
    branch,
    compass,
    mix,
    unit,
)

__all__ = ["ARCHETYPES", "PlantSpec", "draw"]


# --- archetypes ----------------------------------------------------------------------------------


def _tree(p: Painter, *, citrus: bool) -> None:
    spec, rng, par = p.spec, p.rng, p.spec.params
    h, w = spec.height_m, spec.width_m
    trunk_top = par["trunk"] * h
    radius = 0.035 * h**0.8
    crown_z = trunk_top + (h - trunk_top) / 2.0
    crown = np.array([w / 2.0, w / 2.0, (h - trunk_top) / 2.0])
    p.builder.add(
        p.bark,
        tube(
            [[0, 0, 0], [0, 0, trunk_top * 0.6], [0, 0, h * 0.92]],
            [radius, radius * 0.8, radius * 0.15],
            7,
        ),
    )
    tips: list[Floats] = []
    scaffolds = int(par["scaffolds"])
    for index in range(scaffolds):
        azimuth = index * GOLDEN * 2 + rng.uniform(-0.3, 0.3)
        start_z = trunk_top + (h - trunk_top) * 0.55 * index / max(1, scaffolds - 1)
        rise = rng.uniform(0.5, 0.9) if not citrus else rng.uniform(0.3, 0.7)
        direction = compass(np.array([azimuth]), np.array([rise]))[0]
        reach = float(np.linalg.norm(crown[:2])) * rng.uniform(0.55, 0.8)
        path = branch(np.array([0.0, 0.0, start_z]), direction, reach / np.cos(rise), rng)
        p.builder.add(p.bark, tube(path, np.linspace(radius * 0.55, radius * 0.08, len(path)), 5))
        for twig in range(3):
            base = path[1 + twig]
            twig_dir = unit(direction + rng.normal(0, 0.5, 3) + [0, 0, 0.3])
            twig_path = branch(base, twig_dir, reach * 0.45, rng, steps=2)
            p.builder.add(p.bark, tube(twig_path, [radius * 0.18, radius * 0.1, radius * 0.03], 3))
            tips.append(twig_path[-1])
        tips.append(path[-1])
    if spec.foliage == "leafless":
        return
    counts = {"budding": 0.35, "flowering": 0.6, "autumn": 0.7, "senescent": 0.35}
    count = int(par["leaves"] * counts.get(spec.foliage, 1.0))
    # leaves in the crown's outer shell, denser near the branch tips
    direction = unit(rng.normal(size=(count, 3)))
    shell = rng.uniform(0.55, 1.0, count) ** 0.5
    centres = direction * crown * shell[:, None] + [0.0, 0.0, crown_z]
    leaf_size = (par["leaf_m"][0] * (0.55 if spec.foliage == "budding" else 1.0), par["leaf_m"][1])
    outward = unit(direction + rng.normal(0.0, 0.6, (count, 3)) + [0, 0, 0.3])
    p.leaves(centres, outward, leaf_size, bend=0.3, cup=0.2)
    if spec.foliage == "flowering":
        blossoms = int(par["leaves"] * 0.3)
        direction = unit(rng.normal(size=(blossoms, 3)))
        p.blossoms(direction * crown * 0.98 + [0.0, 0.0, crown_z], 0.022)
    if spec.foliage in ("fruiting", "autumn") and spec.fruit_rgb is not None:
        fruit = par["fruit"]
        n = int(fruit["count"] * (1.0 if spec.ripe else 0.8))
        direction = unit(rng.normal(size=(n, 3)) * [1.0, 1.0, 0.7] - [0.0, 0.0, 0.2])
        centres = direction * crown * rng.uniform(0.8, 0.97, (n, 1)) + [0.0, 0.0, crown_z]
        radius = float(fruit["radius_m"])
        detail = (3, 5) if radius < 0.02 else (4, 6)  # small fruit need fewer triangles
        p.spheres(p.fruit, centres, radius, float(fruit["elongation"]), detail)


def _banana(p: Painter) -> None:
    spec, rng, par = p.spec, p.rng, p.spec.params
    h = spec.height_m
    top = 0.55 * h
    girth = 0.06 * h**0.5
    p.builder.add(
        p.stem,
        tube([[0, 0, 0], [0, 0, top * 0.5], [0, 0, top]], [girth, girth * 0.85, girth * 0.7], 8),
    )
    count = int(par["leaves"]) if spec.foliage != "senescent" else int(par["leaves"]) // 2
    azimuth = np.arange(count) * GOLDEN * 2 + rng.uniform(-0.2, 0.2, count)
    elevation = rng.uniform(0.6, 1.2, count)
    length = par["leaf_m"][0] * h
    p.leaves(
        np.tile([0.0, 0.0, top], (count, 1)) + rng.normal(0, 0.02, (count, 3)),
        compass(azimuth, elevation),
        (length, length * par["leaf_m"][1] * 2.2),
        segments=14,
        bend=0.6,
        split=3,
        taper=0.45,
        jitter=0.2,
    )
    if spec.stage in ("Reproductive", "Maturation"):
        stalk = np.array([[0.0, 0.0, top], [0.15 * h, 0.0, top * 0.95], [0.22 * h, 0.0, top * 0.7]])
        p.builder.add(p.stem, tube(stalk, [0.03, 0.025, 0.02], 5))
        fruit = par["fruit"]
        n = int(fruit["count"])
        along = np.linspace(0.0, 1.0, n)
        ring = rng.uniform(0, 2 * np.pi, n)
        centres = np.stack(
            [0.22 * h + 0.07 * np.cos(ring), 0.07 * np.sin(ring), top * (0.72 - 0.25 * along)], -1
        )
        p.spheres(
            p.fruit, centres, float(fruit["radius_m"]), float(fruit["elongation"]) * 0.4, hang=False
        )
        if spec.flower_rgb is not None:
            p.spheres(p.flower, np.array([[0.22 * h, 0.0, top * 0.4]]), 0.06, 1.8, (5, 8))


def _vine(p: Painter) -> None:
    spec, rng, par = p.spec, p.rng, p.spec.params
    h, w, half = spec.height_m, spec.width_m, spec.in_row_m / 2.0
    cordon = par["cordon"] * h
    p.builder.add(p.stake, tube([[0.03, 0, 0], [0.03, 0, h]], [0.018, 0.016], 5))
    p.builder.add(
        p.bark, tube([[0, 0, 0], [0, 0, cordon * 0.6], [0, 0, cordon]], [0.03, 0.025, 0.022], 6)
    )
    for side in (-1.0, 1.0):
        arm = np.array(
            [
                [0, 0, cordon],
                [0, side * half * 0.45, cordon + 0.02],
                [0, side * half * 0.95, cordon],
            ]
        )
        p.builder.add(p.bark, tube(arm, [0.02, 0.016, 0.01], 5))
    for z in (cordon, cordon + 0.3 * (h - cordon), cordon + 0.7 * (h - cordon)):
        for x in (0.0,) if z == cordon else (-w * 0.35, w * 0.35):
            p.builder.add(p.wire, tube([[x, -half, z], [x, half, z]], [0.002, 0.002], 3))
    shoots = max(2, round(par["shoots_per_m"] * spec.in_row_m))
    ys = np.linspace(-half * 0.9, half * 0.9, shoots) + rng.normal(0, 0.02, shoots)
    tops: list[Floats] = []
    for y in ys:
        lean = rng.normal(0.0, 0.25)
        path = np.array(
            [
                [0.0, y, cordon],
                [lean * w * 0.3, y, cordon + (h - cordon) * 0.5],
                [lean * w * 0.5, y + rng.normal(0, 0.03), h],
            ]
        )
        if spec.foliage == "leafless":
            path = path[:2]  # pruned canes in winter
        p.builder.add(
            p.bark if spec.foliage == "leafless" else p.stem,
            tube(path, [0.008, 0.006, 0.003][: len(path)], 3),
        )
        tops.append(path)
    if spec.foliage == "leafless":
        return
    per = int(par["leaves_per_shoot"] * (0.5 if spec.foliage in ("budding", "senescent") else 1.0))
    centres, directions = [], []
    for path in tops:
        t = rng.uniform(0.05, 1.0, per)[:, None]
        centres.append(path[0] + (path[-1] - path[0]) * t + rng.normal(0, 0.01, (per, 3)))
        facing = rng.choice([-1.0, 1.0], per)
        directions.append(
            compass(
                np.where(facing > 0, 0.0, np.pi) + rng.normal(0, 0.5, per),
                rng.uniform(0.0, 0.9, per),
            )
        )
    p.leaves(
        np.concatenate(centres),
        np.concatenate(directions),
        tuple(par["leaf_m"]),
        bend=0.25,
        cup=0.15,
    )
    # bunches hang from set to harvest, autumn leaves or not
    bearing = spec.foliage == "fruiting" or (spec.ripe and spec.foliage == "autumn")
    if bearing and spec.fruit_rgb is not None:
        fruit = par["fruit"]
        for _ in range(int(fruit["count"])):
            y = rng.uniform(-half * 0.8, half * 0.8)
            x = rng.choice([-1.0, 1.0]) * rng.uniform(0.03, w * 0.3)
            berries = int(fruit["berries"])
            depth = rng.uniform(0, 1, berries)
            spread = 0.045 * (1.0 - depth * 0.7)
            angle = rng.uniform(0, 2 * np.pi, berries)
            centres_b = np.stack(
                [
                    x + spread * np.cos(angle),
                    y + spread * np.sin(angle),
                    cordon - 0.02 - depth * 0.16,
                ],
                -1,
            )
            p.spheres(p.fruit, centres_b, float(fruit["radius_m"]), 1.05, (3, 4), hang=False)


def _maize(p: Painter) -> None:
    spec, rng, par = p.spec, p.rng, p.spec.params
    h = spec.height_m
    mature = spec.foliage == "senescent" or (spec.ripe and spec.mature_rgb is not None)
    stalk_top = 0.86 * h if spec.stage != "Vegetative" else h * 0.7
    p.builder.add(
        p.stem,
        tube(
            [[0, 0, 0], [0, 0, stalk_top * 0.5], [0, 0, stalk_top]],
            [0.014 * h**0.5, 0.012 * h**0.5, 0.006],
            6,
        ),
    )
    count = int(par["leaves"] * (0.6 if spec.stage == "Vegetative" else 1.0))
    z = np.linspace(0.08, 0.78, count) * stalk_top / 0.86
    azimuth = np.arange(count) * np.pi + rng.normal(0, 0.25, count)
    lengths = par["leaf_m"][0] * h * (1.0 - 0.4 * np.abs(np.linspace(-0.6, 1.0, count)))
    positions = np.stack([np.zeros(count), np.zeros(count), z], -1)
    for index in range(count):  # each leaf its own length: arching more when long
        p.leaves(
            positions[index : index + 1],
            compass(azimuth[index : index + 1], np.array([0.9])),
            (float(lengths[index]), float(lengths[index]) * par["leaf_m"][1] / par["leaf_m"][0]),
            segments=6,
            bend=0.75,
            taper=0.7,
            jitter=0.0,
        )
    if spec.stage != "Vegetative":
        spikes = 7
        azimuth = rng.uniform(0, 2 * np.pi, spikes)
        for a in azimuth:
            d = compass(np.array([a]), np.array([1.1]))[0]
            path = np.array(
                [
                    [0, 0, stalk_top],
                    [0, 0, stalk_top] + d * 0.08 * h,
                    [0, 0, stalk_top] + d * 0.14 * h - [0, 0, 0.02 * h],
                ]
            )
            tassel = Material("tassel", spec.flower_rgb or (0.85, 0.78, 0.45), 0.8)
            p.builder.add(tassel, tube(path, [0.003, 0.002, 0.001], 3))
        fruit = par["fruit"]
        ear = np.array([[0.04 * h**0.5, 0.0, 0.5 * stalk_top]])
        husk = Material("ear", (0.78, 0.68, 0.4) if mature else (0.45, 0.62, 0.3), 0.8)
        p.spheres(
            husk, ear, float(fruit["radius_m"]), float(fruit["elongation"]), (6, 6), hang=False
        )
    if mature and spec.mature_rgb is not None:
        pass  # the leaf colour already is the ripe crop's (knowledge base)


def _cereal(p: Painter) -> None:
    spec, rng, par = p.spec, p.rng, p.spec.params
    h = spec.height_m
    tillers = int(par["tillers"])
    ear = spec.stage != "Vegetative"
    for index in range(tillers):
        a = index * GOLDEN * 2 + rng.normal(0, 0.3)
        lean = rng.uniform(0.0, 0.12)
        top = np.array(
            [
                lean * np.cos(a) * h,
                lean * np.sin(a) * h,
                h * (0.92 if ear else 0.7) * rng.uniform(0.93, 1.0),
            ]
        )
        path = np.array([[0, 0, 0], top * [0.4, 0.4, 0.5], top])
        p.builder.add(p.stem, tube(path, [0.0025, 0.002, 0.0015], 3))
        leaves = 3 if ear else 4
        z = np.linspace(0.12, 0.55, leaves) * top[2]
        centres = np.stack([top[0] * z / top[2], top[1] * z / top[2], z], -1)
        dirs = compass(
            a + np.pi * np.arange(leaves) + rng.normal(0, 0.3, leaves),
            rng.uniform(0.6, 1.0, leaves),
        )
        p.leaves(
            centres,
            dirs,
            (par["leaf_m"][0] * h, par["leaf_m"][1] * h),
            segments=4,
            bend=0.55,
            taper=0.8,
        )
        if ear:
            ear_m = Material(
                "ear", spec.leaf_rgb if not spec.ripe else (spec.mature_rgb or spec.leaf_rgb), 0.85
            )
            length, radius = par["ear_m"][0] * h, par["ear_m"][1] * h
            p.spheres(ear_m, top[None, :] + [0, 0, length], radius, length / radius / 2, (4, 4))


def _rosette(p: Painter, *, head: bool) -> None:
    spec, rng, par = p.spec, p.rng, p.spec.params
    h, w = spec.height_m, spec.width_m
    count = int(par["leaves"])
    azimuth = np.arange(count) * GOLDEN + rng.normal(0, 0.1, count)
    inner = np.linspace(1.0, 0.0, count)  # the last leaves are the inner, upright ones
    elevation = 0.25 + 1.0 * inner**1.5 if not head else 0.15 + 0.4 * inner
    length = par["leaf_m"][0] * w * (0.55 + 0.45 * (1.0 - inner))
    base = np.stack([0.01 * np.cos(azimuth), 0.01 * np.sin(azimuth), 0.01 + 0.02 * inner], -1)
    for index in range(count):
        p.leaves(
            base[index : index + 1],
            compass(azimuth[index : index + 1], np.array([elevation[index]])),
            (float(length[index]), float(length[index]) * par["leaf_m"][1] / par["leaf_m"][0]),
            segments=4,
            bend=0.35,
            cup=0.7,
            taper=0.5,
            jitter=0.0,
        )
    if head:
        size = par["head"] * w / 2.0 * {"Vegetative": 0.5, "Reproductive": 0.9}.get(spec.stage, 1.0)
        heart = Material("head", mix(spec.leaf_rgb, (0.8, 0.88, 0.7), 0.7), 0.6)
        p.spheres(heart, np.array([[0.0, 0.0, size * 0.9]]), size, 0.9, (8, 10), hang=False)
    if spec.stage == "Reproductive" and spec.flower_rgb is not None and not head:
        stalk = np.array([[0, 0, 0], [0, 0, h * 0.6], [0.01, 0, h]])
        p.builder.add(p.stem, tube(stalk, [0.01, 0.007, 0.003], 4))
        centres = np.stack(
            [rng.normal(0, 0.03, 12), rng.normal(0, 0.03, 12), h * rng.uniform(0.8, 1.0, 12)], -1
        )
        p.blossoms(centres, 0.008)


def _strawberry(p: Painter) -> None:
    spec, rng, par = p.spec, p.rng, p.spec.params
    h, w = spec.height_m, spec.width_m
    for index in range(int(par["leaves"])):
        a = index * GOLDEN * 2 + rng.normal(0, 0.2)
        top = np.array([np.cos(a) * w * 0.3, np.sin(a) * w * 0.3, h * rng.uniform(0.7, 0.95)])
        p.builder.add(
            p.stem, tube([[0, 0, 0.01], top * [0.5, 0.5, 0.8], top], [0.003, 0.0025, 0.002], 3)
        )
        leaflets = compass(a + np.array([-0.9, 0.0, 0.9]), np.full(3, 0.35))
        p.leaves(np.tile(top, (3, 1)), leaflets, tuple(par["leaf_m"]), bend=0.3, cup=0.3, taper=0.6)
    if spec.stage == "Reproductive":
        centres = np.stack(
            [rng.normal(0, w * 0.2, 8), rng.normal(0, w * 0.2, 8), h * rng.uniform(0.4, 0.7, 8)], -1
        )
        p.blossoms(centres, 0.012)
    if spec.stage in ("Reproductive", "Maturation") and spec.fruit_rgb is not None:
        fruit = par["fruit"]
        n = int(fruit["count"])
        a = rng.uniform(0, 2 * np.pi, n)
        centres = np.stack([np.cos(a) * w * 0.3, np.sin(a) * w * 0.3, np.full(n, 0.04)], -1)
        p.spheres(p.fruit, centres, float(fruit["radius_m"]), float(fruit["elongation"]), (4, 6))


def _bushy(p: Painter) -> None:
    spec, rng, par = p.spec, p.rng, p.spec.params
    h, w = spec.height_m, spec.width_m
    stems = int(par["stems"])
    for index in range(stems):
        a = index * GOLDEN * 2 + rng.normal(0, 0.2)
        d = compass(np.array([a]), np.array([rng.uniform(0.7, 1.2)]))[0]
        path = branch(np.zeros(3), d, h * 0.9, rng, steps=3)
        p.builder.add(p.stem, tube(path, [0.006, 0.005, 0.004, 0.002], 4))
        t = np.linspace(0.3, 1.0, 6)
        centres = path[0] + (path[-1] - path[0]) * t[:, None]
        for centre in centres:
            dirs = compass(a + rng.uniform(-1.5, 1.5, 5), rng.uniform(-0.1, 0.8, 5))
            p.leaves(np.tile(centre, (5, 1)), dirs, tuple(par["leaf_m"]), bend=0.3, cup=0.2)
    if spec.stage == "Reproductive" and spec.flower_rgb is not None:
        centres = np.stack(
            [
                rng.normal(0, w * 0.2, 14),
                rng.normal(0, w * 0.2, 14),
                h * rng.uniform(0.85, 1.0, 14),
            ],
            -1,
        )
        p.blossoms(centres, 0.012)


def _feathery(p: Painter) -> None:
    spec, rng, par = p.spec, p.rng, p.spec.params
    h, w = spec.height_m, spec.width_m
    for index in range(int(par["leaves"])):
        a = index * GOLDEN * 2 + rng.normal(0, 0.2)
        tip = np.array([np.cos(a) * w * 0.4, np.sin(a) * w * 0.4, h * rng.uniform(0.8, 1.0)])
        path = np.array([[0, 0, 0.01], tip * [0.3, 0.3, 0.7], tip])
        p.builder.add(p.stem, tube(path, [0.002, 0.0015, 0.001], 3))
        t = np.linspace(0.35, 1.0, 7)
        centres = path[1] + (path[2] - path[1]) * t[:, None]
        for side in (-1.0, 1.0):
            dirs = compass(np.full(7, a + side * 1.2), np.full(7, 0.6))
            p.leaves(centres, dirs, tuple(par["leaf_m"]), segments=1, bend=0.1)
    fruit = par["fruit"]
    if spec.stage == "Maturation" and spec.fruit_rgb is not None:  # the root's orange shoulder
        p.spheres(
            p.fruit,
            np.array([[0.0, 0.0, 0.012]]),
            float(fruit["radius_m"]),
            1.2,
            (5, 8),
            hang=False,
        )
    if spec.stage == "Reproductive" and spec.flower_rgb is not None:
        p.builder.add(p.stem, tube([[0, 0, 0], [0, 0, h]], [0.004, 0.003], 4))
        p.spheres(p.flower, np.array([[0.0, 0.0, h]]), 0.04, 0.25, (3, 8), hang=False)


def _tubular(p: Painter) -> None:
    spec, rng, par = p.spec, p.rng, p.spec.params
    h = spec.height_m
    fallen = spec.ripe or spec.foliage == "senescent"
    for index in range(int(par["leaves"])):
        a = index * GOLDEN * 2 + rng.normal(0, 0.2)
        lean = rng.uniform(0.05, 0.25) + (0.5 if fallen else 0.0)
        d = np.array([np.cos(a) * lean, np.sin(a) * lean, 1.0])
        length = h * rng.uniform(0.75, 1.0)
        t = np.linspace(0.0, 1.0, 6)[:, None]
        path = d * t * length * [1.0, 1.0, 1.0] - [0.0, 0.0, 1.0] * (lean * 0.6 * length * t**2)
        path[:, 2] = np.maximum(path[:, 2], 0.005) + 0.02
        p.builder.add(
            p.sick if (p.sick is not None and rng.random() < spec.ill_share) else p.leaf,
            tube(path, np.linspace(0.006, 0.001, 6), 5),
        )
    fruit = par["fruit"]
    size = float(fruit["radius_m"]) * {"Vegetative": 0.45, "Reproductive": 0.8}.get(spec.stage, 1.0)
    bulb = Material("bulb", spec.fruit_rgb or (0.8, 0.65, 0.4), 0.6)
    p.spheres(
        bulb,
        np.array([[0.0, 0.0, size * 0.6]]),
        size,
        float(fruit["elongation"]),
        (6, 8),
        hang=False,
    )
    if spec.stage == "Reproductive" and spec.flower_rgb is not None:
        p.builder.add(p.stem, tube([[0, 0, 0], [0, 0, h]], [0.005, 0.004], 4))
        p.spheres(p.flower, np.array([[0.0, 0.0, h * 0.97]]), 0.03, 1.0, (4, 6), hang=False)


def _staked(p: Painter) -> None:
    spec, rng, par = p.spec, p.rng, p.spec.params
    h, w = spec.height_m, spec.width_m
    p.builder.add(p.stake, tube([[0.04, 0, 0], [0.04, 0, h]], [0.01, 0.01], 4))
    main = np.array([[0, 0, 0], [0.01, 0.01, h * 0.5], [0.0, 0.0, h * 0.97]])
    p.builder.add(p.stem, tube(main, [0.008, 0.006, 0.003], 5))
    branches = int(par["branches"])
    tips = []
    for index in range(branches):
        a = index * GOLDEN * 2 + rng.normal(0, 0.2)
        base = main[0] + (main[2] - main[0]) * (0.15 + 0.75 * index / branches)
        d = compass(np.array([a]), np.array([rng.uniform(0.2, 0.6)]))[0]
        path = branch(base, d, w * 0.45, rng, steps=2)
        p.builder.add(p.stem, tube(path, [0.004, 0.003, 0.002], 3))
        t = np.linspace(0.3, 1.0, 4)
        centres = path[0] + (path[-1] - path[0]) * t[:, None]
        dirs = compass(a + rng.uniform(-1.2, 1.2, 4), rng.uniform(-0.2, 0.5, 4))
        p.leaves(centres, dirs, tuple(par["leaf_m"]), bend=0.35, cup=0.2)
        for centre in centres:  # compound leaves: leaflets along each leaf
            small = compass(a + rng.uniform(-1.8, 1.8, 6), rng.uniform(-0.3, 0.6, 6))
            p.leaves(
                np.tile(centre, (6, 1)) + rng.normal(0, 0.02, (6, 3)),
                small,
                (par["leaf_m"][0] * 0.8, par["leaf_m"][1] * 0.8),
                segments=1,
            )
        tips.append(path[-1])
    if spec.stage == "Reproductive" and spec.flower_rgb is not None:
        p.blossoms(np.array(tips) + rng.normal(0, 0.02, (len(tips), 3)), 0.01)
    if spec.stage in ("Reproductive", "Maturation") and spec.fruit_rgb is not None:
        fruit = par["fruit"]
        n = int(fruit["count"] * (1.0 if spec.ripe else 0.6))
        which = rng.integers(0, len(tips), n)
        centres = (
            np.array(tips)[which] * [0.8, 0.8, 1.0] + rng.normal(0, 0.04, (n, 3)) - [0, 0, 0.03]
        )
        p.spheres(p.fruit, centres, float(fruit["radius_m"]), float(fruit["elongation"]), (4, 6))


ARCHETYPES: dict[str, Callable[[Painter], None]] = {
    "broadleaf_tree": lambda p: _tree(p, citrus=False),
    "citrus_tree": lambda p: _tree(p, citrus=True),
    "banana": _banana,
    "vine": _vine,
    "maize": _maize,
    "cereal": _cereal,
    "rosette": lambda p: _rosette(p, head=False),
    "head": lambda p: _rosette(p, head=True),
    "strawberry": _strawberry,
    "bushy": _bushy,
    "feathery": _feathery,
    "tubular": _tubular,
    "staked": _staked,
}


def draw(spec: PlantSpec, seed: int) -> PlantMesh:
    """The plant of ``spec`` for shape variant ``seed``: exactly ``H`` tall and ``W`` wide."""
    painter = Painter(spec, np.random.default_rng(seed))
    ARCHETYPES[spec.archetype](painter)
    low, high = painter.builder.extent()
    height = float(high[2])
    across = float(max(abs(low[0]), abs(high[0]))) * 2.0
    along = float(max(abs(low[1]), abs(high[1]))) * 2.0
    sz = spec.height_m / height
    if spec.archetype == "vine":  # the wires span the row spacing: only the hedge's depth scales
        sx, sy = spec.width_m / across, 1.0
    else:
        sx = sy = spec.width_m / max(across, along)
    return painter.builder.build((sx, sy, sz))
