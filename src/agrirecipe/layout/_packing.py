"""The field packer: field rectangles placed without overlap, honouring relations.

Fields are arranged on a grid of cells, one field per cell. Column widths and
row heights are those of the largest field they hold, with a farm-track gap
between neighbouring columns and rows, so two fields in different cells can
never overlap. Relations become ordering constraints on cells:

- ``a north_of b``: a's row is above b's (so a lies entirely north of b, at
  least one gap away); ``south_of``, ``east_of`` and ``west_of`` likewise;
- ``a next_to b``: same row and a neighbouring column with no field between
  them (or the same column and a neighbouring row);
- ``a between b c``: all three in one row with a's column between b's and c's
  (or one column with a's row between).

``next_to`` and ``between`` leave a choice of axis and side; a small
deterministic search tries the choices in a fixed order (east-west before
north-south) and keeps the first arrangement that honours every relation.
Fields linked by relations form a block; blocks and unrelated fields are then
shelf-packed near the origin into a roughly square farm, in recipe order.
"""

from __future__ import annotations

import itertools
import math
from collections.abc import Iterable, Mapping, Sequence
from dataclasses import dataclass

from agrirecipe._errors import ConfigurationError, PromptError
from agrirecipe.recipe import FieldGeometry, Relation

__all__ = ["DEFAULT_GAP_M", "FieldRequest", "describe_relation", "pack_fields"]

#: Farm track left between neighbouring fields, metres.
DEFAULT_GAP_M = 4.0
# Bound on search nodes for next_to/between choices; real prompts need a handful.
_SEARCH_BUDGET = 20_000

_Edge = tuple[str, str]  # (a, b): a comes before b along the axis (west of / south of)


@dataclass(frozen=True)
class FieldRequest:
    """A field to be placed: its id and the rectangle it needs.

    ``width_m`` runs across the rows (east-west, local X), ``length_m`` along
    the rows (north-south, local Y); ``headland_m`` is carried into the
    resulting :class:`~agrirecipe.recipe.FieldGeometry`.
    """

    id: str
    width_m: float
    length_m: float
    headland_m: float = 0.0
    #: Counter-clockwise turn of the rectangle (rows along its local Y); the field is
    #: packed by its bounding box, so a turned field never overlaps a neighbour.
    rotation_deg: float = 0.0
    #: The planted block inside the headland when smaller than the field (see
    #: :attr:`~agrirecipe.recipe.FieldGeometry.planted_m`), carried into the geometry.
    planted_m: tuple[float, float] | None = None
    #: The stated plant count when it leaves the last row short (see
    #: :attr:`~agrirecipe.recipe.FieldGeometry.plant_count`), carried into the geometry.
    plant_count: int | None = None


def describe_relation(relation: Relation) -> str:
    """``"pears north_of carrots"``, ``"road between a and b"``: a relation as words."""
    return f"{relation.subject} {relation.kind} {' and '.join(relation.objects)}"


def pack_fields(
    requests: Sequence[FieldRequest],
    relations: Sequence[Relation] = (),
    *,
    gap_m: float = DEFAULT_GAP_M,
) -> dict[str, FieldGeometry]:
    """Place every requested field; return its geometry by id, in request order.

    Deterministic: the same requests and relations give the same geometry.
    Fields never overlap and neighbours are at least ``gap_m`` apart. Raises
    :class:`~agrirecipe.PromptError` (stage ``"layout"``) when the relations
    cannot all hold, naming them.
    """
    if not math.isfinite(gap_m) or gap_m < 0:
        raise ConfigurationError(
            f"gap_m must be a finite distance >= 0, got {gap_m!r}", stage="layout"
        )
    sizes = _checked_sizes(requests)
    ids = list(sizes)
    _check_relations(relations, ids)

    blocks: list[_Block] = []
    for component in _components(ids, relations):
        members = set(component)
        local = [r for r in relations if r.subject in members]
        cells = _solve_cells(component, local) if local else {component[0]: (0, 0)}
        blocks.append(_grid_block(component, cells, sizes, gap_m))

    origins = _shelf_pack(blocks, gap_m)
    geometry: dict[str, FieldGeometry] = {}
    for request in requests:
        x, y = origins[request.id]
        offset_x, offset_y = _turned_offset(request)
        geometry[request.id] = FieldGeometry(
            origin_m=(x + offset_x, y + offset_y),
            size_m=(float(request.width_m), float(request.length_m)),
            rotation_deg=float(request.rotation_deg),
            headland_m=float(request.headland_m),
            planted_m=request.planted_m,
            plant_count=request.plant_count,
        )
    return geometry


def _turned_corners(request: FieldRequest) -> list[tuple[float, float]]:
    """The rectangle's corners relative to its origin after the turn."""
    cos_r = math.cos(math.radians(request.rotation_deg))
    sin_r = math.sin(math.radians(request.rotation_deg))
    local = (
        (0.0, 0.0),
        (request.width_m, 0.0),
        (request.width_m, request.length_m),
        (0.0, request.length_m),
    )
    return [(u * cos_r - v * sin_r, u * sin_r + v * cos_r) for u, v in local]


def _turned_offset(request: FieldRequest) -> tuple[float, float]:
    """Where the turned rectangle's origin lies inside its packed bounding box."""
    if not request.rotation_deg:
        return 0.0, 0.0
    corners = _turned_corners(request)
    return -min(x for x, _ in corners), -min(y for _, y in corners)


def _footprint(request: FieldRequest) -> tuple[float, float]:
    """Width and length of the bounding box the packer places."""
    if not request.rotation_deg:
        return float(request.width_m), float(request.length_m)
    corners = _turned_corners(request)
    xs = [x for x, _ in corners]
    ys = [y for _, y in corners]
    return max(xs) - min(xs), max(ys) - min(ys)


# --- input checks -------------------------------------------------------------------------------


def _checked_sizes(requests: Sequence[FieldRequest]) -> dict[str, tuple[float, float]]:
    sizes: dict[str, tuple[float, float]] = {}
    for index, request in enumerate(requests):
        if request.id in sizes:
            raise PromptError(
                f"two fields share the id {request.id!r}",
                stage="layout",
                path=f"fields[{index}].id",
                hint="every field needs its own id",
            )
        for name in ("width_m", "length_m"):
            value = getattr(request, name)
            if not isinstance(value, int | float) or not math.isfinite(value) or value <= 0:
                raise PromptError(
                    f"field {request.id!r}: {name} must be a positive number of metres, "
                    f"got {value!r}",
                    stage="layout",
                    path=f"fields[{index}].{name}",
                )
        headland = request.headland_m
        if not isinstance(headland, int | float) or not math.isfinite(headland) or headland < 0:
            raise PromptError(
                f"field {request.id!r}: headland_m must be >= 0 metres, got {headland!r}",
                stage="layout",
                path=f"fields[{index}].headland_m",
            )
        rotation = request.rotation_deg
        if (
            not isinstance(rotation, int | float)
            or not math.isfinite(rotation)
            or not (-180.0 <= rotation <= 180.0)
        ):
            raise PromptError(
                f"field {request.id!r}: rotation_deg must be between -180 and 180, "
                f"got {rotation!r}",
                stage="layout",
                path=f"fields[{index}].rotation_deg",
            )
        sizes[request.id] = _footprint(request)
    return sizes


def _check_relations(relations: Sequence[Relation], ids: Sequence[str]) -> None:
    known = set(ids)
    for index, relation in enumerate(relations):
        named = (relation.subject, *relation.objects)
        for name in named:
            if name not in known:
                raise PromptError(
                    f"relation '{describe_relation(relation)}' names an unknown field {name!r}",
                    stage="layout",
                    path=f"relations[{index}]",
                    hint="fields: " + ", ".join(ids),
                )
        expected = 2 if relation.kind == "between" else 1
        if len(relation.objects) != expected or len(set(named)) != len(named):
            raise PromptError(
                f"relation '{describe_relation(relation)}' cannot hold: "
                f"{relation.kind} relates a field to {expected} other distinct field(s)",
                stage="layout",
                path=f"relations[{index}]",
            )


class _Groups:
    """Union-find over field ids: which fields have been bound together."""

    def __init__(self, names: Iterable[str]) -> None:
        self._parent = {name: name for name in names}

    def find(self, name: str) -> str:
        parent = self._parent
        while parent[name] != name:
            parent[name] = parent[parent[name]]
            name = parent[name]
        return name

    def join(self, a: str, b: str) -> None:
        root_a, root_b = self.find(a), self.find(b)
        if root_a != root_b:
            # The smaller name stays the root: the result never depends on join order.
            self._parent[max(root_a, root_b)] = min(root_a, root_b)


def _components(ids: Sequence[str], relations: Sequence[Relation]) -> list[list[str]]:
    """Fields linked by relations, each group in recipe order, groups by first member."""
    groups = _Groups(ids)
    for relation in relations:
        for other in relation.objects:
            groups.join(relation.subject, other)
    members: dict[str, list[str]] = {}
    for name in ids:
        members.setdefault(groups.find(name), []).append(name)
    return list(members.values())


# --- cell assignment ----------------------------------------------------------------------------


@dataclass(frozen=True)
class _Constraints:
    """Ordering and alignment constraints on cells, per axis."""

    x_edges: tuple[_Edge, ...] = ()  # a west of b
    y_edges: tuple[_Edge, ...] = ()  # a south of b
    same_row: tuple[_Edge, ...] = ()
    same_col: tuple[_Edge, ...] = ()

    def plus(self, other: _Constraints) -> _Constraints:
        return _Constraints(
            self.x_edges + other.x_edges,
            self.y_edges + other.y_edges,
            self.same_row + other.same_row,
            self.same_col + other.same_col,
        )


def _strict(relation: Relation) -> _Constraints:
    subject, target = relation.subject, relation.objects[0]
    if relation.kind == "north_of":
        return _Constraints(y_edges=((target, subject),))
    if relation.kind == "south_of":
        return _Constraints(y_edges=((subject, target),))
    if relation.kind == "east_of":
        return _Constraints(x_edges=((target, subject),))
    return _Constraints(x_edges=((subject, target),))  # west_of


def _options(relation: Relation) -> list[_Constraints]:
    """The ways a ``next_to`` or ``between`` relation can hold, preferred first."""
    subject = relation.subject
    if relation.kind == "next_to":
        other = relation.objects[0]
        return [
            _Constraints(x_edges=((other, subject),), same_row=((other, subject),)),
            _Constraints(x_edges=((subject, other),), same_row=((other, subject),)),
            _Constraints(y_edges=((other, subject),), same_col=((other, subject),)),
            _Constraints(y_edges=((subject, other),), same_col=((other, subject),)),
        ]
    first, second = relation.objects
    return [
        _Constraints(
            x_edges=((first, subject), (subject, second)),
            same_row=((first, subject), (subject, second)),
        ),
        _Constraints(
            x_edges=((second, subject), (subject, first)),
            same_row=((first, subject), (subject, second)),
        ),
        _Constraints(
            y_edges=((first, subject), (subject, second)),
            same_col=((first, subject), (subject, second)),
        ),
        _Constraints(
            y_edges=((second, subject), (subject, first)),
            same_col=((first, subject), (subject, second)),
        ),
        # (last, on a diagonal: "an orchard in the NE corner, vegetables in the SW corner
        # and a cereal field between them")
        *(
            _Constraints(x_edges=((a, subject), (subject, b)), y_edges=((c, subject), (subject, d)))
            for a, b in ((first, second), (second, first))
            for c, d in ((first, second), (second, first))
        ),
    ]


def _unsatisfiable(relations: Iterable[Relation], why: str = "") -> PromptError:
    listed = "; ".join(f"'{describe_relation(r)}'" for r in relations)
    return PromptError(
        f"the field relations cannot all hold{why}: {listed}",
        stage="layout",
        path="relations",
        hint="drop or change one of these relations (north_of, south_of, east_of, "
        "west_of, next_to, between)",
    )


def _solve_cells(
    component: Sequence[str], relations: Sequence[Relation]
) -> dict[str, tuple[int, int]]:
    """A grid cell per field honouring every relation of the component."""
    strict = _Constraints()
    edge_relation: dict[tuple[str, str, str], Relation] = {}
    choices: list[list[_Constraints]] = []
    next_to: list[tuple[str, str]] = []
    for relation in relations:
        if relation.kind in ("next_to", "between"):
            choices.append(_options(relation))
            if relation.kind == "next_to":
                next_to.append((relation.subject, relation.objects[0]))
        else:
            constraint = _strict(relation)
            strict = strict.plus(constraint)
            for a, b in constraint.x_edges:
                edge_relation[("x", a, b)] = relation
            for a, b in constraint.y_edges:
                edge_relation[("y", a, b)] = relation

    # A cycle among the fixed relations (a north of b north of a) is reported precisely.
    for axis, edges in (("x", strict.x_edges), ("y", strict.y_edges)):
        cycle = _find_cycle(component, edges)
        if cycle:
            involved = [edge_relation[(axis, a, b)] for a, b in cycle]
            raise _unsatisfiable(dict.fromkeys(involved), " (they form a cycle)")

    search = _CellSearch(component, next_to)
    cells = search.run(strict, choices)
    if cells is None:
        raise _unsatisfiable(relations)
    return cells


class _CellSearch:
    """Depth-first search over relation choices and same-cell tie-breaks, with a budget."""

    def __init__(self, component: Sequence[str], next_to: Sequence[tuple[str, str]]) -> None:
        self.component = list(component)
        self.order = {name: index for index, name in enumerate(component)}
        self.next_to = list(next_to)
        self.budget = _SEARCH_BUDGET

    def run(
        self, constraints: _Constraints, choices: Sequence[Sequence[_Constraints]]
    ) -> dict[str, tuple[int, int]] | None:
        self.budget -= 1
        if self.budget < 0:
            return None
        levels = self._levels(constraints)
        if levels is None:
            return None
        if choices:
            for option in choices[0]:
                found = self.run(constraints.plus(option), choices[1:])
                if found is not None:
                    return found
            return None
        collision = self._collision(levels)
        if collision is None:
            return levels if self._neighbours_adjacent(levels) else None
        first, second = collision
        # Two fields landed in one cell: separate them, trying each axis and side.
        for option in (
            _Constraints(x_edges=((first, second),)),
            _Constraints(x_edges=((second, first),)),
            _Constraints(y_edges=((first, second),)),
            _Constraints(y_edges=((second, first),)),
        ):
            found = self.run(constraints.plus(option), ())
            if found is not None:
                return found
        return None

    def _levels(self, constraints: _Constraints) -> dict[str, tuple[int, int]] | None:
        columns = _axis_levels(self.component, constraints.x_edges, constraints.same_col)
        rows = _axis_levels(self.component, constraints.y_edges, constraints.same_row)
        if columns is None or rows is None:
            return None
        return {name: (columns[name], rows[name]) for name in self.component}

    def _collision(self, cells: Mapping[str, tuple[int, int]]) -> tuple[str, str] | None:
        seen: dict[tuple[int, int], str] = {}
        for name in self.component:
            other = seen.get(cells[name])
            if other is not None:
                return other, name
            seen[cells[name]] = name
        return None

    def _neighbours_adjacent(self, cells: Mapping[str, tuple[int, int]]) -> bool:
        """No field sits between two fields that must be next to each other."""
        for a, b in self.next_to:
            (col_a, row_a), (col_b, row_b) = cells[a], cells[b]
            for name in self.component:
                col, row = cells[name]
                if row_a == row_b == row and min(col_a, col_b) < col < max(col_a, col_b):
                    return False
                if col_a == col_b == col and min(row_a, row_b) < row < max(row_a, row_b):
                    return False
        return True


def _axis_levels(
    names: Sequence[str], edges: Sequence[_Edge], equal: Sequence[_Edge]
) -> dict[str, int] | None:
    """Longest-path level of each field along one axis, or None if contradictory.

    Fields bound by ``equal`` share a level; an edge inside such a group, or a
    cycle between groups, is a contradiction.
    """
    groups = _Groups(names)
    find = groups.find
    for a, b in equal:
        groups.join(a, b)
    successors: dict[str, set[str]] = {find(name): set() for name in names}
    for a, b in edges:
        root_a, root_b = find(a), find(b)
        if root_a == root_b:
            return None
        successors[root_a].add(root_b)
    indegree = dict.fromkeys(successors, 0)
    for targets in successors.values():
        for target in targets:
            indegree[target] += 1
    level = dict.fromkeys(successors, 0)
    ready = sorted(root for root, count in indegree.items() if count == 0)
    visited = 0
    while ready:
        root = ready.pop()
        visited += 1
        for target in sorted(successors[root]):
            level[target] = max(level[target], level[root] + 1)
            indegree[target] -= 1
            if indegree[target] == 0:
                ready.append(target)
    if visited != len(successors):
        return None
    return {name: level[find(name)] for name in names}


def _find_cycle(names: Sequence[str], edges: Sequence[_Edge]) -> list[_Edge]:
    """The edges of one directed cycle, or [] when there is none."""
    successors: dict[str, list[str]] = {name: [] for name in names}
    for a, b in edges:
        successors[a].append(b)
    state = dict.fromkeys(names, 0)  # 0 new, 1 on the current path, 2 done
    path: list[str] = []

    def visit(name: str) -> list[_Edge]:
        state[name] = 1
        path.append(name)
        for target in successors[name]:
            if state[target] == 1:
                loop = [*path[path.index(target) :], target]
                return list(itertools.pairwise(loop))
            if state[target] == 0:
                found = visit(target)
                if found:
                    return found
        path.pop()
        state[name] = 2
        return []

    for name in names:
        if state[name] == 0:
            found = visit(name)
            if found:
                return found
    return []


# --- geometry -----------------------------------------------------------------------------------


@dataclass(frozen=True)
class _Block:
    """Fields of one component with origins relative to the block's south-west corner."""

    offsets: dict[str, tuple[float, float]]
    width_m: float
    length_m: float


def _grid_block(
    component: Sequence[str],
    cells: Mapping[str, tuple[int, int]],
    sizes: Mapping[str, tuple[float, float]],
    gap_m: float,
) -> _Block:
    columns = 1 + max(col for col, _ in cells.values())
    rows = 1 + max(row for _, row in cells.values())
    widths = [0.0] * columns
    lengths = [0.0] * rows
    for name in component:
        col, row = cells[name]
        widths[col] = max(widths[col], sizes[name][0])
        lengths[row] = max(lengths[row], sizes[name][1])
    col_x = [sum(widths[:col]) + gap_m * col for col in range(columns)]
    row_y = [sum(lengths[:row]) + gap_m * row for row in range(rows)]
    offsets = {name: (col_x[cells[name][0]], row_y[cells[name][1]]) for name in component}
    return _Block(
        offsets=offsets,
        width_m=col_x[-1] + widths[-1],
        length_m=row_y[-1] + lengths[-1],
    )


def _shelf_pack(blocks: Sequence[_Block], gap_m: float) -> dict[str, tuple[float, float]]:
    """Blocks left to right in shelves of about the square root of the total area."""
    if not blocks:
        return {}
    area = sum((b.width_m + gap_m) * (b.length_m + gap_m) for b in blocks)
    shelf_width = max(math.sqrt(area), max(b.width_m for b in blocks))
    origins: dict[str, tuple[float, float]] = {}
    x = y = shelf_length = 0.0
    for block in blocks:
        if x > 0.0 and x + block.width_m > shelf_width:
            x, y, shelf_length = 0.0, y + shelf_length + gap_m, 0.0
        for name, (dx, dy) in block.offsets.items():
            origins[name] = (x + dx, y + dy)
        x += block.width_m + gap_m
        shelf_length = max(shelf_length, block.length_m)
    return origins
