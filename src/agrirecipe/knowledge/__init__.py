"""Crop knowledge: structured lookup of agronomic facts, and the paper's embedding retrieval."""

from agrirecipe.knowledge._base import (
    KnowledgeBase,
    KnowledgeEntry,
    default_knowledge_base,
    load_knowledge_base,
)

__all__ = [
    "KnowledgeBase",
    "KnowledgeEntry",
    "default_knowledge_base",
    "load_knowledge_base",
]
