"""Static check of generated Unreal editor Python against the UE 5.6 API stub index.

:func:`check_script` parses a script with :mod:`ast` and follows, per
function, which local names hold which ``unreal`` types:

- ``unreal.X(...)`` makes an ``X``; ``unreal.X.cast(obj)`` an ``X``;
  ``get_editor_subsystem(unreal.X)`` / ``spawn_actor_from_class(unreal.X, ...)``
  an ``X`` (a class argument specialises a base-class or type-variable return);
- a method call or property read gives the stub's return annotation
  (``Optional[...]`` stripped, ``Array[T][i]`` gives ``T``, ``Tuple[A, B]`` unpacks);
- parameters and returns annotated ``unreal.X`` in the script's own functions
  carry ``X`` into and out of them; ``with ... as task`` uses ``__enter__``.

Then every ``unreal.X`` must exist in the stub and be on the allow-list; every
member used on a known type must exist (inherited ones included), with keyword
names that are real parameters, a positional count the signature takes, and
all required arguments; ``set_editor_property``/``get_editor_property`` names
must be editor properties of the class. A call on an ``unreal`` value whose
type could not be followed is only accepted for member names on an explicit
allow-list (and must exist on some stub class). Values that never came from
``unreal`` (plain Python) are not checked.
"""

from __future__ import annotations

import ast
from collections.abc import Iterable, Iterator
from dataclasses import dataclass, field

from unreal_stub_index import Member, StubIndex, split_top_level

__all__ = ["ApiReport", "check_script", "policy_problems"]


@dataclass(frozen=True)
class _Type:
    """A followed type: an unreal class object ("class"), an instance ("object"),
    an Array ("array") or tuple ("tuple") of types, a module function ("function"),
    a member read off a class or object ("bound"), or an unreal value of unknown
    type ("unknown"). ``None`` stands for plain Python values."""

    kind: str
    name: str = ""
    items: tuple[_Type | None, ...] = ()


_UNKNOWN = _Type("unknown")


@dataclass
class ApiReport:
    """What a script uses of the ``unreal`` module, and every problem found."""

    problems: list[str] = field(default_factory=list)
    #: ``unreal.X`` names referenced.
    names: set[str] = field(default_factory=set)
    #: ``(class, member)`` pairs used on values of known type (the class they were used on).
    members: set[tuple[str, str]] = field(default_factory=set)
    #: Member names used on unreal values whose type was not followed.
    untracked: set[str] = field(default_factory=set)

    def problem(self, node: ast.AST, message: str) -> None:
        """Record a problem at ``node``'s line."""
        self.problems.append(f"line {getattr(node, 'lineno', '?')}: {message}")


def _strip_optional(annotation: str) -> str:
    text = annotation.strip()
    while text.startswith("Optional[") and text.endswith("]"):
        text = text[len("Optional[") : -1].strip()
    return text


class _Checker:
    def __init__(
        self,
        index: StubIndex,
        allowed_names: frozenset[str],
        allowed_untracked: frozenset[str],
        report: ApiReport,
    ) -> None:
        self.index = index
        self.allowed_names = allowed_names
        self.allowed_untracked = allowed_untracked
        self.report = report
        self.functions: dict[str, tuple[dict[str, _Type | None], _Type | None]] = {}
        self.memo: dict[int, _Type | None] = {}

    # -- types -------------------------------------------------------------

    def parse_annotation(self, text: str, bound: str | None = None) -> _Type | None:
        """A stub return annotation as a followed type (None for plain Python values)."""
        text = _strip_optional(text)
        if not text or text in ("None", "bool", "int", "float", "str"):
            return None
        if text in ("_T",) and bound:
            return _Type("object", bound)
        head, _, rest = text.partition("[")
        if rest.endswith("]"):
            inner = rest[:-1]
            if head == "Array":
                return _Type("array", items=(self.parse_annotation(inner),))
            if head in ("Tuple", "tuple"):
                return _Type(
                    "tuple", items=tuple(self.parse_annotation(p) for p in split_top_level(inner))
                )
            return _UNKNOWN
        if text in self.index.classes:
            return _Type("object", text)
        return _UNKNOWN

    def script_annotation(self, node: ast.expr | None) -> _Type | None:
        """An annotation in the script: ``unreal.X`` (or a string of it) is followed.

        A missing annotation or ``Any`` may hide an unreal value: its type is unknown,
        so members used on it must be on the untracked allow-list.
        """
        if node is None or (isinstance(node, ast.Name) and node.id == "Any"):
            return _UNKNOWN
        if isinstance(node, ast.Constant) and isinstance(node.value, str):
            try:
                node = ast.parse(node.value, mode="eval").body
            except SyntaxError:
                return None
        if _is_unreal_attribute(node):
            assert isinstance(node, ast.Attribute)
            return _Type("object", node.attr)
        if isinstance(node, ast.BinOp) and isinstance(node.op, ast.BitOr):
            return self.script_annotation(node.left) or self.script_annotation(node.right)
        return None

    # -- walking -----------------------------------------------------------

    def collect_functions(self, tree: ast.Module) -> None:
        for node in tree.body:
            if isinstance(node, ast.FunctionDef):
                params = {
                    arg.arg: self.script_annotation(arg.annotation)
                    for arg in [*node.args.posonlyargs, *node.args.args, *node.args.kwonlyargs]
                }
                self.functions[node.name] = (params, self.script_annotation(node.returns))

    def run(self, tree: ast.Module) -> None:
        self.collect_functions(tree)
        module_env: dict[str, _Type | None] = {}
        self.block(tree.body, module_env)
        for node in tree.body:
            if isinstance(node, ast.FunctionDef):
                params, _ = self.functions[node.name]
                self.block(node.body, dict(params))

    def block(self, statements: Iterable[ast.stmt], env: dict[str, _Type | None]) -> None:
        for statement in statements:
            self.statement(statement, env)

    def statement(self, node: ast.stmt, env: dict[str, _Type | None]) -> None:
        if isinstance(node, ast.FunctionDef | ast.AsyncFunctionDef | ast.ClassDef):
            return  # module-level functions are walked with their own environment
        if isinstance(node, ast.Assign):
            value = self.infer(node.value, env)
            for target in node.targets:
                self.bind(target, value, env)
        elif isinstance(node, ast.AnnAssign):
            declared = self.script_annotation(node.annotation)
            value = self.infer(node.value, env) if node.value is not None else None
            self.bind(node.target, declared or value, env)
        elif isinstance(node, ast.With):
            for item in node.items:
                context = self.infer(item.context_expr, env)
                entered: _Type | None = None
                if context is not None and context.kind == "object":
                    member = self.index.member(context.name, "__enter__")
                    if member is None:
                        self.report.problem(node, f"{context.name} is not a context manager")
                    else:
                        entered = self.parse_annotation(member.returns, context.name)
                if item.optional_vars is not None:
                    self.bind(item.optional_vars, entered, env)
            self.block(node.body, env)
            return
        elif isinstance(node, ast.For):
            self.infer(node.iter, env)
            self.bind(node.target, None, env)
            self.block(node.body, env)
            self.block(node.orelse, env)
            return
        elif isinstance(node, ast.If | ast.While):
            self.infer(node.test, env)
            self.block(node.body, env)
            self.block(node.orelse, env)
            return
        elif isinstance(node, ast.Try):
            self.block(node.body, env)
            for handler in node.handlers:
                self.block(handler.body, env)
            self.block(node.orelse, env)
            self.block(node.finalbody, env)
            return
        # Anything else (expressions, returns, raises, augmented assignments):
        # check every expression in it.
        for child in _expressions(node):
            self.infer(child, env)

    def bind(self, target: ast.expr, value: _Type | None, env: dict[str, _Type | None]) -> None:
        if isinstance(target, ast.Name):
            env[target.id] = value
        elif isinstance(target, ast.Tuple | ast.List):
            items: tuple[_Type | None, ...] = ()
            if value is not None and value.kind == "tuple":
                items = value.items
            for position, element in enumerate(target.elts):
                element_type: _Type | None = None
                if position < len(items):
                    element_type = items[position]
                elif value is not None and value.kind == "unknown":
                    element_type = _UNKNOWN
                self.bind(element, element_type, env)
        elif isinstance(target, ast.Attribute):
            owner = self.infer(target.value, env)
            self.check_attribute_write(target, owner)
        elif isinstance(target, ast.Subscript):
            self.infer(target.value, env)
            self.infer(target.slice, env)

    # -- expressions -------------------------------------------------------

    def infer(self, node: ast.expr | None, env: dict[str, _Type | None]) -> _Type | None:
        if node is None:
            return None
        key = id(node)
        if key in self.memo:
            return self.memo[key]
        result = self._infer(node, env)
        self.memo[key] = result
        return result

    def _infer(self, node: ast.expr, env: dict[str, _Type | None]) -> _Type | None:
        if isinstance(node, ast.Name):
            return env.get(node.id)
        if _is_unreal_attribute(node):
            assert isinstance(node, ast.Attribute)
            return self.unreal_name(node)
        if isinstance(node, ast.Attribute):
            owner = self.infer(node.value, env)
            return self.read_attribute(node, owner)
        if isinstance(node, ast.Call):
            return self.call(node, env)
        if isinstance(node, ast.Subscript):
            container = self.infer(node.value, env)
            self.infer(node.slice, env)
            if container is None:
                return None
            if container.kind == "array":
                return container.items[0] if container.items else _UNKNOWN
            if container.kind == "tuple" and isinstance(node.slice, ast.Constant):
                position = node.slice.value
                if isinstance(position, int) and -len(container.items) <= position < len(
                    container.items
                ):
                    return container.items[position]
            return _UNKNOWN
        if isinstance(node, ast.Lambda):
            return None
        for child in ast.iter_child_nodes(node):
            if isinstance(child, ast.expr):
                self.infer(child, env)
            elif isinstance(child, ast.comprehension):
                self.infer(child.iter, env)
                for condition in child.ifs:
                    self.infer(condition, env)
        return None

    def unreal_name(self, node: ast.Attribute) -> _Type | None:
        name = node.attr
        self.report.names.add(name)
        if name not in self.index:
            self.report.problem(node, f"unreal.{name} does not exist in the UE 5.6 API")
            return _UNKNOWN
        if name not in self.allowed_names:
            self.report.problem(node, f"unreal.{name} is not on the allow-list")
        if name in self.index.classes:
            return _Type("class", name)
        return _Type("function", name)

    def lookup(self, node: ast.AST, class_name: str, member_name: str) -> Member | None:
        member = self.index.member(class_name, member_name)
        if member is None:
            self.report.problem(
                node, f"{class_name} has no member {member_name!r} in the UE 5.6 API"
            )
            return None
        self.report.members.add((class_name, member_name))
        return member

    def read_attribute(self, node: ast.Attribute, owner: _Type | None) -> _Type | None:
        if owner is None:
            return None
        if owner.kind == "unknown":
            return self.untracked(node, node.attr)
        if owner.kind in ("class", "object"):
            member = self.lookup(node, owner.name, node.attr)
            if member is None:
                return _UNKNOWN
            if member.kind in ("property", "attribute"):
                return self.parse_annotation(member.returns, owner.name)
            if owner.kind == "object" and member.kind in ("classmethod", "staticmethod"):
                return _Type("bound", owner.name)
            return _Type("bound", owner.name)
        return _UNKNOWN

    def check_attribute_write(self, node: ast.Attribute, owner: _Type | None) -> None:
        if owner is None:
            return
        if owner.kind == "unknown":
            self.untracked(node, node.attr)
            return
        if owner.kind == "object":
            member = self.lookup(node, owner.name, node.attr)
            if member is not None and not (member.kind == "property" and member.writable):
                self.report.problem(node, f"{owner.name}.{node.attr} is not a writable property")

    def untracked(self, node: ast.AST, member_name: str) -> _Type:
        self.report.untracked.add(member_name)
        if member_name not in self.index.method_names:
            self.report.problem(node, f"{member_name!r} exists on no class of the UE 5.6 API")
        elif member_name not in self.allowed_untracked:
            self.report.problem(
                node,
                f"{member_name!r} is called on an unreal value whose type was not followed "
                "and is not on the untracked allow-list",
            )
        return _UNKNOWN

    def call(self, node: ast.Call, env: dict[str, _Type | None]) -> _Type | None:
        arguments = [self.infer(arg, env) for arg in node.args]
        for keyword in node.keywords:
            self.infer(keyword.value, env)
        keywords = tuple(k.arg for k in node.keywords if k.arg is not None)
        func = node.func
        first_class = (
            arguments[0].name
            if arguments and arguments[0] and arguments[0].kind == "class"
            else None
        )
        if _is_unreal_attribute(func):
            assert isinstance(func, ast.Attribute)
            target = self.unreal_name(func)
            if target is None or target.kind == "unknown":
                return _UNKNOWN
            if target.kind == "function":
                member = self.index.functions[target.name]
                self.check_arguments(node, f"unreal.{target.name}", member, keywords)
                return self.returned(member, target.name, first_class)
            constructor = self.index.member(target.name, "__init__")
            if constructor is not None:
                self.check_arguments(node, f"unreal.{target.name}", constructor, keywords)
            return _Type("object", target.name)
        if isinstance(func, ast.Attribute):
            owner = self.infer(func.value, env)
            if owner is None:
                return None
            if owner.kind == "unknown":
                return self.untracked(func, func.attr)
            if owner.kind not in ("class", "object"):
                return _UNKNOWN
            member = self.lookup(func, owner.name, func.attr)
            self.memo[id(func)] = _Type("bound", owner.name)
            if member is None:
                return _UNKNOWN
            if member.kind in ("property", "attribute"):
                self.report.problem(func, f"{owner.name}.{func.attr} is a property, not callable")
                return _UNKNOWN
            if owner.kind == "class" and member.kind == "method":
                self.report.problem(
                    func, f"{owner.name}.{func.attr} is an instance method called on the class"
                )
            self.check_arguments(node, f"{owner.name}.{func.attr}", member, keywords)
            if func.attr in ("set_editor_property", "get_editor_property") and node.args:
                self.check_editor_property(node, owner.name)
            return self.returned(member, owner.name, first_class)
        if isinstance(func, ast.Name) and func.id in self.functions:
            return self.functions[func.id][1]
        self.infer(func, env)
        return None

    def returned(self, member: Member, owner: str, first_class: str | None) -> _Type | None:
        annotation = _strip_optional(member.returns)
        # get_editor_subsystem(unreal.X) -> X; spawn_actor_from_class(unreal.X) -> X.
        if first_class is not None and (
            annotation.startswith("_")
            or (
                annotation in self.index.classes and self.index.is_subclass(first_class, annotation)
            )
        ):
            return _Type("object", first_class)
        return self.parse_annotation(member.returns, owner)

    def check_arguments(
        self, node: ast.Call, label: str, member: Member, keywords: tuple[str, ...]
    ) -> None:
        if any(isinstance(arg, ast.Starred) for arg in node.args) or any(
            k.arg is None for k in node.keywords
        ):
            self.report.problem(node, f"{label}() is called with * or ** unpacking (uncheckable)")
            return
        for message in member.check_call(len(node.args), keywords):
            self.report.problem(node, f"{label}: {message}")

    def check_editor_property(self, node: ast.Call, class_name: str) -> None:
        name_node = node.args[0]
        if not (isinstance(name_node, ast.Constant) and isinstance(name_node.value, str)):
            self.report.problem(node, "editor property names must be string literals")
            return
        if self.index.editor_property(class_name, name_node.value) is None:
            self.report.problem(
                node, f"{class_name} has no editor property {name_node.value!r} in the UE 5.6 API"
            )


def _is_unreal_attribute(node: ast.AST) -> bool:
    return (
        isinstance(node, ast.Attribute)
        and isinstance(node.value, ast.Name)
        and node.value.id == "unreal"
    )


def _expressions(node: ast.stmt) -> Iterator[ast.expr]:
    for child in ast.iter_child_nodes(node):
        if isinstance(child, ast.expr):
            yield child


def check_script(
    source: str,
    index: StubIndex,
    *,
    allowed_names: frozenset[str],
    allowed_untracked: frozenset[str] = frozenset(),
    banned_names: frozenset[str] = frozenset(),
) -> ApiReport:
    """Check ``source`` against the stub index; the report lists problems and what is used."""
    report = ApiReport()
    tree = ast.parse(source)
    for node in ast.walk(tree):
        identifier = None
        if isinstance(node, ast.Attribute):
            identifier = node.attr
        elif isinstance(node, ast.Name):
            identifier = node.id
        elif isinstance(node, ast.FunctionDef):
            identifier = node.name
        if identifier in banned_names:
            report.problem(node, f"{identifier!r} does not exist in UE 5.6 (engines.md)")
    _Checker(index, allowed_names, allowed_untracked, report).run(tree)
    return report


def policy_problems(source: str) -> list[str]:
    """Project rules beyond the API (engines.md): ``Rotator`` only by keyword, and
    ``add_instances(transforms, False, world_space=...)`` with no other positional
    argument (older engines lack the later parameters)."""
    problems: list[str] = []
    for node in ast.walk(ast.parse(source)):
        if not isinstance(node, ast.Call) or not isinstance(node.func, ast.Attribute):
            continue
        keywords = {k.arg for k in node.keywords}
        if _is_unreal_attribute(node.func) and node.func.attr == "Rotator" and node.args:
            problems.append(f"line {node.lineno}: unreal.Rotator takes roll first: use keywords")
        if node.func.attr == "add_instances" and (
            len(node.args) != 2 or keywords != {"world_space"}
        ):
            problems.append(
                f"line {node.lineno}: add_instances must be (transforms, False, world_space=...)"
            )
    return problems
