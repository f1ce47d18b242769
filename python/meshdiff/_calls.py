"""How the package calls the extension: one-line TypeErrors for mistyped
keywords and argument counts, the progress= hook (a callable, or True for a
tqdm bar), and the report warnings as Python warnings.

The keyword names, their defaults and every rule stay the extension's (the C++
library's): the names come from the signature line pybind11 writes at the top of
each docstring, nothing here repeats them.
"""
import difflib
import re
import warnings
from typing import Any, Callable, Dict, List, Optional, Sequence, Tuple

from . import _meshdiff  # type: ignore[attr-defined]  # the extension (no stub of its own)


class MeshWarning(UserWarning):
    """A warning of a report about one of its meshes (isolated vertices,
    non-manifold edges, degenerate faces, ...): the text also stored in the
    report's "warnings" list of that mesh."""


def _split_top_level(text: str) -> List[str]:
    """text split at the commas outside brackets ("a: Tuple[int, int], b" -> two parts)."""
    parts, depth, start = [], 0, 0
    for i, c in enumerate(text):
        depth += c in "([{"
        depth -= c in ")]}"
        if c == "," and depth == 0:
            parts.append(text[start:i])
            start = i + 1
    parts.append(text[start:])
    return parts


def signature(fn: Any) -> Tuple[List[str], List[str]]:
    """(positional names, keyword-only names) of the extension function fn, from
    the first line of its docstring, e.g. "compare(V1: object, ..., *, levels:
    object = None, ...) -> dict"."""
    first = (fn.__doc__ or "").lstrip().split("\n", 1)[0]
    m = re.match(r"^\w+\((.*)\)\s*->", first)
    if not m:
        return [], []
    positional: List[str] = []
    keywords: List[str] = []
    target = positional
    for part in _split_top_level(m.group(1)):
        part = part.strip()
        if part == "*":
            target = keywords
            continue
        name = re.match(r"^(\w+)", part)
        if name and name.group(1) != "self":
            target.append(name.group(1))
    return positional, keywords


def _one_line(fn_name: str, fn: Any, args: Sequence[Any], kwargs: Dict[str, Any]) -> str:
    positional, keywords = signature(fn)
    known = set(positional) | set(keywords)
    for key in kwargs:
        if key not in known:
            close = difflib.get_close_matches(key, sorted(known), n=1)
            hint = f" (did you mean {close[0]!r}?)" if close else ""
            return f"{fn_name}(): unknown keyword {key!r}{hint}"
    if len(args) > len(positional):
        return (f"{fn_name}(): takes {len(positional)} positional arguments ({', '.join(positional)}), "
                f"{len(args)} given; the options are keyword-only")
    missing = [p for p in positional[len(args):] if p not in kwargs]
    if missing:
        return f"{fn_name}(): missing argument {missing[0]!r}"
    return ""


class TqdmProgress:
    """progress=True: one tqdm bar per stage of the library (reading, curvature,
    rings, index, sampling, distances, certification, ...), on stderr."""

    def __init__(self) -> None:
        from tqdm import tqdm  # type: ignore[import]  # Debian python3-tqdm; only for progress=True

        self._tqdm = tqdm
        self._bar: Any = None
        self._stage = ""

    def __call__(self, stage: str, done: int, total: int) -> None:
        if stage != self._stage or self._bar is None:
            self.close()
            self._bar = self._tqdm(total=total or None, desc=stage, leave=False)
            self._stage = stage
        self._bar.n = done
        self._bar.refresh()

    def close(self) -> None:
        if self._bar is not None:
            self._bar.close()
            self._bar = None


def _hook(progress: Any) -> Optional[Callable[[str, int, int], Any]]:
    if progress is None or progress is False:
        return None
    if progress is True:
        return TqdmProgress()
    if callable(progress):
        return progress  # type: ignore[no-any-return]
    raise TypeError(f"progress: expected a callable progress(stage, done, total), True (a tqdm bar) or None, "
                    f"not {type(progress).__name__}")


def call(fn_name: str, fn: Callable[..., Any], args: Sequence[Any], kwargs: Dict[str, Any]) -> Any:
    """fn(*args, **kwargs), with pybind11's "incompatible function arguments"
    (the whole signature) made one line naming the keyword or argument at fault,
    and kwargs["progress"] (if any) called as the library reports its stages:
    progress(stage, done, total), total 0 when not known in advance. An
    exception of the hook stops the call and is raised in its place, as Ctrl-C's
    KeyboardInterrupt is."""
    hook = _hook(kwargs.pop("progress", None))
    if hook is not None:
        _meshdiff._set_progress(hook)
    try:
        return fn(*args, **kwargs)
    except TypeError as e:
        if "incompatible function arguments" not in str(e):
            raise
        line = _one_line(fn_name, fn, args, kwargs)
        if not line:
            raise
        raise TypeError(line) from None
    finally:
        if hook is not None:
            _meshdiff._set_progress(None)
            if isinstance(hook, TqdmProgress):
                hook.close()


def warn_report(report: Any, sides: Sequence[str], stacklevel: int = 3) -> None:
    """Raises each text of report[side]["warnings"] (or report["warnings"] when
    sides is empty) through warnings.warn with the category MeshWarning."""
    if not isinstance(report, dict):
        return
    parts = [(side, report.get(side)) for side in sides] if sides else [("", report)]
    for side, part in parts:
        texts = part.get("warnings") if isinstance(part, dict) else None
        for text in texts or []:
            warnings.warn(f"{side}: {text}" if side else str(text), MeshWarning, stacklevel=stacklevel)
