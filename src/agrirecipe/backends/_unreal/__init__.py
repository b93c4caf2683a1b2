"""Files of the Unreal backend: the runtime inlined into generated scripts, and its defaults.

``runtime.py`` is source text for the Unreal Editor's Python; it is read as a
resource and never imported by the library (it needs the ``unreal`` module).
"""
