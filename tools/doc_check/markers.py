"""The markers a doc puts beside its figures, and the check and rewrite of what they mark.

Inline: a figure followed by `<!--= NAME ARGS -->`, as in

    learned reaches the goal **500 of 500**<!--= goals learned 10-30 --> at 10–30 km/h

The text just before the marker (Markdown emphasis aside) must end in what the figure
NAME computes for ARGS. Markdown renders the marker as nothing.

Block: the lines between `<!-- figures: NAME ARGS -->` and `<!-- /figures -->` must be
exactly what the table NAME writes for ARGS.
"""

from __future__ import annotations

import re
from dataclasses import dataclass
from typing import Callable

INLINE = re.compile(r"<!--=\s*(?P<call>[^>]*?)\s*-->")
BLOCK = re.compile(r"(?P<open><!--\s*figures:\s*(?P<call>[^>]*?)\s*-->\n)(?P<body>.*?)"
                   r"(?P<close><!--\s*/figures\s*-->)", re.S)
# Emphasis may close around a figure: **500 of 500**<!--= … -->.
EMPHASIS = "*_`"


@dataclass(frozen=True)
class Figure:
    """How to compute a figure's text from the rows, and a regular expression matching
    any text of its form (what `update` replaces)."""

    compute: Callable[..., str]
    form: str


class FigureError(Exception):
    """A marker that cannot be computed: an unknown figure, wrong arguments, no rows."""


@dataclass(frozen=True)
class Problem:
    line: int
    call: str
    message: str
    table: bool = False

    def text(self, doc: str) -> str:
        marker = f"<!-- figures: {self.call} -->" if self.table else f"<!--= {self.call} -->"
        return f"{doc}:{self.line}: {marker}: {self.message}"


def _line_of(text: str, offset: int) -> int:
    return text.count("\n", 0, offset) + 1


def _compute(table: dict, call: str) -> str:
    name, *args = call.split()
    if name not in table:
        raise FigureError(f"no figure or table called '{name}' (known: {', '.join(sorted(table))})")
    entry = table[name]
    compute = entry.compute if isinstance(entry, Figure) else entry
    try:
        return compute(*args)
    except (TypeError, ValueError) as error:
        raise FigureError(f"wrong arguments for '{name}': {error}") from error


def _split_emphasis(before: str) -> tuple[str, str]:
    """The text before a marker as (figure side, closing emphasis)."""
    core = before.rstrip(EMPHASIS)
    return core, before[len(core):]


def _inside_a_number(before: str) -> bool:
    """Whether a figure right after the character `before` would be a longer number's tail."""
    return before.isdigit() or before in ".,"


def _ends_with_figure(core: str, expected: str) -> bool:
    """Whether `core` ends with the figure `expected` and not with a longer number whose
    tail it is: "30 in 30" does not end with the figure "0 in 30", nor "2 500" with "500"
    (counts are written with spaces)."""
    if not core.endswith(expected):
        return False
    before = core[:len(core) - len(expected)]
    if not expected[:1].isdigit() or not before:
        return True
    if _inside_a_number(before[-1]):
        return False
    grouped = re.match(r"\d{3}(?!\d)", expected)
    return not (grouped and re.search(r"\d $", before))


def _old_figure(core: str, form: str) -> re.Match | None:
    """The figure's old text: the longest tail of `core` that has the figure's form and
    does not start inside a number (counts are written with spaces: 2 500; nor after a
    decimal point)."""
    window = core[-120:]
    for start in range(len(window)):
        match = re.fullmatch(form, window[start:])
        if match and (start == 0 or not _inside_a_number(window[start - 1])):
            return match
    return None


Tables = dict[str, Callable[..., str]]


def check(text: str, figures: dict[str, Figure], tables: Tables) -> list[Problem]:
    problems = []
    for marker in INLINE.finditer(text):
        call = marker["call"]
        try:
            expected = _compute(figures, call)
        except FigureError as error:
            problems.append(Problem(_line_of(text, marker.start()), call, str(error)))
            continue
        core, _ = _split_emphasis(text[:marker.start()])
        if not _ends_with_figure(core, expected):
            name = call.split()[0]
            old = _old_figure(core, figures[name].form)
            found = old.group(0) if old else core[-30:].split("\n")[-1]
            problems.append(Problem(_line_of(text, marker.start()), call,
                                    f"the rows give '{expected}', the doc says '{found}'"))
    for block in BLOCK.finditer(text):
        call = block["call"]
        line = _line_of(text, block.start())
        try:
            expected = _compute(tables, call).rstrip("\n") + "\n"
        except FigureError as error:
            problems.append(Problem(line, call, str(error), table=True))
            continue
        if block["body"] != expected:
            problems.append(Problem(line, call, "the table differs from the one the rows make "
                                    "(tools/doc-check update rewrites it)", table=True))
    return problems


def update(text: str, figures: dict[str, Figure], tables: Tables) -> str:
    """The text with every marked figure and table rewritten from the rows. A figure whose
    old text cannot be found (it no longer has the figure's form) raises FigureError."""
    text = BLOCK.sub(lambda b: b["open"] + _compute(tables, b["call"]).rstrip("\n") + "\n"
                     + b["close"], text)
    pieces, last = [], 0
    for marker in INLINE.finditer(text):
        call = marker["call"]
        expected = _compute(figures, call)
        core, emphasis = _split_emphasis(text[last:marker.start()])
        if not _ends_with_figure(core, expected):
            old = _old_figure(core, figures[call.split()[0]].form)
            if old is None:
                raise FigureError(f"line {_line_of(text, marker.start())}: no figure of the "
                                  f"form of '{call}' right before its marker")
            core = core[:len(core) - len(old.group(0))] + expected
        pieces += [core, emphasis, marker.group(0)]
        last = marker.end()
    pieces.append(text[last:])
    return "".join(pieces)
