"""Explanations of skills code in plain words, exact and instant: each skill says what it does.

``explain_code`` reads code made of ``t = skill(t, ...)`` statements (what the answer grammar
allows) and renders one sentence per step from the skill's template below, with its arguments
filled in: amount words with what they resolve to, objects by name, defaults spelled out. Code that
is anything else (raw numpy, the paper's prompt) is not explained here: ``explain_code`` returns None.
"""

from __future__ import annotations

import ast
import inspect
from collections.abc import Callable
from typing import Any

from trajadapt.code_parse import parse_code
from trajadapt.model.geometry import PART_WORDS
from trajadapt.skills import SKILLS
from trajadapt.skills.core import AMOUNT_WORDS
from trajadapt.skills.objects import CLOSER_FRACTIONS, OVER_CLEARANCE

TEMPLATES: dict[str, str] = {
    "shift": "moves the path {amount} {direction}, keeping the start and blending in over the first 15%",
    "shift_goal": "moves the goal {amount} {direction}; the start stays and the path bends towards it",
    "shift_start": "moves the start {amount} {direction}; the goal stays and the change fades along the path",
    "shift_part": "moves the {part} part of the path {amount} {direction}, blending in and out",
    "lift_middle": "bows the middle of the path {amount} {direction}; start and goal stay",
    "move_closer": "brings the part of the path nearest {point} {amount} towards it; start and goal stay",
    "move_away": "pushes the part of the path nearest {point} {amount} away from it; start and goal stay",
    "avoid": "keeps every waypoint at least {clearance} from {points}",
    "pass_through": "bends the path so that it passes exactly through {point}",
    "pass_over": "bends the path so that it passes {clearance} above {points}",
    "reach": "makes the path end at {point} instead of the old goal; the start stays",
    "scale_speed": "multiplies the speed by {factor} {where}",
    "set_speed": "sets the speed to {speed} {where}",
    "speed_profile": "replaces the speed by a {kind} profile from {start} of the path on",
    "stop_at": "ends the path at the waypoint nearest {point}, with speed 0 there",
    "wait": "pauses {steps} timesteps at {at}",
    "extend": "continues past the goal by {distance} {direction}",
    "append_segment": "after the goal, goes on in a straight line to {point}",
    "spiral": "adds a spiral of {turns} turns growing to {max_radius} at {at}",
    "circle_around": "circles {turns} time(s) around {center} at {radius}, then continues the path",
    "set_height": "flies the path at height {height}{ends}",
    "stay_above": "raises every waypoint below height {height} up to it",
    "stay_below": "lowers every waypoint above height {height} down to it",
    "keep_side": "keeps every waypoint on the {side} side of {point}",
    "rotate": "turns the path {degrees} degrees clockwise (seen from above) about {center}",
    "scale_about": "multiplies each waypoint's distance from {point} by {factor}",
    "exaggerate_curve": "scales how far the path bends away from the straight start-goal line by {factor}",
    "zigzag": "adds a sideways zig-zag of {amplitude} with {cycles} cycles; start and goal stay",
    "smooth": "smooths the path (strength {strength}); start and goal stay",
    "resample": "resamples the path to {count} evenly spaced waypoints",
    "add_noise": "adds random offsets of {scale} to the positions; start and goal stay",
}
IN_A_PART: dict[str, str] = {
    "move_closer": "brings {span} {amount} towards {point}",
    "move_away": "pushes {span} {amount} away from {point}",
}
"""The sentence of an object move given a ``part`` (a reader's "the first 6 points"): all of it moves."""
BY_NAME: dict[str, Callable[..., Any]] = {function.__name__: function for function in SKILLS}


PLACES = ("object", "between", "nearest", "waypoint", "count", "expression")


class _Unexplained(ValueError):
    """A piece of code that is not a skill call with readable arguments."""


def explain_code(code: str) -> list[str] | None:
    """One sentence per step of skills code, or None when the code is not only skill calls."""
    try:
        tree = parse_code(code)
        return [line for statement in tree.body if (line := _statement(statement)) is not None]
    except (SyntaxError, _Unexplained):
        return None


def _statement(statement: ast.stmt) -> str | None:
    if not isinstance(statement, ast.Assign) or len(statement.targets) != 1:
        raise _Unexplained("not an assignment")
    value = statement.value
    if isinstance(value, ast.Name) or (
        isinstance(value, ast.Call) and isinstance(value.func, ast.Name) and value.func.id == "get_trajectory"
    ):
        return None  # t = get_trajectory(), modified_trajectory = t
    if not (isinstance(value, ast.Call) and isinstance(value.func, ast.Name) and value.func.id in TEMPLATES):
        raise _Unexplained("not a skill call")
    return explain_call(value.func.id, value.args[1:], value.keywords)


def explain_call(name: str, args: list[ast.expr], keywords: list[ast.keyword]) -> str:
    """The sentence for one call of skill ``name`` with these argument expressions (trajectory left out)."""
    parameters = list(inspect.signature(BY_NAME[name]).parameters.values())[1:]
    values: dict[str, Any] = {p.name: p.default for p in parameters}
    try:
        values.update({p.name: _value(a) for p, a in zip(parameters, args, strict=False)})
        values.update({k.arg: _value(k.value) for k in keywords if k.arg})
    except ValueError as exc:
        raise _Unexplained(str(exc)) from exc
    words = {key: _words(key, value, name) for key, value in values.items()}
    words["where"] = _where(values)
    words["ends"] = (
        "" if values.get("keep_start", True) and values.get("keep_goal", True) else ", ends included"
    )
    if name == "stop_at" and (values.get("beside") or values.get("within") is not None):
        beside = "from its waypoint nearest it straight on to beside it, speed 0 there"
        within = values.get("within")
        where = "beside" if within is None else f"within {within} of"
        return f"ends the path {where} {words['point']}: {beside}"
    if name in IN_A_PART and values.get("part") is not None:
        return IN_A_PART[name].format(span=_span(values["part"]), **words)
    return TEMPLATES[name].format(**words)


def _span(part: Any) -> str:
    """A part of the path in words: 'waypoints 0 to 5' for an index pair, else the part's name."""
    if isinstance(part, tuple | list) and all(isinstance(p, int) for p in part):
        return f"waypoints {part[0]} to {part[1] - 1}"
    return f"the {part} part of the path" if isinstance(part, str) else f"the part {part} of the path"


def _value(node: ast.expr) -> Any:
    """A readable form of an argument: literals as themselves, objects as ('object', name)."""
    if isinstance(node, ast.Call) and isinstance(node.func, ast.Name):
        inner = [_value(a) for a in node.args]
        if node.func.id == "detect_objects" and len(inner) == 1:
            return ("object", inner[0])
        if node.func.id == "midpoint" and len(inner) == 2:
            return ("between", inner[0], inner[1])
        if node.func.id == "closest_waypoint" and len(inner) == 2:
            return ("nearest", inner[1])
        if node.func.id == "len":
            return ("count",)
        raise ValueError(f"unreadable call {node.func.id}")
    if isinstance(node, ast.Subscript) and isinstance(node.value, ast.Name):
        return ("waypoint", ast.literal_eval(node.slice))
    if isinstance(node, ast.BinOp):
        return ("expression", ast.unparse(node))
    if isinstance(node, ast.List | ast.Tuple) and any(isinstance(e, ast.Call) for e in node.elts):
        return [_value(element) for element in node.elts]
    return ast.literal_eval(node)


def _words(key: str, value: Any, skill: str) -> str:
    if isinstance(value, tuple) and value and value[0] in PLACES:
        return _place(value)
    if key == "amount" and skill == "move_closer":
        fraction = CLOSER_FRACTIONS.get(str(value).lower() if value is not None else "", value)
        label = f"'{value}' " if isinstance(value, str) else ""
        return f"{label}({float(fraction):.0%} of the way)" if fraction is not None else str(value)
    if key == "clearance" and skill == "pass_over":
        return f"{OVER_CLEARANCE:.0%} of the path's size" if value is None else _distance(value, key)
    if key in ("amount", "distance", "max_radius", "radius", "amplitude", "scale"):
        return _distance(value, key)
    if key == "part":
        return str(value) if isinstance(value, str) and value in PART_WORDS else f"{value}"
    if key == "start" and isinstance(value, float | int):
        return f"{value:.0%}"
    if key == "center" and value is None:
        return "the start"
    if key in ("points",) and isinstance(value, list):
        return " and ".join(_place(v) if isinstance(v, tuple) else str(v) for v in value)
    if key == "at" and isinstance(value, str):
        return f"the {value}"
    if key == "direction" and value is None:
        return "along the final heading"
    return str(value)


def _distance(value: Any, key: str) -> str:
    if value is None and key == "distance":
        return "20% of the path's size"
    if value is None:
        default = "a bit" if key in ("max_radius", "amplitude") else ""
        share = AMOUNT_WORDS[default]
        return (
            "the current distance"
            if key == "radius"
            else f"the default amount ({share:.0%} of the path's size)"
        )
    if isinstance(value, str):
        word = value.strip().lower()
        return (
            f"'{value}' ({AMOUNT_WORDS[word]:.0%} of the path's size)"
            if word in AMOUNT_WORDS
            else f"'{value}'"
        )
    return f"{value}"


def _place(value: tuple[Any, ...]) -> str:
    kind = value[0]
    if kind == "object":
        return f"the {value[1]}"
    if kind == "between":
        return f"the point between {_place(value[1]) if isinstance(value[1], tuple) else value[1]} and " + (
            _place(value[2]) if isinstance(value[2], tuple) else str(value[2])
        )
    if kind == "nearest":
        return f"the waypoint nearest {_place(value[1]) if isinstance(value[1], tuple) else value[1]}"
    if kind == "waypoint":
        return f"waypoint {value[1]}"
    if kind == "count":
        return "the current number of waypoints"
    return str(value[1])


def _where(values: dict[str, Any]) -> str:
    near, radius, part = values.get("near"), values.get("radius"), values.get("part")
    where = []
    if near is not None:
        place = _place(near) if isinstance(near, tuple) else str(near)
        fading = (
            "held over the stretch nearest it, then fading" if values.get("held") else "fading with distance"
        )
        where.append(f"within {radius} of {place}" if radius is not None else f"near {place}, {fading}")
    if part is not None:
        where.append(f"in the {part} part" if isinstance(part, str) else f"in the part {part}")
    return " and ".join(where) or "everywhere"
