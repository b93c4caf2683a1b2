"""The "llm" strategy: a local GGUF model reads the prompt under grammars, step by step.

A 270M base model (Gemma 3, the default) is weak, so the strategy is built
around what such a model can do: continue a few-shot document
(``data/llm/fewshot.yaml``) and pick among a few options. Each prompt becomes
a record continued one line at a time, every line under a grammar generated
from the hierarchy and the recipe schema (:mod:`agrirecipe.resolve._grammar`)::

    Request: a healthy Pink Lady apple orchard in summer next to young carrots
    Parts: a healthy Pink Lady apple orchard in summer | young carrots   <- decompose
    Part 1: a healthy Pink Lady apple orchard in summer
    Count: 1                                                              <- per-field
    Crop: Apple                                                              subquery
    Variety: Pink Lady
    Stage: none
    Season: Summer
    Health: Healthy
    Part 2: young carrots
    ...
    Relations: 1 next to 2

1. **Decompose**: the model splits the request into parts; the grammar only
   offers runs of the request's own words, in order, without overlap. It is
   asked where two fields the words name have no joining word ("and", a
   comma, "next to") between them; elsewhere the joining words fix every
   boundary, step 2 would overrule any other answer, and the line is written
   without asking (``narrow=False`` always asks).
2. **Validate and repair the parts** (deterministic): a part naming two plants
   is split between them, a plant no part covers joins the part next to it,
   words naming no plant are merged into a neighbour or, with "all", shared
   by every part; "none" on a request that names a crop is overruled.
3. **Retrieve** each part's candidates from the lexicon (exact and typo
   matches of hierarchy names and aliases, plot nouns, stage/season/health
   words, counts, plants the hierarchy does not hold).
4. **Per-field subquery**: one line per attribute, each a choice among the
   retrieved candidates. The model decides wherever more than one is left
   ("cherry" in "a cherry orchard": Cherry or Tomato; sizes; relations other
   than one "next to" between two parts, which reads one way only); a single
   candidate is written without asking, and with nothing retrieved every
   canonical value plus "none" is offered. The trace says how often the model
   was asked.
5. **Validate the record** (deterministic): "other" is an
   :class:`~agrirecipe.UnknownCropError` listing the nearest known crops; a
   variety of one crop named beside another crop is a contradiction
   (:class:`~agrirecipe.PromptError`); self-relations are dropped.

Why the candidates are narrowed so far, measured on 30 development prompts
(docs in the closing report): offered every canonical value, the model answered
the stage line with the same value whatever the words said (5/17 right; 11/17
with everyday labels such as "young", which is the "always none" baseline),
and dropped named varieties for "none" about half the time. Offered only what
retrieval found, it chooses correctly between readings and can never invent.
``LlmResolver(narrow=False)`` keeps every option open, to measure the model alone.

The model is loaded on first use and kept; the few-shot prefix stays in its KV
cache, so a warm prompt costs only its own tokens. Output is deterministic:
greedy decoding over bit-identical logits whatever ran before (see
:class:`~agrirecipe.localmodels.LlamaCppModel`).

The modules, in the order the strategy uses them:

- ``_strategy``: :class:`LlmResolver`, which runs the steps above, and
  ``_Record``, the few-shot document it continues for one prompt (one line
  per answer; the model is asked only where more than one option is left);
  ``_LocalRecord``, the same lines with each question reading only what it
  depends on (the finetuned strategy's, :mod:`agrirecipe.finetune`).
- ``_examples``: the few-shot examples (``data/llm/fewshot.yaml``) rendered
  as the document every record continues, the local records of one example
  (:func:`render_local`, the fine-tuning data), and the examples of
  :meth:`LlmResolver.choose` (``data/llm/choose.yaml``).
- ``_evidence``: retrieval over the lexicon (step 3), ``_Evidence``: what a
  run of words names (crops, varieties, plots, states, counts, sizes,
  relations, places); also the hemisphere and the trace's description.
- ``_parts``: the request's parts (steps 1 and 2): the mentions and groups of
  words naming one field, whether the model must decide a boundary, and the
  repair of its decomposition.
- ``_checks``: the deterministic checks of step 5: a variety written next to
  another crop's name, a plot that cannot hold its crop, a variety of another
  crop; and the error for a plant the hierarchy does not hold.
- ``_answers``: the model's answers turned into intents (step 4 to 5): one
  :class:`~agrirecipe.resolve.FieldIntent` per counted field, sizes and
  relations.
"""

from __future__ import annotations

from agrirecipe.resolve.llm._examples import (
    DATA_DIR,
    load_examples,
    render_examples,
    render_local,
)
from agrirecipe.resolve.llm._strategy import MAX_FIELDS, MAX_PROMPT_TOKENS, LlmResolver

__all__ = [
    "DATA_DIR",
    "MAX_FIELDS",
    "MAX_PROMPT_TOKENS",
    "LlmResolver",
    "load_examples",
    "render_examples",
    "render_local",
]
