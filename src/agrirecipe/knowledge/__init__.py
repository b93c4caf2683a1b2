"""Crop knowledge: structured lookup of agronomic facts, and the paper's embedding retrieval."""

from agrirecipe.knowledge._base import (
    KnowledgeBase,
    KnowledgeEntry,
    default_knowledge_base,
    load_knowledge_base,
)
from agrirecipe.knowledge._retrieval import KnowledgeRetriever, RetrievalHit

__all__ = [
    "KnowledgeBase",
    "KnowledgeEntry",
    "KnowledgeRetriever",
    "RetrievalHit",
    "default_knowledge_base",
    "load_knowledge_base",
]
