"""Edit a scene by words: change one thing, keep everything else byte-identical.

>>> from agrirecipe import generate
>>> scene = generate("a pear orchard next to a carrot field")  # doctest: +SKIP
>>> edited = scene.edit("make the pears ill")  # doctest: +SKIP
>>> edited.changes  # doctest: +SKIP
('~ pear_orchard_1: health Healthy -> Ill',)
"""

from agrirecipe.edit._diff import diff_recipes
from agrirecipe.edit._edit import MAX_INSTRUCTION_CHARS, EditResult, edit_recipe

__all__ = ["MAX_INSTRUCTION_CHARS", "EditResult", "diff_recipes", "edit_recipe"]
