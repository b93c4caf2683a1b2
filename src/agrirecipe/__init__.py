"""agrirecipe: natural-language requests to agricultural 3D scenes, offline.

>>> from agrirecipe import generate
>>> scene = generate("a healthy Pink Lady apple orchard in summer", seed=0)  # doctest: +SKIP
>>> scene.recipe.fields[0].variety  # doctest: +SKIP
'Pink Lady'
"""

from agrirecipe._errors import (
    AgrirecipeError,
    BackendError,
    ConfigurationError,
    HierarchyError,
    KnowledgeBaseError,
    ModelError,
    PipelineError,
    PromptError,
    RecipeValidationError,
    UnknownCropError,
    UserInputError,
)
from agrirecipe._scene import Scene, generate
from agrirecipe.backends import Backend, available_backends, get_backend, register_backend
from agrirecipe.recipe import FieldSpec, SceneRecipe, dump_recipe, load_recipe

__version__ = "0.1.0"

__all__ = [
    "AgrirecipeError",
    "Backend",
    "BackendError",
    "ConfigurationError",
    "FieldSpec",
    "HierarchyError",
    "KnowledgeBaseError",
    "ModelError",
    "PipelineError",
    "PromptError",
    "RecipeValidationError",
    "Scene",
    "SceneRecipe",
    "UnknownCropError",
    "UserInputError",
    "__version__",
    "available_backends",
    "dump_recipe",
    "generate",
    "get_backend",
    "load_recipe",
    "register_backend",
]
