"""A small grammar algebra: build a grammar in Python, render it as llama.cpp GBNF, and match text.

The same object is what the model is constrained by (rendered to GBNF for llama.cpp) and what the
tests check examples against (``Grammar.matches``), so the two cannot disagree.

Nodes: ``Lit`` (exact text), ``Chars`` (one character of a class), ``Seq``, ``Alt``, ``Opt``,
``Many`` (zero or more), ``Some`` (one or more) and ``Ref`` (a named rule).
"""

from __future__ import annotations

from collections.abc import Iterator, Mapping
from dataclasses import dataclass
from typing import Union

Node = Union["Lit", "Chars", "Seq", "Alt", "Opt", "Many", "Some", "Upto", "Ref"]


@dataclass(frozen=True)
class Lit:
    """Exactly this text."""

    text: str


@dataclass(frozen=True)
class Chars:
    """One character that is not in ``excluded`` (a negated class, the only kind needed here)."""

    excluded: str


@dataclass(frozen=True)
class Seq:
    """Each part in turn."""

    parts: tuple[Node, ...]


@dataclass(frozen=True)
class Alt:
    """Any one of the choices."""

    choices: tuple[Node, ...]


@dataclass(frozen=True)
class Opt:
    """The inner node or nothing."""

    inner: Node


@dataclass(frozen=True)
class Many:
    """The inner node zero or more times."""

    inner: Node


@dataclass(frozen=True)
class Some:
    """The inner node one or more times."""

    inner: Node


@dataclass(frozen=True)
class Upto:
    """The inner node zero to ``most`` times."""

    inner: Node
    most: int


@dataclass(frozen=True)
class Ref:
    """The rule of this name."""

    name: str


def seq(*parts: Node | str) -> Node:
    """A sequence; strings are literals."""
    nodes = tuple(Lit(p) if isinstance(p, str) else p for p in parts)
    return nodes[0] if len(nodes) == 1 else Seq(nodes)


def alt(*choices: Node | str) -> Node:
    """A choice; strings are literals."""
    nodes = tuple(Lit(c) if isinstance(c, str) else c for c in choices)
    return nodes[0] if len(nodes) == 1 else Alt(nodes)


@dataclass(frozen=True)
class Grammar:
    """Named rules; ``root`` is where matching starts."""

    rules: Mapping[str, Node]

    def to_gbnf(self) -> str:
        """The grammar in llama.cpp's GBNF, one rule per line, root first."""
        names = ["root", *sorted(name for name in self.rules if name != "root")]
        return "\n".join(f"{name} ::= {_render(self.rules[name])}" for name in names) + "\n"

    def matches(self, text: str) -> bool:
        """Whether the whole of ``text`` is in the language of the grammar."""
        return any(end == len(text) for end in _match(self, Ref("root"), text, 0))

    def check(self) -> None:
        """Raise ValueError if there is no root or a rule refers to a rule that is not defined."""
        if "root" not in self.rules:
            raise ValueError("the grammar has no 'root' rule")
        for name, node in self.rules.items():
            for ref in _refs(node):
                if ref not in self.rules:
                    raise ValueError(f"rule {name!r} refers to undefined rule {ref!r}")


def renamed(rules: Mapping[str, Node], suffix: str) -> dict[str, Node]:
    """The rules with ``suffix`` added to every rule name and every reference.

    A renamed copy can sit beside the original in one grammar (one set of value rules per clause).
    """
    return {f"{name}{suffix}": _renamed(node, suffix) for name, node in rules.items()}


def _renamed(node: Node, suffix: str) -> Node:
    if isinstance(node, Ref):
        return Ref(node.name + suffix)
    if isinstance(node, Seq):
        return Seq(tuple(_renamed(part, suffix) for part in node.parts))
    if isinstance(node, Alt):
        return Alt(tuple(_renamed(choice, suffix) for choice in node.choices))
    if isinstance(node, Opt | Many | Some):
        return type(node)(_renamed(node.inner, suffix))
    if isinstance(node, Upto):
        return Upto(_renamed(node.inner, suffix), node.most)
    return node


def _refs(node: Node) -> Iterator[str]:
    if isinstance(node, Ref):
        yield node.name
    elif isinstance(node, Seq):
        for part in node.parts:
            yield from _refs(part)
    elif isinstance(node, Alt):
        for choice in node.choices:
            yield from _refs(choice)
    elif isinstance(node, Opt | Many | Some | Upto):
        yield from _refs(node.inner)


def _render(node: Node) -> str:
    if isinstance(node, Lit):
        return _quote(node.text)
    if isinstance(node, Chars):
        return "[^" + "".join(_class_char(c) for c in node.excluded) + "]"
    if isinstance(node, Ref):
        return node.name
    if isinstance(node, Seq):
        return " ".join(_group(part) for part in node.parts)
    if isinstance(node, Alt):
        return " | ".join(_render(choice) for choice in node.choices)
    if isinstance(node, Upto):
        return _group(node.inner) + f"{{0,{node.most}}}"
    suffix = {Opt: "?", Many: "*", Some: "+"}[type(node)]
    return _group(node.inner) + suffix


def _group(node: Node) -> str:
    return f"({_render(node)})" if isinstance(node, Seq | Alt) else _render(node)


_ESCAPES = {'"': '\\"', "\\": "\\\\", "\n": "\\n", "\r": "\\r", "\t": "\\t", "]": "\\]", "[": "\\["}


def _quote(text: str) -> str:
    return '"' + "".join(_ESCAPES.get(c, c) if c in '"\\\n\r\t' else _printable(c) for c in text) + '"'


def _class_char(char: str) -> str:
    return _ESCAPES.get(char) or _printable(char) if char not in "^-" else "\\" + char


def _printable(char: str) -> str:
    return char if char.isprintable() else f"\\x{ord(char):02X}" if ord(char) < 256 else f"\\u{ord(char):04X}"


def _match(grammar: Grammar, node: Node, text: str, pos: int) -> Iterator[int]:
    """Every end position at which ``node`` can finish matching ``text`` from ``pos``."""
    if isinstance(node, Lit):
        if text.startswith(node.text, pos):
            yield pos + len(node.text)
    elif isinstance(node, Chars):
        if pos < len(text) and text[pos] not in node.excluded:
            yield pos + 1
    elif isinstance(node, Ref):
        yield from _match(grammar, grammar.rules[node.name], text, pos)
    elif isinstance(node, Seq):
        yield from _match_seq(grammar, node.parts, text, pos)
    elif isinstance(node, Alt):
        for choice in node.choices:
            yield from _match(grammar, choice, text, pos)
    elif isinstance(node, Opt):
        yield pos
        yield from _match(grammar, node.inner, text, pos)
    elif isinstance(node, Upto):
        yield from _match_upto(grammar, node, text, pos)
    else:
        yield from _match_repeat(grammar, node, text, pos)


def _match_seq(grammar: Grammar, parts: tuple[Node, ...], text: str, pos: int) -> Iterator[int]:
    if not parts:
        yield pos
        return
    for middle in _match(grammar, parts[0], text, pos):
        yield from _match_seq(grammar, parts[1:], text, middle)


def _match_upto(grammar: Grammar, node: Upto, text: str, pos: int) -> Iterator[int]:
    """Zero to ``node.most`` repetitions, longest first."""
    reached, frontier = {pos}, {pos}
    for _ in range(node.most):
        frontier = {
            end for start in frontier for end in _match(grammar, node.inner, text, start) if end > start
        }
        reached |= frontier
    yield from sorted(reached, reverse=True)


def _match_repeat(grammar: Grammar, node: Many | Some, text: str, pos: int) -> Iterator[int]:
    """Repetitions, longest first; each repetition must consume text (no endless empty loops)."""
    frontier, seen = {pos}, {pos}
    ends = [] if isinstance(node, Some) else [pos]
    while frontier:
        reached = {
            end for start in frontier for end in _match(grammar, node.inner, text, start) if end > start
        }
        frontier = reached - seen
        seen |= reached
        ends.extend(sorted(frontier))
    yield from sorted(set(ends), reverse=True)


PLAIN_TEXT_CHAR = Chars('"\\' + "".join(chr(c) for c in range(32)))
"""A character of a JSON string that needs no escape: anything but a quote, a backslash, a control."""
