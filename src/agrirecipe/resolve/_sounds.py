"""Words spelt as they sound (issue 8): "lettus" is Lettuce, "tomatos" Tomato.

A misspelling by ear can be two or three edits from the word ("lettus" and "lettuce"),
more than the edit distance of :meth:`Lexicon.fuzzy` allows, yet sound the same. The
key below is a small English sound-alike code in the spirit of Soundex and Metaphone:
letters that sound alike are written alike ("c" before e/i/y as "s", "ph" as "f", "ck"
as "k"), a silent final "e" is dropped, doubled letters are said once and every run of
vowels is one vowel. Two words with the same key and the same first letter sound alike.
"""

from __future__ import annotations

import re

__all__ = ["sound_key"]

_SPELLINGS = (
    (re.compile(r"ph"), "f"),
    (re.compile(r"ck"), "k"),
    (re.compile(r"qu"), "kw"),
    (re.compile(r"c(?=[eiy])"), "s"),
    (re.compile(r"c"), "k"),
    (re.compile(r"z"), "s"),
    (re.compile(r"x"), "ks"),
    (re.compile(r"(?<=[^aeiou])e$"), ""),
    (re.compile(r"(.)\1+"), r"\1"),
    (re.compile(r"[aeiouy]+"), "a"),
)


def sound_key(word: str) -> str:
    """The sound-alike key of one lowercase word ("lettus" and "lettuce": "latas")."""
    key = word
    for pattern, written in _SPELLINGS:
        key = pattern.sub(written, key)
    return key
