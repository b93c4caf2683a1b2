"""Engine backends: Unreal Engine 5 scripts, Blender scripts, OpenUSD stages, annotations."""

from agrirecipe.backends._base import Backend
from agrirecipe.backends._registry import available_backends, get_backend, register_backend

__all__ = ["Backend", "available_backends", "get_backend", "register_backend"]
