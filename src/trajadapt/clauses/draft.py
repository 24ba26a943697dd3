"""A first answer written clause by clause: one constrained request per clause, composed in order.

Each request carries the whole instruction (for context) and the words of one clause; its grammar
admits one or two skill steps whose objects and numbers come from that clause (``step_grammar``),
and its examples are clause examples matched to those words (``render_clause_examples``). The
environment, trajectory and instruction come first in every request, so a backend that keeps its
context (llama.cpp) reads them once per case and only the clause's examples and words after that.

The plan the user reviews is built here, not written by the model: each step's exact explanation
(``skills.explain``) with the words it serves. A clause that got no step is said in the plan.
"""

from __future__ import annotations

import ast
import json
from collections.abc import Callable, Sequence
from dataclasses import dataclass, replace

from trajadapt.answer import Plan
from trajadapt.backends.base import ChatMessage, ChatRequest, Completion, Usage
from trajadapt.case import Case
from trajadapt.clauses.examples import render_clause_examples
from trajadapt.clauses.grammar import (
    MAX_STEPS_PER_CLAUSE,
    allowed_numbers,
    clause_objects,
    said_places,
    step_grammar,
)
from trajadapt.clauses.split import only_keeps, split_clauses
from trajadapt.errors import BackendError
from trajadapt.geometry import AxisConvention
from trajadapt.prompts import describe_environment, render, render_functions, summarize_trajectory
from trajadapt.sandbox.api import RESULT_VARIABLE
from trajadapt.skills.explain import explain_code

ClauseCheck = Callable[[str, tuple[str, ...]], list[str]]
"""What a clause's lines, run alone on the original path, contradict in the clause's words."""

CLAUSE_MAX_TOKENS = 96
"""Two skill lines fit in about 50 tokens; a backend that ignores the grammar stops here."""


@dataclass(frozen=True)
class ClauseStep:
    """The words of one clause, the step lines written for them, and the exchange that wrote them."""

    clause: str
    lines: tuple[str, ...]
    request: ChatRequest | None
    """None for a clause that only asks to keep something (``split.only_keeps``): nothing was asked."""
    completion: Completion | None
    error: str | None = None
    findings: tuple[str, ...] = ()
    """What the kept lines, run alone, still contradict in the clause's words (``ClauseCheck``)."""
    asked_again: bool = False
    kept_second: bool = False
    earlier: tuple[Completion, ...] = ()
    """Answers given before the kept one (a step asked again)."""

    @property
    def completions(self) -> tuple[Completion, ...]:
        """Every answer this clause got, the kept one last."""
        return (*self.earlier, *((self.completion,) if self.completion else ()))


@dataclass(frozen=True)
class ClauseDraft:
    """The composed answer and the step of each clause."""

    plan: Plan
    steps: tuple[ClauseStep, ...]

    def replanned(self, code: str) -> Plan:
        """The plan of ``code`` after readers changed the composed one (its steps explained again)."""
        return self.plan if code == self.plan.code else describe_plan(code, self.steps)

    @property
    def completion(self) -> Completion:
        """All clause exchanges as one completion: texts one after the other, usage and time summed."""
        done = [completion for step in self.steps for completion in step.completions]
        return Completion(
            text="\n\n".join(f"Words: {s.clause}\n{s.completion.text}" for s in self.steps if s.completion),
            model=done[0].model if done else "",
            usage=Usage(
                prompt_tokens=sum(c.usage.prompt_tokens or 0 for c in done),
                completion_tokens=sum(c.usage.completion_tokens or 0 for c in done),
            ),
            duration_s=sum(c.duration_s for c in done),
        )


@dataclass(frozen=True)
class ClauseRequests:
    """How each clause's request is made: the axes, how many examples, the grammar, sampling."""

    axes: AxisConvention
    examples: int = 3
    grammar: bool = True
    temperature: float = 0.0
    seed: int | None = 0
    whole_instruction: bool = True
    """Show the whole instruction before the clause's words (context), or only the clause (no cross-talk)."""


def clause_system_prompt(axes: AxisConvention) -> str:
    """The fixed first message of every clause request."""
    return render("system_clause", functions=render_functions("skills"), coordinate_system=axes.describe())


def clause_request(case: Case, clauses: Sequence[str], index: int, how: ClauseRequests) -> ChatRequest:
    """The request for the step of ``clauses[index]``."""
    names = [obj.name for obj in case.scene.objects]
    clause = clauses[index]
    task = render(
        "clause_task",
        environment=describe_environment(case),
        trajectory=summarize_trajectory(case.trajectory),
        instruction=f"INSTRUCTION: {case.instruction}\n\n" if how.whole_instruction else "",
        examples=render_clause_examples(clause, how.examples, names),
        clause=clause,
    )
    grammar = step_grammar(
        clause_objects(clauses, index, names), allowed_numbers(clause), said_places(clause)
    )
    return ChatRequest(
        messages=(ChatMessage("system", clause_system_prompt(how.axes)), ChatMessage("user", task)),
        temperature=how.temperature,
        max_tokens=CLAUSE_MAX_TOKENS,
        seed=how.seed,
        grammar=grammar.to_gbnf() if how.grammar else None,
    )


def step_lines(text: str) -> tuple[str, ...]:
    """The answer's lines that are one ``t = <call>(t, ...)`` each, in order, at most two."""
    found = []
    for line in text.replace("\\n", "\n").splitlines():
        line = line.strip().strip("`")
        if not line.startswith("t = ") or "get_trajectory" in line:
            continue
        try:
            statement = ast.parse(line).body
        except SyntaxError:
            continue
        if (
            len(statement) == 1
            and isinstance(statement[0], ast.Assign)
            and isinstance(statement[0].value, ast.Call)
        ):
            found.append(line)
    return tuple(found[:MAX_STEPS_PER_CLAUSE])


def draft_by_clause(
    case: Case,
    complete: Callable[[ChatRequest], Completion],
    how: ClauseRequests,
    check: ClauseCheck | None = None,
) -> ClauseDraft:
    """Ask for each clause's step in turn and compose them.

    A clause whose request fails gets no step; a line the same as an earlier clause's is that
    clause's step written again ("shift left slightly and extend it to reach the clock" gave the
    second clause the first one's shift and an extension): it is left out. With ``check``, a step
    that contradicts its clause's words goes back once with the findings, and the answer with fewer
    findings is kept.
    """
    names = [obj.name for obj in case.scene.objects]
    clauses = split_clauses(case.instruction, names)
    steps: list[ClauseStep] = []
    for index, clause in enumerate(clauses):
        if only_keeps(clause, names):
            steps.append(ClauseStep(clause, (), None, None))
            continue
        taken = {line for step in steps for line in step.lines}
        step = _step_for(clause, clause_request(case, clauses, index, how), complete, taken)
        if check is not None and step.lines:
            step = _checked(step, complete, check, taken)
        steps.append(step)
    return ClauseDraft(compose_plan(steps), tuple(steps))


def _step_for(
    clause: str, request: ChatRequest, complete: Callable[[ChatRequest], Completion], taken: set[str]
) -> ClauseStep:
    try:
        completion = complete(request)
    except BackendError as exc:
        return ClauseStep(clause, (), request, None, str(exc))
    lines = tuple(line for line in step_lines(completion.text) if line not in taken)  # another clause's step
    return ClauseStep(clause, lines, request, completion)


def _checked(
    step: ClauseStep, complete: Callable[[ChatRequest], Completion], check: ClauseCheck, taken: set[str]
) -> ClauseStep:
    """The step, or its second answer when the first contradicts the words and the second less."""
    findings = check(step.clause, step.lines)
    if not findings or step.completion is None or step.request is None:
        return step
    retry = render("clause_retry", findings="; ".join(findings), clause=step.clause)
    request = replace(step.request, messages=(
        *step.request.messages, ChatMessage("assistant", step.completion.text), ChatMessage("user", retry)
    ))  # fmt: skip
    second = _step_for(step.clause, request, complete, taken)
    second_findings = check(second.clause, second.lines) if second.lines else [*findings, "no step"]
    if len(second_findings) < len(findings):
        return replace(
            second,
            findings=tuple(second_findings),
            asked_again=True,
            kept_second=True,
            earlier=(step.completion,),
        )
    return replace(step, findings=tuple(findings), asked_again=True, earlier=second.completions)


def compose_plan(steps: Sequence[ClauseStep]) -> Plan:
    """One program of every clause's lines in the user's order, and a plan that names their words."""
    lines = [line for step in steps for line in step.lines]
    return describe_plan("\n".join(["t = get_trajectory()", *lines, f"{RESULT_VARIABLE} = t"]), steps)


def describe_plan(code: str, steps: Sequence[ClauseStep]) -> Plan:
    """The plan of ``code``: each step's exact explanation, and a finding per clause with no step.

    Each step names the clause it serves while the code still has one line per clause line (a
    reader may have left one out since).
    """
    sentences = explain_code(code) or [line for line in code.splitlines()[1:-1]]
    owners = [step.clause for step in steps for _ in step.lines]
    plan_steps = [
        _capital(sentence) + (f" \u2014 for \u201c{owner}\u201d" if len(owners) == len(sentences) else "")
        for sentence, owner in zip(sentences, owners or [""] * len(sentences), strict=False)
    ]
    plan_steps += [
        f"(keeps: \u201c{step.clause}\u201d)"
        if step.request is None
        else f"(no step for \u201c{step.clause}\u201d)"
        for step in steps
        if not step.lines
    ]
    numbered = " ".join(f"{i}) {text}" for i, text in enumerate(plan_steps, start=1))
    raw = json.dumps({"high_level_plan": numbered, "python_code": code})
    return Plan(steps=tuple(plan_steps), code=code, raw_text=raw)


def _capital(sentence: str) -> str:
    return sentence[:1].upper() + sentence[1:]
