"""A recording fake of Unreal's ``unreal`` module, for executing generated scripts here.

:func:`make_fake_unreal` builds a fresh module object (put it in
``sys.modules["unreal"]`` while a script runs) and the :class:`Recording` it
writes to. It implements exactly the surface the generated scripts use, with
the UE 5.6 names and parameter names (a test checks every class, base, method,
property and parameter against the API stub), and behaves like the editor
where it matters for placement:

- a plain ``Actor`` has no root component, so its spawn location is lost and
  ``set_actor_location`` does nothing until a component becomes its root;
- a component added through the ``SubobjectDataSubsystem`` becomes the root of
  an actor without one;
- ``add_instances(..., world_space=True)`` stores instances relative to the
  component (the actor's location subtracted), as the engine does;
- ``EditorAssetLibrary`` knows only the project assets it was given and those
  imported while the script runs; engine basic shapes and
  ``BasicShapeMaterial`` always load;
- ``AssetTools.import_asset_tasks`` imports a glTF binary the way Interchange
  does: it reads the file (failing on anything that is not glTF 2.0), names the
  static mesh after the file's first mesh (Interchange ignores
  ``destination_name``), creates one material asset per glTF material, and
  fills ``imported_object_paths``;
- every state change is recorded with the transaction and slow-task depth it
  happened at; ``should_cancel`` turns true after a given number of progress
  frames.

State the tests read is kept in underscore attributes, outside the API surface.
"""

from __future__ import annotations

import json
import struct
import sys
import types
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

__all__ = [
    "ENGINE_ASSETS",
    "SUPPORT_TYPES",
    "Event",
    "Recording",
    "make_fake_unreal",
    "run_script",
]

#: Engine content the fake can load (UE ships these with every project).
ENGINE_ASSETS = {
    "/Engine/BasicShapes/Cube.Cube": "StaticMesh",
    "/Engine/BasicShapes/Cone.Cone": "StaticMesh",
    "/Engine/BasicShapes/Cylinder.Cylinder": "StaticMesh",
    "/Engine/BasicShapes/Sphere.Sphere": "StaticMesh",
    "/Engine/BasicShapes/Plane.Plane": "StaticMesh",
    "/Engine/BasicShapes/BasicShapeMaterial.BasicShapeMaterial": "MaterialInterface",
}

#: Classes the fake defines because scripts receive their instances (or because
#: they declare the members scripts use) without naming them as ``unreal.X``.
SUPPORT_TYPES = frozenset(
    {
        "Object",
        "Info",
        "Light",
        "ActorComponent",
        "SceneComponent",
        "PrimitiveComponent",
        "MeshComponent",
        "LightComponentBase",
        "LightComponent",
        "SkyLightComponent",
        "EditorSubsystem",
        "EngineSubsystem",
        "BlueprintFunctionLibrary",
        "MaterialInstanceDynamic",
        "StructBase",
        "EnumBase",
        "SubobjectDataHandle",
        "SubobjectData",
        "Text",
        "Interface",
        "AssetTools",
    }
)


@dataclass(frozen=True)
class Event:
    """One recorded state change."""

    kind: str
    target: Any
    details: tuple[Any, ...]
    transaction_depth: int
    slow_task_depth: int


@dataclass
class Recording:
    """Everything a script did to the fake editor."""

    project_assets: frozenset[str] = frozenset()
    cancel_after_frames: int | None = None
    imported: dict[str, str] = field(default_factory=dict)  # object path -> asset kind
    import_tasks: list[dict[str, Any]] = field(default_factory=list)
    events: list[Event] = field(default_factory=list)
    actors: list[Any] = field(default_factory=list)
    logs: list[tuple[str, str]] = field(default_factory=list)
    transactions: list[str] = field(default_factory=list)
    slow_tasks: list[Any] = field(default_factory=list)
    frames: list[tuple[float, str]] = field(default_factory=list)
    transaction_depth: int = 0
    slow_task_depth: int = 0

    def record(self, kind: str, target: Any, *details: Any) -> None:
        """Note a state change at the current transaction and slow-task depth."""
        self.events.append(
            Event(kind, target, details, self.transaction_depth, self.slow_task_depth)
        )

    def warnings(self) -> list[str]:
        """Messages logged with ``unreal.log_warning``."""
        return [message for level, message in self.logs if level == "warning"]

    def errors(self) -> list[str]:
        """Messages logged with ``unreal.log_error``."""
        return [message for level, message in self.logs if level == "error"]

    def actors_of(self, class_name: str) -> list[Any]:
        """Spawned actors whose class has exactly this name."""
        return [actor for actor in self.actors if type(actor).__name__ == class_name]


def make_fake_unreal(
    *, project_assets: frozenset[str] = frozenset(), cancel_after_frames: int | None = None
) -> tuple[types.ModuleType, Recording]:
    """A fresh fake ``unreal`` module and the recording it writes to.

    ``project_assets`` are the object paths ``EditorAssetLibrary`` finds (as
    static meshes); ``cancel_after_frames`` makes ``should_cancel`` return True
    once that many progress frames were entered.
    """
    recording = Recording(
        project_assets=frozenset(project_assets), cancel_after_frames=cancel_after_frames
    )
    module = types.ModuleType("unreal", "Recording fake of Unreal's Python API (tests only).")
    for name, value in _define(recording).items():
        setattr(module, name, value)
    return module, recording


def run_script(
    source: str,
    *,
    project_assets: frozenset[str] = frozenset(),
    cancel_after_frames: int | None = None,
) -> tuple[dict[str, Any], Recording]:
    """Execute a generated script with a fresh fake as ``unreal``; return its namespace.

    The script's ``import unreal`` finds the fake through ``sys.modules``; the
    previous entry (if any) is restored afterwards.
    """
    module, recording = make_fake_unreal(
        project_assets=project_assets, cancel_after_frames=cancel_after_frames
    )
    previous = sys.modules.get("unreal")
    sys.modules["unreal"] = module
    namespace: dict[str, Any] = {"__name__": "__main__"}
    try:
        exec(compile(source, "unreal_build.py", "exec"), namespace)
    finally:
        if previous is None:
            sys.modules.pop("unreal", None)
        else:
            sys.modules["unreal"] = previous
    return namespace, recording


def _require(condition: bool, message: str) -> None:
    # The engine raises TypeError/ValueError on bad arguments; so does the fake.
    if not condition:
        raise TypeError(message)


def _define(recording: Recording) -> dict[str, Any]:
    """Define the fake's classes and functions bound to ``recording``."""
    serial = iter(range(1, 1_000_000_000))

    class StructBase:
        """Base of value types (UE ``StructBase``)."""

    class Vector(StructBase):
        """A 3D vector (cm)."""

        def __init__(self, x: float = 0.0, y: float = 0.0, z: float = 0.0) -> None:
            self.x, self.y, self.z = float(x), float(y), float(z)

        def __repr__(self) -> str:
            return f"Vector({self.x}, {self.y}, {self.z})"

    class Rotator(StructBase):
        """A rotation in degrees; UE 5's Python constructor takes roll first."""

        def __init__(self, roll: float = 0.0, pitch: float = 0.0, yaw: float = 0.0) -> None:
            self.roll, self.pitch, self.yaw = float(roll), float(pitch), float(yaw)

    class LinearColor(StructBase):
        """A linear RGBA colour."""

        def __init__(self, r: float = 0.0, g: float = 0.0, b: float = 0.0, a: float = 0.0) -> None:
            self.r, self.g, self.b, self.a = float(r), float(g), float(b), float(a)

    class Transform(StructBase):
        """Location, rotation and scale."""

        def __init__(self, location: Any = None, rotation: Any = None, scale: Any = None) -> None:
            location = Vector() if location is None else location
            rotation = Rotator() if rotation is None else rotation
            scale = Vector(1.0, 1.0, 1.0) if scale is None else scale
            _require(isinstance(location, Vector), "Transform location must be a Vector")
            _require(isinstance(rotation, Rotator), "Transform rotation must be a Rotator here")
            _require(isinstance(scale, Vector), "Transform scale must be a Vector")
            self._location, self._rotation, self._scale = location, rotation, scale

    class Text:
        """Localised text (UE ``Text``)."""

        def __init__(self, value: str = "") -> None:
            self._value = str(value)

        def is_empty(self) -> bool:
            return not self._value

        def __str__(self) -> str:
            return self._value

    class EnumBase:
        """Base of UE enums."""

        def __init__(self) -> None:
            self._name = ""

    class CollisionEnabled(EnumBase):
        """Which collision a body has."""

    no_collision = CollisionEnabled()
    no_collision._name = "NO_COLLISION"
    CollisionEnabled.NO_COLLISION = no_collision  # type: ignore[attr-defined]

    class Object:
        """Base of UE objects."""

        def __init__(self, outer: Any = None, name: str = "None") -> None:
            self._outer = outer
            self._object_name = f"{type(self).__name__}_{next(serial)}" if name == "None" else name

        @classmethod
        def cast(cls, object: Any) -> Any:
            if not isinstance(object, cls):
                raise TypeError(f"cannot cast {type(object).__name__} to {cls.__name__}")
            return object

    # -- assets ---------------------------------------------------------------

    class StaticMesh(Object):
        """A static mesh asset."""

    class MaterialInterface(Object):
        """A material asset."""

    class MaterialInstanceDynamic(MaterialInterface):
        """A material instance made at edit time on a component."""

        def set_vector_parameter_value(self, parameter_name: str, value: Any) -> None:
            _require(isinstance(value, LinearColor), "value must be a LinearColor")
            self._vectors[str(parameter_name)] = value
            recording.record("material_vector", self, str(parameter_name), value)

    class Interface(Object):
        """Base of UE interfaces."""

    task_properties = {
        "async_": False,
        "automated": False,
        "destination_name": "",
        "destination_path": "",
        "factory": None,
        "filename": "",
        "imported_object_paths": [],
        "options": None,
        "replace_existing": True,
        "replace_existing_settings": False,
        "result": [],
        "save": True,
    }

    class AssetImportTask(Object):
        """One file to import (editor properties only, like the engine's)."""

        def __init__(self, outer: Any = None, name: str = "None") -> None:
            super().__init__(outer, name)
            self._properties = dict(task_properties)

        def get_editor_property(self, name: Any) -> object:
            _require(str(name) in self._properties, f"AssetImportTask has no property {name}")
            return self._properties[str(name)]

        def set_editor_property(self, name: Any, value: object, notify_mode: Any = None) -> None:
            _require(str(name) in self._properties, f"AssetImportTask has no property {name}")
            self._properties[str(name)] = value

    def _read_glb(filename: str) -> dict[str, Any]:
        data = Path(filename).read_bytes()
        magic, version, length = struct.unpack_from("<III", data)
        _require(magic == 0x46546C67 and version == 2, f"{filename} is not glTF 2.0 binary")
        _require(length == len(data), f"{filename} is truncated")
        chunk_length, chunk_type = struct.unpack_from("<II", data, 12)
        _require(chunk_type == 0x4E4F534A, f"{filename} has no JSON chunk")
        document: dict[str, Any] = json.loads(data[20 : 20 + chunk_length])
        return document

    class AssetTools(Interface):
        """The editor's asset tools (only file import)."""

        def import_asset_tasks(self, import_tasks: Any) -> None:
            for task in import_tasks:
                _require(isinstance(task, AssetImportTask), "import_tasks holds AssetImportTasks")
                properties = task._properties
                filename = str(properties["filename"])
                folder = str(properties["destination_path"])
                _require(folder.startswith("/Game/"), "destination_path must be under /Game/")
                document = _read_glb(filename)  # the engine logs an error and imports nothing
                mesh_name = document["meshes"][0]["name"]
                paths = [f"{folder}/{mesh_name}.{mesh_name}"]
                recording.imported[paths[0]] = "StaticMesh"
                for material in document.get("materials", []):
                    material_path = f"{folder}/MI_{material['name']}.MI_{material['name']}"
                    recording.imported[material_path] = "MaterialInterface"
                    paths.append(material_path)
                properties["imported_object_paths"] = paths
                recording.import_tasks.append(dict(properties))
                recording.record("import", task, filename, folder, mesh_name)

    class AssetToolsHelpers(Object):
        """Access to the editor's asset tools."""

        @classmethod
        def get_asset_tools(cls) -> Any:
            return subsystems.setdefault(AssetTools, AssetTools())

    def _asset(path: str, kind: str) -> Object:
        asset: Object = StaticMesh() if kind == "StaticMesh" else MaterialInterface()
        asset._path = path  # type: ignore[attr-defined]
        return asset

    # -- components -------------------------------------------------------------

    class ActorComponent(Object):
        """A component of an actor."""

        def __init__(self, outer: Any = None, name: str = "None") -> None:
            super().__init__(outer, name)
            self._owner: Any = None

    class SceneComponent(ActorComponent):
        """A component with a transform."""

    class PrimitiveComponent(SceneComponent):
        """A component that renders or collides."""

        def __init__(self, outer: Any = None, name: str = "None") -> None:
            super().__init__(outer, name)
            self._collision: Any = None
            self._materials: dict[int, Any] = {}

        def set_collision_enabled(self, new_type: Any) -> None:
            _require(isinstance(new_type, CollisionEnabled), "new_type must be CollisionEnabled")
            self._collision = new_type
            recording.record("collision", self, new_type._name)

        def create_dynamic_material_instance(
            self, element_index: int, source_material: Any = None, optional_name: str = "None"
        ) -> Any:
            _require(isinstance(element_index, int), "element_index must be an int")
            _require(
                isinstance(source_material, MaterialInterface),
                "source_material must be a MaterialInterface",
            )
            instance = MaterialInstanceDynamic(self, optional_name)
            instance._parent = source_material  # type: ignore[attr-defined]
            instance._vectors = {}  # type: ignore[attr-defined]
            self._materials[element_index] = instance
            recording.record("material_instance", self, element_index, source_material)
            return instance

    class MeshComponent(PrimitiveComponent):
        """A component drawing a mesh."""

    class StaticMeshComponent(MeshComponent):
        """A component drawing one static mesh."""

        def __init__(self, outer: Any = None, name: str = "None") -> None:
            super().__init__(outer, name)
            self._mesh: Any = None

        def set_static_mesh(self, new_mesh: Any) -> bool:
            _require(new_mesh is None or isinstance(new_mesh, StaticMesh), "not a StaticMesh")
            self._mesh = new_mesh
            recording.record("static_mesh", self, new_mesh)
            return True

    class InstancedStaticMeshComponent(StaticMeshComponent):
        """Many instances of one static mesh (instances stored component-relative)."""

        def __init__(self, outer: Any = None, name: str = "None") -> None:
            super().__init__(outer, name)
            self._instances: list[Any] = []
            self._add_calls: list[int] = []

        def add_instances(
            self,
            instance_transforms: Any,
            should_return_indices: bool,
            world_space: bool = False,
            update_navigation: bool = True,
        ) -> Any:
            _require(isinstance(should_return_indices, bool), "should_return_indices: bool")
            _require(isinstance(world_space, bool), "world_space must be a bool")
            transforms = list(instance_transforms)
            _require(
                all(isinstance(t, Transform) for t in transforms), "instances must be Transforms"
            )
            _require(self._owner is not None, "the component belongs to no actor")
            first = len(self._instances)
            origin = self._owner._world_location()
            if world_space and (
                self._owner._scale is not None or self._owner._rotation is not None
            ):
                raise NotImplementedError("the fake converts only for unrotated actors")
            for transform in transforms:
                location = transform._location
                if world_space:
                    location = Vector(
                        location.x - origin.x, location.y - origin.y, location.z - origin.z
                    )
                self._instances.append(Transform(location, transform._rotation, transform._scale))
            self._add_calls.append(len(transforms))
            recording.record("add_instances", self, len(transforms), world_space)
            return list(range(first, len(self._instances))) if should_return_indices else []

    class LightComponentBase(SceneComponent):
        """Base of light components."""

    class LightComponent(LightComponentBase):
        """A light component."""

    class DirectionalLightComponent(LightComponent):
        """The component of a DirectionalLight."""

        def __init__(self, outer: Any = None, name: str = "None") -> None:
            super().__init__(outer, name)
            self._atmosphere_sun = False

        def set_atmosphere_sun_light(self, new_value: bool) -> None:
            _require(isinstance(new_value, bool), "new_value must be a bool")
            self._atmosphere_sun = new_value
            recording.record("atmosphere_sun", self, new_value)

    class SkyLightComponent(LightComponentBase):
        """The component of a SkyLight."""

        def __init__(self, outer: Any = None, name: str = "None") -> None:
            super().__init__(outer, name)
            self._real_time_capture = False

        def set_real_time_capture(self, real_time_capture: bool) -> None:
            _require(isinstance(real_time_capture, bool), "real_time_capture must be a bool")
            self._real_time_capture = real_time_capture
            recording.record("real_time_capture", self, real_time_capture)

    # -- actors -----------------------------------------------------------------

    class Actor(Object):
        """A plain actor: no root component until one is added."""

        _default_root: type | None = None

        def __init__(self, outer: Any = None, name: str = "None") -> None:
            super().__init__(outer, name)
            self._label = ""
            self._folder = ""
            self._root: Any = None
            self._components: list[Any] = []
            self._location: Vector | None = None
            self._rotation: Rotator | None = None
            self._scale: Vector | None = None
            if self._default_root is not None:
                self._attach(self._default_root(self))

        def _attach(self, component: Any) -> None:
            component._owner = self
            self._components.append(component)
            if self._root is None:
                self._root = component

        def _world_location(self) -> Vector:
            return self._location if self._location is not None else Vector()

        def set_actor_label(self, new_actor_label: str, mark_dirty: bool = True) -> None:
            _require(isinstance(new_actor_label, str), "new_actor_label must be a str")
            self._label = new_actor_label
            recording.record("label", self, new_actor_label)

        def set_folder_path(self, new_folder_path: str) -> None:
            _require(isinstance(new_folder_path, str), "new_folder_path must be a name")
            self._folder = new_folder_path
            recording.record("folder", self, new_folder_path)

        def set_actor_location(self, new_location: Any, sweep: bool, teleport: bool) -> Any:
            _require(isinstance(new_location, Vector), "new_location must be a Vector")
            _require(isinstance(sweep, bool) and isinstance(teleport, bool), "bools expected")
            if self._root is None:
                recording.record("location_ignored", self, new_location)
                return None
            self._location = new_location
            recording.record("location", self, new_location)
            return None

        def set_actor_scale3d(self, new_scale3d: Any) -> None:
            _require(isinstance(new_scale3d, Vector), "new_scale3d must be a Vector")
            self._scale = new_scale3d
            recording.record("scale", self, new_scale3d)

    class StaticMeshActor(Actor):
        """An actor drawing one static mesh."""

        _default_root = StaticMeshComponent

        @property
        def static_mesh_component(self) -> Any:
            return self._root

    class Light(Actor):
        """Base of light actors."""

        @property
        def light_component(self) -> Any:
            return self._root

    class DirectionalLight(Light):
        """A sun-like light shining along its forward axis."""

        _default_root = DirectionalLightComponent

    class Info(Actor):
        """Base of information actors."""

    class SkyAtmosphere(Info):
        """Physically based sky and atmosphere."""

        _default_root = SceneComponent

    class SkyLight(Info):
        """Ambient light captured from the sky."""

        _default_root = SkyLightComponent

        @property
        def light_component(self) -> Any:
            return self._root

    # -- subsystems and libraries ------------------------------------------------

    class EditorSubsystem(Object):
        """Base of editor subsystems."""

    class EngineSubsystem(Object):
        """Base of engine subsystems."""

    class EditorActorSubsystem(EditorSubsystem):
        """Spawns actors in the editor world."""

        def spawn_actor_from_class(
            self, actor_class: Any, location: Any, rotation: Any = None, transient: bool = False
        ) -> Any:
            _require(
                isinstance(actor_class, type) and issubclass(actor_class, Actor),
                "actor_class must be an Actor class",
            )
            _require(isinstance(location, Vector), "location must be a Vector")
            _require(rotation is None or isinstance(rotation, Rotator), "rotation: Rotator")
            actor = actor_class()
            if actor._root is not None:
                actor._location = location
                if rotation is not None and (rotation.roll, rotation.pitch, rotation.yaw) != (
                    0.0,
                    0.0,
                    0.0,
                ):
                    actor._rotation = rotation
            recording.actors.append(actor)
            recording.record("spawn", actor, actor_class.__name__, location, rotation)
            return actor

    class LevelEditorSubsystem(EditorSubsystem):
        """Level operations of the level editor."""

        def save_current_level(self) -> bool:
            recording.record("save_level", self)
            return True

    class SubobjectDataHandle(StructBase):
        """A handle on an actor or one of its components in the subobject tree."""

        def __init__(self) -> None:
            self._object: Any = None

    class SubobjectData(StructBase):
        """The data behind a subobject handle."""

        def __init__(self) -> None:
            self._object: Any = None

    def _handle(target: Any) -> SubobjectDataHandle:
        handle = SubobjectDataHandle()
        handle._object = target
        return handle

    class AddNewSubobjectParams(StructBase):
        """What ``add_new_subobject`` adds, and under which parent."""

        def __init__(
            self,
            parent_handle: Any = None,
            new_class: Any = None,
            blueprint_context: Any = None,
            skip_mark_blueprint_modified: bool = False,
            conform_transform_to_parent: bool = False,
        ) -> None:
            self._parent_handle = parent_handle
            self._new_class = new_class
            self._blueprint_context = blueprint_context

    class SubobjectDataSubsystem(EngineSubsystem):
        """Adds components to actor instances."""

        def k2_gather_subobject_data_for_instance(self, context: Any) -> Any:
            _require(isinstance(context, Actor), "context must be an Actor")
            return [_handle(context)] + [_handle(c) for c in context._components]

        def add_new_subobject(self, params: Any) -> Any:
            _require(isinstance(params, AddNewSubobjectParams), "params: AddNewSubobjectParams")
            parent = params._parent_handle
            _require(isinstance(parent, SubobjectDataHandle), "parent_handle must be a handle")
            _require(params._blueprint_context is None, "instances take no blueprint_context")
            new_class = params._new_class
            _require(
                isinstance(new_class, type) and issubclass(new_class, ActorComponent),
                "new_class must be a component class",
            )
            owner = parent._object if isinstance(parent._object, Actor) else parent._object._owner
            component = new_class(owner)
            owner._attach(component)
            recording.record("add_component", owner, new_class.__name__)
            return _handle(component), Text("")

    class BlueprintFunctionLibrary(Object):
        """Base of static function libraries."""

    class SubobjectDataBlueprintFunctionLibrary(BlueprintFunctionLibrary):
        """Reads subobject handles."""

        @classmethod
        def get_data(cls, data_handle: Any) -> Any:
            _require(isinstance(data_handle, SubobjectDataHandle), "data_handle: a handle")
            data = SubobjectData()
            data._object = data_handle._object
            return data

        @classmethod
        def get_object(cls, data: Any, even_if_pending_kill: bool = False) -> Any:
            _require(isinstance(data, SubobjectData), "data must be SubobjectData")
            return data._object

    class EditorAssetLibrary(BlueprintFunctionLibrary):
        """Asset queries on the project's content."""

        @classmethod
        def does_asset_exist(cls, asset_path: str) -> bool:
            _require(isinstance(asset_path, str), "asset_path must be a str")
            return asset_path in recording.project_assets or asset_path in recording.imported

        @classmethod
        def load_asset(cls, asset_path: str) -> Any:
            if asset_path in recording.project_assets:
                return _asset(asset_path, "StaticMesh")
            if asset_path in recording.imported:
                return _asset(asset_path, recording.imported[asset_path])
            recording.logs.append(("error", f"LoadAsset failed: {asset_path}"))
            return None

    # -- scopes -----------------------------------------------------------------

    class ScopedEditorTransaction:
        """One undo step around everything done inside it."""

        def __init__(self, desc: str) -> None:
            _require(isinstance(desc, str), "desc must be text")
            self._desc = desc

        def __enter__(self) -> Any:
            recording.transactions.append(self._desc)
            recording.transaction_depth += 1
            recording.record("transaction_begin", self, self._desc)
            return self

        def __exit__(self, type: Any, value: Any, traceback: Any) -> bool:
            recording.record("transaction_end", self, type)
            recording.transaction_depth -= 1
            return False

    class ScopedSlowTask:
        """A progress dialog the user can cancel."""

        def __init__(self, work: float, desc: str = "", enabled: bool = True) -> None:
            _require(isinstance(work, int | float) and work > 0, "work must be positive")
            self._work = float(work)
            self._desc = desc
            self._frames: list[tuple[float, str]] = []
            self._dialog: tuple[bool, bool] | None = None

        def __enter__(self) -> Any:
            recording.slow_tasks.append(self)
            recording.slow_task_depth += 1
            recording.record("slow_task_begin", self, self._work, self._desc)
            return self

        def __exit__(self, type: Any, value: Any, traceback: Any) -> bool:
            recording.record("slow_task_end", self, type)
            recording.slow_task_depth -= 1
            return False

        def make_dialog(self, can_cancel: bool = False, allow_in_pie: bool = False) -> None:
            self._dialog = (can_cancel, allow_in_pie)

        def enter_progress_frame(self, work: float = 1.0, desc: str = "") -> None:
            _require(isinstance(work, int | float) and work >= 0, "work must be >= 0")
            self._frames.append((float(work), desc))
            recording.frames.append((float(work), desc))

        def should_cancel(self) -> bool:
            limit = recording.cancel_after_frames
            return limit is not None and len(recording.frames) >= limit

    # -- module functions ------------------------------------------------------------

    def log(arg: Any) -> None:
        recording.logs.append(("info", str(arg)))

    def log_warning(arg: Any) -> None:
        recording.logs.append(("warning", str(arg)))

    def log_error(arg: Any) -> None:
        recording.logs.append(("error", str(arg)))

    def load_asset(name: str, type: Any = None, follow_redirectors: bool = True) -> Any:
        _require(isinstance(name, str), "name must be a str")
        if name in ENGINE_ASSETS:
            return _asset(name, ENGINE_ASSETS[name])
        if name in recording.project_assets:
            return _asset(name, "StaticMesh")
        recording.logs.append(("warning", f"Failed to find object {name}"))
        return None

    subsystems: dict[type, Any] = {}

    def get_editor_subsystem(subsystem: Any) -> Any:
        _require(issubclass(subsystem, EditorSubsystem), "not an editor subsystem class")
        return subsystems.setdefault(subsystem, subsystem())

    def get_engine_subsystem(subsystem: Any) -> Any:
        _require(issubclass(subsystem, EngineSubsystem), "not an engine subsystem class")
        return subsystems.setdefault(subsystem, subsystem())

    definitions: dict[str, Any] = {
        name: value
        for name, value in locals().items()
        if not name.startswith("_")
        and (isinstance(value, type) or callable(value))
        and name not in ("recording", "serial", "subsystems", "no_collision")
    }
    return definitions
