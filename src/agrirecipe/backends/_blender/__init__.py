"""Parts of the Blender backend: the scene style, proxy plans and the bpy-side builder.

``scene_builder.py`` is never imported by the library: its source is inlined
into generated ``blender_build.py`` scripts, which run inside Blender.
"""
