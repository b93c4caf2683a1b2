"""The Unreal API surface generated scripts may use, and names they must never use."""

from __future__ import annotations

__all__ = ["ALLOWED_NAMES", "ALLOWED_UNTRACKED_MEMBERS", "BANNED_NAMES"]

#: Every ``unreal.X`` a generated script may reference. Anything else fails.
ALLOWED_NAMES = frozenset(
    {
        # scopes
        "ScopedEditorTransaction",
        "ScopedSlowTask",
        # value types
        "Vector",
        "Rotator",
        "Transform",
        "LinearColor",
        "CollisionEnabled",
        # actors and components
        "Actor",
        "StaticMeshActor",
        "DirectionalLight",
        "SkyAtmosphere",
        "SkyLight",
        "StaticMeshComponent",
        "InstancedStaticMeshComponent",
        "DirectionalLightComponent",
        # subsystems and libraries
        "EditorActorSubsystem",
        "LevelEditorSubsystem",
        "SubobjectDataSubsystem",
        "AddNewSubobjectParams",
        "SubobjectDataBlueprintFunctionLibrary",
        "EditorAssetLibrary",
        "AssetToolsHelpers",
        "AssetImportTask",
        # assets
        "StaticMesh",
        "MaterialInterface",
        # module functions
        "get_editor_subsystem",
        "get_engine_subsystem",
        "load_asset",
        "log",
        "log_warning",
        "log_error",
    }
)

#: Members that may be used on an ``unreal`` value whose type the checker could
#: not follow. Empty: every call in the generated scripts is type-checked.
ALLOWED_UNTRACKED_MEMBERS: frozenset[str] = frozenset()

#: Names public scripts use that do not exist in UE 5.6, or are deprecated
#: (reference/engines.md). They must never appear in a generated script.
BANNED_NAMES = frozenset(
    {
        "add_component_by_class",
        "add_instance_component",
        "register_component",
        "get_root_component",
        "InstancedStaticMeshActor",
        "LandscapeEditorSubsystem",
        "EditorLevelLibrary",
    }
)
