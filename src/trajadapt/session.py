"""AdaptationSession: draft a plan, take feedback, approve, execute with automatic repair.

The CLI and any other front end are thin views over these methods; the session does no I/O of its
own beyond the backend, the sandbox and the log store it is given.
"""

from __future__ import annotations

import re
import time
from collections.abc import Callable, Sequence
from dataclasses import dataclass, field, replace
from typing import Any, Literal

from trajadapt import __version__
from trajadapt.backends.base import Backend, ChatMessage, ChatRequest, Completion
from trajadapt.checks.constraints import ConstraintMove, Constraints, constraints_for, new_violations
from trajadapt.checks.effect import Effect, contradictions, measure_effect
from trajadapt.checks.projection import project
from trajadapt.checks.review import ReviewNote, review_notes, validate_result
from trajadapt.checks.robot_limits import robot_constraints
from trajadapt.clauses.check import clause_findings
from trajadapt.clauses.grammar import MAX_CLAUSES, attribute_lines, clause_answer_grammar
from trajadapt.clauses.split import split_clauses
from trajadapt.errors import (
    AnswerParseError,
    BackendError,
    CodeRejected,
    DependencyNotInstalled,
    InvalidTrajectory,
    SessionStateError,
)
from trajadapt.files.store import NewExchange, NewSession, Store
from trajadapt.llm.answer import Plan, parse_answer
from trajadapt.llm.answer_grammar import answer_grammar
from trajadapt.llm.example_bank import Example
from trajadapt.memory import MemoryBank, RememberedExample, choose_examples
from trajadapt.model.case import Case
from trajadapt.model.geometry import AXIS_CONVENTIONS, AxisConvention
from trajadapt.model.trajectory import Trajectory
from trajadapt.prompts import first_messages, render
from trajadapt.readers import ReaderNote, read_against_words
from trajadapt.safe_text import ANSWER_CHARS, INSTRUCTION_CHARS, safe_text
from trajadapt.sandbox.api import RESULT_VARIABLE
from trajadapt.sandbox.runner import ExecutionOptions, Sandbox, SandboxResult
from trajadapt.sandbox.skill_program import check_skill_program
from trajadapt.settings import Settings
from trajadapt.skills import SKILLS, signature_line, summary
from trajadapt.skills.explain import explain_code

TurnKind = Literal["draft", "feedback", "repair", "format-retry"]


@dataclass(frozen=True)
class SessionSettings:
    """How a session talks to the LLM and how hard it tries before giving up.

    ``constraints`` adds the user's limits to those the scene states; a result that breaks them is
    projected onto them (``project``, the default; a review note says what bound it and how far
    waypoints moved), or, with ``project=False``, goes back for repair with the measured numbers.
    ``grammar`` (skills mode) sends the answer grammar of the case's scene with each request, for
    backends that can constrain decoding to it (see ``answer_grammar``).
    """

    axes: AxisConvention = AXIS_CONVENTIONS["paper"]
    mode: str = "skills"
    repair_attempts: int = 2
    format_retries: int = 1
    constraints: Constraints | None = None
    robot: str = "none"
    check_constraints: bool = True
    project: bool = True
    temperature: float = 0.0
    max_tokens: int = 1024
    seed: int | None = 0
    waypoints_in_prompt: bool = False
    grammar: bool = True
    examples: int = 3
    leave_out_unasked: bool = True
    repair_contradictions: bool = False
    clause_steps: bool = False
    clause_check: bool = True

    @classmethod
    def from_settings(cls, settings: Settings, constraints: Constraints | None = None) -> SessionSettings:
        """The one way from the user's settings (config, environment, flags) to a session's."""
        return cls(
            axes=AXIS_CONVENTIONS[settings.axes],
            mode=settings.mode,
            repair_attempts=settings.repair_attempts,
            constraints=constraints,
            robot=settings.robot,
            project=settings.project,
            temperature=settings.temperature,
            seed=settings.seed,
            waypoints_in_prompt=settings.waypoints_in_prompt,
            grammar=settings.grammar,
            examples=settings.examples,
            leave_out_unasked=settings.leave_out_unasked,
            repair_contradictions=settings.repair_contradictions,
            clause_steps=settings.clause_steps,
            clause_check=settings.clause_check,
        )

    def describe(self) -> dict[str, Any]:
        """What reproduces a run, for result files and the log."""
        return {
            "trajadapt_version": __version__,
            "mode": self.mode,
            "axes": self.axes.name,
            "temperature": self.temperature,
            "seed": self.seed,
            "max_tokens": self.max_tokens,
            "repair_attempts": self.repair_attempts,
            "waypoints_in_prompt": self.waypoints_in_prompt,
            "project": self.project,
            "robot": self.robot,
            "constraints": list(self.constraints.sources) if self.constraints else [],
            "grammar": self.grammar,
            "examples": self.examples,
            "leave_out_unasked": self.leave_out_unasked,
            "repair_contradictions": self.repair_contradictions,
            "clause_steps": self.clause_steps,
            "clause_check": self.clause_check,
        }


@dataclass(frozen=True)
class Explanation:
    """What the code does in plain words: exact from the skills, or the model's own reading of other code."""

    source: Literal["skills", "model"]
    lines: tuple[str, ...]

    def to_dict(self) -> dict[str, Any]:
        """The result file's ``explanation`` field."""
        return {"source": self.source, "lines": list(self.lines)}


@dataclass(frozen=True)
class Turn:
    """One request to the LLM and what came of it."""

    kind: TurnKind
    user_text: str
    plan: Plan | None
    completion: Completion | None
    error: str | None = None


@dataclass(frozen=True)
class Checkpoint:
    """The conversation right after a plan: where to cut back to on undo, and the words said by then."""

    messages: int
    turns: int
    plan: Plan
    asked: tuple[str, ...]
    left_out: tuple[ReaderNote, ...]


@dataclass(frozen=True)
class Timings:
    """Seconds spent waiting for the LLM, executing code, and in all."""

    llm_s: float = 0.0
    exec_s: float = 0.0
    total_s: float = 0.0

    def to_dict(self) -> dict[str, float]:
        """The result file's ``timings_s`` field."""
        return {
            "llm": round(self.llm_s, 4),
            "exec": round(self.exec_s, 4),
            "total": round(self.total_s, 4),
        }


@dataclass(frozen=True)
class Failure:
    """Why code gave no trajectory, typed: what kind of failure, and the line people read.

    ``kind`` is an exception type (TypeError, ...) or one of ConstraintViolation, InvalidTrajectory,
    NoResult, RepairUnreadable and a backend error's type; ``message`` is the whole line shown to
    people and sent back for repair.
    """

    kind: str
    message: str

    @classmethod
    def of(cls, kind: str, detail: str) -> Failure:
        """A failure whose message is 'kind: detail'."""
        return cls(kind, f"{kind}: {detail}")

    def __str__(self) -> str:
        return self.message


Outcome = Trajectory | Failure


@dataclass(frozen=True)
class AdaptationResult:
    """The outcome of an approved plan: the new trajectory, or why there is none."""

    case: Case
    status: Literal["ok", "error"]
    plan: Plan | None
    trajectory: Trajectory | None
    failure: Failure | None
    attempts: int
    backend: str
    model: str
    timings: Timings
    notes: tuple[ReviewNote, ...] = ()
    stdout: str = ""
    tokens: dict[str, int] = field(default_factory=dict)
    settings: dict[str, Any] = field(default_factory=dict)
    effect: Effect | None = None
    contradictions: tuple[str, ...] = ()
    explanation: Explanation | None = None
    recalled: tuple[str, ...] = ()
    """Ids of the user's remembered examples that were in the prompt."""
    remembered_as: str = ""
    """The id this approved answer is remembered under ('' when memory is off or it failed)."""

    @property
    def ok(self) -> bool:
        """True when the code ran and produced a valid trajectory."""
        return self.status == "ok"

    @property
    def error(self) -> str | None:
        """Why there is no trajectory, in one line (None when there is one)."""
        return self.failure.message if self.failure else None

    def to_dict(self) -> dict[str, Any]:
        """The result file's content."""
        return {
            "case": self.case.name,
            "case_source": str(self.case.source) if self.case.source else None,
            "instruction": self.case.instruction,
            "high_level_plan": list(self.plan.steps) if self.plan else [],
            "code": self.plan.code if self.plan else "",
            "modified_trajectory": self.trajectory.to_rows() if self.trajectory else None,
            "original_trajectory": self.case.trajectory.to_rows(),
            "objects": [obj.to_dict() for obj in self.case.scene.objects],
            "status": self.status,
            "error": self.error,
            "error_kind": self.failure.kind if self.failure else None,
            "attempts": self.attempts,
            "backend": self.backend,
            "model": self.model,
            "timings_s": self.timings.to_dict(),
            "tokens": self.tokens,
            "review_notes": [note.message for note in self.notes],
            "stdout": self.stdout,
            "settings": self.settings,
            "explanation": self.explanation.to_dict() if self.explanation else None,
            "effect": (
                {
                    **self.effect.to_dict(),
                    "in_words": self.effect.describe(),
                    "contradictions": list(self.contradictions),
                }
                if self.effect
                else None
            ),
            "memory": {"recalled": list(self.recalled), "remembered_as": self.remembered_as or None},
        }


ProgressCallback = Callable[[str], None]


def _count(found: list[tuple[str, list[str]]]) -> int:
    return sum(len(findings) for _, findings in found)


def skill_hints(code: str, problem: str) -> str:
    """The prompt lines of the skills used on the failing line, so that the repair gets the call right."""
    match = re.search(r"\(line (\d+)\)", problem)
    lines = code.splitlines()
    if match is None or not 0 < int(match.group(1)) <= len(lines):
        return ""
    failing = lines[int(match.group(1)) - 1]
    used = [f for f in SKILLS if re.search(rf"\b{f.__name__}\s*\(", failing)]
    if not used:
        return ""
    return "\nHow to call it:\n" + "\n".join(f"- {signature_line(f)}: {summary(f)}" for f in used)


def _recalled(
    case: Case, settings: SessionSettings, remembered: Sequence[RememberedExample]
) -> tuple[Example, ...]:
    """The remembered examples the first prompt shows (the same choice ``first_messages`` made)."""
    if not remembered or settings.mode != "skills":
        return ()
    chosen = choose_examples(case.instruction, settings.examples, case.scene.names(), remembered)
    return tuple(example for example in chosen if example.remembered)


def _same_program(first: str, second: str) -> bool:
    """Equal programs up to blank lines and spaces at line ends."""

    def lines(code: str) -> list[str]:
        return [line.rstrip() for line in code.strip().splitlines() if line.strip()]

    return lines(first) == lines(second)


class AdaptationSession:
    """The conversation about one case: plans, feedback, repairs and the final result."""

    def __init__(
        self,
        case: Case,
        backend: Backend,
        sandbox: Sandbox,
        settings: SessionSettings | None = None,
        store: Store | None = None,
        on_progress: ProgressCallback | None = None,
        memory: MemoryBank | None = None,
    ) -> None:
        """A session on ``case``; ``memory`` recalls the user's approved answers and keeps new ones.

        Raises:
            MemoryUnusable: the bank of remembered examples cannot be read.
        """
        self.case = case
        self.memory = memory
        remembered = memory.examples() if memory is not None else []
        self.backend = backend
        self.sandbox = sandbox
        self.settings = settings or SessionSettings()
        self.store = store
        self.on_progress = on_progress or (lambda _message: None)
        self.turns: list[Turn] = []
        self.messages: list[ChatMessage] = list(
            first_messages(
                case,
                self.settings.axes,
                self.settings.mode,
                self.settings.waypoints_in_prompt,
                self.settings.examples,
                remembered,
            )
        )
        self.recalled_examples = _recalled(case, self.settings, remembered)
        self.recalled = tuple(example.remembered for example in self.recalled_examples)
        self._remembered_as = ""
        self.session_id: str | None = None
        self._llm_s = 0.0
        self._exec_s = 0.0
        self._tokens = {"prompt": 0, "completion": 0}
        self._last_stdout = ""
        self._last_notes: tuple[str, ...] = ()
        self._last_moves: tuple[ConstraintMove, ...] = ()
        self._asked: list[str] = [case.instruction]  # the user's words: instruction, then feedback
        self._left_out: list[ReaderNote] = []  # what the readers changed in the current plan
        self._model_explanations: dict[str, Explanation] = {}
        self._started = time.perf_counter()
        self._checkpoints: list[Checkpoint] = []  # right after each plan

    @property
    def plan(self) -> Plan | None:
        """The latest plan the LLM proposed."""
        return next((turn.plan for turn in reversed(self.turns) if turn.plan), None)

    def draft(self) -> Plan:
        """Ask for the first plan and code.

        Raises:
            SessionStateError: a plan was already drafted.
            BackendError, AnswerParseError: the LLM could not give a readable plan.
        """
        if self.turns:
            raise SessionStateError("this session already has a plan; use feedback() to change it")
        if not self.case.instruction:
            raise SessionStateError("the case has no instruction; give one with --instruction")
        self._start_log()
        plan = self._ask("draft", self.case.instruction, first=True)
        clauses = self._clauses()
        if clauses and self.settings.clause_check:
            plan = self._second_answer_by_clause(plan, clauses)
        return plan

    def _clauses(self) -> tuple[str, ...] | None:
        """The instruction's clauses when the first answer keeps a step per clause, else None.

        That is in skills mode with the grammar, where the backend follows it (``clause_steps``).
        """
        settings = self.settings
        if not (settings.mode == "skills" and settings.grammar and settings.clause_steps):
            return None
        if not self.backend.follows_grammar:
            return None
        clauses = split_clauses(self.case.instruction, self._names)
        return clauses if len(clauses) <= MAX_CLAUSES else None

    def _second_answer_by_clause(self, plan: Plan, clauses: tuple[str, ...]) -> Plan:
        """One more first answer when a clause's step, run alone, contradicts that clause's words.

        The answer with fewer findings is kept; a second answer that is not kept leaves nothing in the
        conversation, the turns or the notes (the log keeps the exchange).
        """
        first = self._clause_findings(self.turns[-1], clauses)
        if not first:
            return plan
        self.on_progress("a step contradicts its words, asking once more")
        kept = self._mark()
        problems = "\n".join(
            f"- the step for \u201c{clause}\u201d: {'; '.join(found)}" for clause, found in first
        )
        self.messages.append(ChatMessage("user", render(
            "clause_contradiction", problems=problems, instruction=self.case.instruction
        )))  # fmt: skip
        try:
            second = self._ask("draft", problems, first=True)
        except (AnswerParseError, BackendError):
            second = None
        again = self._clause_findings(self.turns[-1], clauses) if second is not None else None
        if second is not None and again is not None and _count(again) < _count(first):
            self._left_out.append(
                ReaderNote("clause-check", f"a step contradicted its words ({problems[2:]}); asked once more")
            )
            return second
        self._rewind_to(kept)
        self._left_out = [
            *self._left_out,
            ReaderNote(
                "clause-check", f"a step contradicts its words ({problems[2:]}); asked once more, no better"
            ),
        ]
        return plan

    def _clause_findings(self, turn: Turn, clauses: tuple[str, ...]) -> list[tuple[str, list[str]]]:
        """(clause, findings) for each clause whose lines in the turn's answer, run alone, contradict it."""
        if turn.completion is None or turn.plan is None:
            return []
        lines = parse_answer(turn.completion.text).code.splitlines()[1:-1]
        divided = attribute_lines(lines, clauses, self._names)
        found = [(clause, self._findings_alone(clause, part)) for clause, part in divided or ()]
        return [(clause, findings) for clause, findings in found if findings]

    @property
    def _names(self) -> list[str]:
        return [obj.name for obj in self.case.scene.objects]

    def feedback(self, text: str) -> Plan:
        """Send the user's feedback with the original instruction and previous plan; get a new plan."""
        previous = self._require_plan()
        text = safe_text(text, INSTRUCTION_CHARS)
        if not text.strip():
            raise SessionStateError("feedback is empty; say what should change in the plan")
        self._asked.append(text)
        self.messages.append(ChatMessage("user", render(
            "feedback",
            feedback=text.strip(),
            instruction=self.case.instruction,
            previous_plan=previous.numbered() or "(no plan)",
        )))  # fmt: skip
        return self._ask("feedback", text.strip())

    def approve(self) -> AdaptationResult:
        """Run the current code; on failure send the error back for up to ``repair_attempts`` fixes.

        A result that runs is remembered in the session's memory (when it has one): the instruction
        and the program, for the next request in the user's words; approving again after a
        correction replaces what this session remembered with the corrected program.
        """
        result = self._run_approved()
        memory = self.memory
        if not (result.ok and result.plan is not None and memory is not None and not memory.read_only):
            return result
        if self._remembered_as:  # approved again after a correction: the corrected answer replaces it
            memory.forget(self._remembered_as)
        kept = memory.remember(
            self.case.instruction, result.plan.numbered(), result.plan.code, self.case.scene.names()
        )
        self._remembered_as = kept.id
        self.on_progress(f"remembered as example {kept.id} (trajadapt examples show {kept.id})")
        return replace(result, remembered_as=kept.id)

    def _run_approved(self) -> AdaptationResult:
        plan = self._require_plan()
        attempts = 0
        while True:
            attempts += 1
            self.on_progress(f"running the code (attempt {attempts})")
            outcome = self._execute(plan)
            if isinstance(outcome, Trajectory):
                plan, outcome = self._second_look(plan, outcome)
                return self._result(plan, outcome, attempts)
            if attempts > self.settings.repair_attempts:
                return self._result(plan, outcome, attempts)
            self.on_progress(f"the code failed, asking for a repair: {outcome}")
            problem = outcome.message
            if self.settings.mode == "skills":
                problem += skill_hints(plan.code, outcome.message)
            self.messages.append(ChatMessage("user", render(
                "repair", problem=problem, instruction=self.case.instruction
            )))  # fmt: skip
            try:
                plan = self._ask("repair", outcome.message)
            except AnswerParseError as exc:
                return self._result(
                    plan, Failure("RepairUnreadable", f"repair answer unreadable: {exc}"), attempts
                )
            except BackendError as exc:  # keep what failed; the repair itself could not be asked
                unasked = Failure(outcome.kind, f"{outcome} (no repair: {type(exc).__name__}: {exc})")
                return self._result(plan, unasked, attempts)

    def _second_look(self, plan: Plan, trajectory: Trajectory) -> tuple[Plan, Trajectory]:
        """With ``repair_contradictions``: one more answer when the result contradicts the instruction.

        The new code is kept only if it runs and its result contradicts the words less; otherwise the
        first result stands (and its flags go to the reviewer as usual).
        """
        if not self.settings.repair_contradictions:
            return plan, trajectory
        flags = self._effect(trajectory)["contradictions"]
        if not flags:
            return plan, trajectory
        self.on_progress("the result contradicts the instruction, asking once more")
        kept = self._mark()
        problems = "\n".join(f"- {flag}" for flag in flags)
        self.messages.append(ChatMessage("user", render(
            "contradiction", problems=problems, instruction=self.case.instruction
        )))  # fmt: skip
        try:
            second = self._ask("repair", "; ".join(flags))
        except (AnswerParseError, BackendError):
            self._rewind_to(kept)
            return plan, trajectory
        outcome = self._execute(second)
        if isinstance(outcome, Trajectory) and len(self._effect(outcome)["contradictions"]) < len(flags):
            return second, outcome
        self._rewind_to(kept)  # the first result stands, with its own notes, output and plan
        return plan, trajectory

    def _mark(self) -> tuple[Any, ...]:
        """What a second answer that is not kept must leave as it was."""
        return (
            len(self.messages), len(self.turns), len(self._checkpoints), list(self._left_out),
            self._last_stdout, self._last_notes, self._last_moves,
        )  # fmt: skip

    def _rewind_to(self, mark: tuple[Any, ...]) -> None:
        messages, turns, checkpoints, left_out, stdout, notes, moves = mark
        del self.messages[messages:], self.turns[turns:], self._checkpoints[checkpoints:]
        self._left_out, self._last_stdout, self._last_notes, self._last_moves = left_out, stdout, notes, moves

    def explain(self) -> Explanation:
        """The current code in plain words: from the skills when it is skill calls, else asked of the model.

        Raises:
            SessionStateError: no plan yet.
            BackendError: the model could not be asked.
        """
        code = self._require_plan().code
        lines = explain_code(code)
        if lines is not None:
            return Explanation("skills", tuple(lines))
        if code not in self._model_explanations:
            request = ChatRequest(
                messages=(ChatMessage("user", render("explain", code=code)),),
                temperature=0.0,
                max_tokens=300,
                seed=self.settings.seed,
            )
            text = safe_text(self.backend.complete(request).text, ANSWER_CHARS)
            steps = tuple(line.strip() for line in text.splitlines() if line.strip())
            self._model_explanations[code] = Explanation("model", steps)
        return self._model_explanations[code]

    @property
    def versions(self) -> list[Plan]:
        """Every plan of the conversation so far, oldest first (index = version)."""
        return [checkpoint.plan for checkpoint in self._checkpoints]

    def preview(self) -> Outcome:
        """Run the current plan's code once, without repair: the proposed trajectory, or what went wrong."""
        return self._execute(self._require_plan())

    def rewind(self, version: int) -> Plan:
        """Go back to plan ``version`` (undo): later plans and feedback are dropped from the conversation.

        Raises:
            SessionStateError: no such version.
        """
        if not 0 <= version < len(self._checkpoints):
            raise SessionStateError(
                f"there is no plan version {version}; versions are 0..{len(self._checkpoints) - 1}"
            )
        kept = self._checkpoints[version]
        del self.messages[kept.messages :], self.turns[kept.turns :], self._checkpoints[version + 1 :]
        self._asked = list(kept.asked)  # the words said since are gone too
        self._left_out = list(kept.left_out)
        self._log("undo", self._require_plan().code, {"user_text": f"back to version {version}"}, None, {})
        return self._require_plan()

    def _require_plan(self) -> Plan:
        plan = self.plan
        if plan is None:
            raise SessionStateError("there is no plan yet; call draft() first")
        return plan

    def _ask(self, kind: TurnKind, user_text: str, first: bool = False) -> Plan:
        """Send the conversation (its last user message already in place) and parse the answer.

        ``first``: the first answer, under the grammar from the instruction's clauses where it applies.
        """
        for retry in range(self.settings.format_retries + 1):
            completion = self._complete(first)
            self.messages.append(ChatMessage("assistant", completion.text))
            try:
                plan = self._read_against_words(parse_answer(completion.text))
            except AnswerParseError as exc:
                self._record(Turn(kind, user_text, None, completion, str(exc)))
                if retry >= self.settings.format_retries:
                    raise
                self.messages.append(ChatMessage("user", render(
                    "retry_format", problem=str(exc), instruction=self.case.instruction
                )))  # fmt: skip
                kind, user_text = "format-retry", str(exc)
                continue
            self._record(Turn(kind, user_text, plan, completion))
            self._checkpoints.append(
                Checkpoint(
                    len(self.messages), len(self.turns), plan, tuple(self._asked), tuple(self._left_out)
                )
            )
            return plan
        raise AssertionError("unreachable")

    def _read_against_words(self, plan: Plan) -> Plan:
        """The plan after the readers of ``trajadapt.readers`` (skills mode), their changes noted."""
        self._left_out = []
        if self.settings.mode != "skills" or not self.settings.leave_out_unasked:
            return plan
        approved = next((e for e in self.recalled_examples if _same_program(e.code, plan.code)), None)
        if approved is not None:  # the user's own approved program for a request like this one
            kept = f"the program of remembered example {approved.remembered}, kept as approved"
            self._left_out = [ReaderNote("memory", kept)]
            return plan
        names = [obj.name for obj in self.case.scene.objects]
        code, self._left_out = read_against_words(plan.code, self._asked, names)
        return replace(plan, code=code) if self._left_out else plan

    def _findings_alone(self, clause: str, lines: tuple[str, ...]) -> list[str]:
        """What a clause's lines, run alone on the original path, contradict in the clause's words."""
        code = "\n".join(["t = get_trajectory()", *lines, f"{RESULT_VARIABLE} = t"])
        options = ExecutionOptions(skills=True, positive_x=self.settings.axes.positive_x, accept_last=True)
        result = self.sandbox.run(code, self.case.trajectory, self.case.scene, options)
        self._exec_s += result.duration_s
        if result.error is not None or result.rows is None:
            return [f"the step failed: {result.error.describe() if result.error else 'no trajectory'}"]
        try:
            trajectory = validate_result(result.rows)
        except InvalidTrajectory as exc:
            return [f"the step gave no valid trajectory: {exc}"]
        axes = self.settings.axes.frame
        return clause_findings(
            clause, measure_effect(self.case.trajectory, trajectory, self.case.scene.objects, axes), axes
        )

    def _complete(self, first: bool = False) -> Completion:
        """Send the conversation so far and count the time and tokens of the answer."""
        self.on_progress(f"asking {self.backend.name} ({self.backend.model})")
        request = ChatRequest(
            messages=tuple(self.messages),
            temperature=self.settings.temperature,
            max_tokens=self.settings.max_tokens,
            seed=self.settings.seed,
            grammar=self._answer_grammar(first),
        )
        started = time.perf_counter()
        completion = self.backend.complete(request)
        completion = replace(completion, text=safe_text(completion.text, ANSWER_CHARS))
        self._llm_s += time.perf_counter() - started
        self._tokens["prompt"] += completion.usage.prompt_tokens or 0
        self._tokens["completion"] += completion.usage.completion_tokens or 0
        return completion

    def _answer_grammar(self, first: bool = False) -> str | None:
        """The scene's answer grammar; for the first answer, the one from the instruction's clauses."""
        if self.settings.mode != "skills" or not self.settings.grammar:
            return None
        clauses = self._clauses() if first else None
        if clauses:
            return clause_answer_grammar(clauses, tuple(self._names)).to_gbnf()
        return answer_grammar(tuple(self._names)).to_gbnf()

    def _execute(self, plan: Plan) -> Outcome:
        refused = self._refused(plan)
        if refused is not None:
            return refused
        skills = self.settings.mode == "skills"
        options = ExecutionOptions(
            skills=skills, positive_x=self.settings.axes.positive_x, accept_last=skills
        )
        result: SandboxResult = self.sandbox.run(plan.code, self.case.trajectory, self.case.scene, options)
        self._exec_s += result.duration_s
        outcome: Outcome
        self._last_notes, self._last_moves = result.notes, ()
        if result.error is not None:
            outcome = Failure(result.error.type, result.error.describe())
        elif result.rows is None:
            outcome = Failure("NoResult", "the code produced no trajectory")
        else:
            try:
                outcome = self._enforce_constraints(validate_result(result.rows))
            except InvalidTrajectory as exc:
                outcome = Failure.of("InvalidTrajectory", str(exc))
        problem = None if isinstance(outcome, Trajectory) else outcome.message
        self._log("execution", plan.code, {
            "ok": isinstance(outcome, Trajectory),
            "stdout": result.stdout,
            "layers": list(result.layers),
            "waypoints": len(outcome) if isinstance(outcome, Trajectory) else None,
            "trajectory": outcome.to_rows() if isinstance(outcome, Trajectory) else None,
        }, problem, {"exec": result.duration_s})  # fmt: skip
        self._last_stdout = result.stdout
        return outcome

    def _refused(self, plan: Plan) -> Failure | None:
        """Where the answer was held to the grammar, code that is not a skill program never runs.

        That is skills mode with the grammar, sent to a backend that follows it: a server that ignored
        the grammar it was sent is caught here. Other backends may write numpy (the prompt's rule 5).
        """
        if not (self.settings.mode == "skills" and self.settings.grammar and self.backend.follows_grammar):
            return None
        try:
            check_skill_program(plan.code)
        except CodeRejected as exc:
            self._log("execution", plan.code, {"ok": False}, str(exc), {})
            return Failure.of("CodeRejected", f"{exc} (the answer must be a program of skill calls)")
        return None

    def _enforce_constraints(self, trajectory: Trajectory) -> Outcome:
        """The trajectory if it keeps the constraints (projected onto them if asked), else the problem."""
        if not self.settings.check_constraints:
            return trajectory
        robot = robot_constraints(self.settings.robot)
        asked = " ".join(self._asked)
        limits = constraints_for(self.case.scene, self.settings.constraints, robot, asked)
        original = self.case.trajectory.array
        violations = new_violations(trajectory.array, original, self.case.scene, limits)
        if violations and self.settings.project:
            broken = "; ".join(v.message for v in violations)
            try:
                projection = project(trajectory.array, original, self.case.scene, limits)
            except DependencyNotInstalled as exc:
                return Failure.of("ConstraintViolation", f"{broken} ({exc})")
            self._last_notes += (f"{projection.describe()} (the code's result broke: {broken})",)
            self._last_moves = projection.moves
            trajectory = validate_result(projection.trajectory)
            violations = new_violations(trajectory.array, original, self.case.scene, limits)
        if violations:
            return Failure.of("ConstraintViolation", "; ".join(v.message for v in violations))
        return trajectory

    def failure(self, failure: Failure) -> AdaptationResult:
        """The result of a session that ended without running code (e.g. the LLM gave no readable plan)."""
        return self._result(self.plan, failure, 0)

    def _result(self, plan: Plan | None, outcome: Outcome, attempts: int) -> AdaptationResult:
        ok = isinstance(outcome, Trajectory)
        trajectory = outcome if isinstance(outcome, Trajectory) else None
        return AdaptationResult(
            case=self.case,
            status="ok" if ok else "error",
            plan=plan,
            trajectory=trajectory,
            failure=outcome if isinstance(outcome, Failure) else None,
            attempts=attempts,
            backend=self.backend.name,
            model=self.backend.model,
            timings=Timings(self._llm_s, self._exec_s, time.perf_counter() - self._started),
            notes=self._notes(trajectory),
            stdout=self._last_stdout,
            tokens=dict(self._tokens),
            settings=self.settings.describe(),
            explanation=self._explanation_of(plan),
            recalled=self.recalled,
            **self._effect(trajectory),
        )

    def _explanation_of(self, plan: Plan | None) -> Explanation | None:
        """The skills' explanation, or the model's if the user asked for it; no LLM call here."""
        if plan is None:
            return None
        lines = explain_code(plan.code)
        return (
            Explanation("skills", tuple(lines))
            if lines is not None
            else self._model_explanations.get(plan.code)
        )

    def _effect(self, trajectory: Trajectory | None) -> dict[str, Any]:
        """The measured effect of the result and what it contradicts in the user's words."""
        if trajectory is None:
            return {}
        axes = self.settings.axes.frame
        effect = measure_effect(self.case.trajectory, trajectory, self.case.scene.objects, axes)
        effect = replace(effect, constraint_moves=self._last_moves)
        return {
            "effect": effect,
            "contradictions": tuple(contradictions(" ".join(self._asked), effect, axes)),
        }

    def _notes(self, trajectory: Trajectory | None) -> tuple[ReviewNote, ...]:
        if trajectory is None:
            return ()
        sandbox_notes = tuple(ReviewNote(note.reader, note.message) for note in self._left_out)
        sandbox_notes += tuple(ReviewNote("sandbox", note) for note in self._last_notes)
        return sandbox_notes + tuple(review_notes(self.case.trajectory, trajectory))

    def _start_log(self) -> None:
        if self.store is None:
            return
        self.session_id = self.store.start_session(NewSession(
            case_name=self.case.name,
            case_source=str(self.case.source) if self.case.source else None,
            instruction=self.case.instruction,
            backend=self.backend.name,
            model=self.backend.model,
            case=self.case.to_dict(),
            settings=self.settings.describe(),
        ))  # fmt: skip

    def _record(self, turn: Turn) -> None:
        self.turns.append(turn)
        completion = turn.completion
        self._log(turn.kind, turn.plan.code if turn.plan else "", {
            "plan": list(turn.plan.steps) if turn.plan else None,
            "answer": completion.text if completion else None,
            "request": [{"role": m.role, "content": m.content} for m in self.messages[:-1]],
            "user_text": turn.user_text,
            "usage": vars(completion.usage) if completion else None,
        }, turn.error, {"llm": completion.duration_s if completion else None})  # fmt: skip

    def _log(
        self,
        kind: str,
        code: str,
        details: dict[str, Any],
        error: str | None,
        timings: dict[str, Any],
    ) -> None:
        if self.store is None or self.session_id is None:
            return
        self.store.log_exchange(self.session_id, NewExchange(
            kind=kind,
            code=code,
            user_text=details.pop("user_text", None),
            request=details.pop("request", None),
            answer=details.pop("answer", None),
            plan="\n".join(details.get("plan") or []),
            outcome=details,
            error=error,
            timings=timings,
        ))  # fmt: skip
