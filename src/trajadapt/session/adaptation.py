"""AdaptationSession: draft a plan, take feedback, approve, execute with automatic repair.

The session orchestrates: the conversation with the model (``prompts``, ``llm``), the readers of the
answer (``readers``), the run of the code (``session.execution``) and the result record
(``session.records``). The CLI and any other front end are thin views over its methods; it does no
I/O of its own beyond the backend, the sandbox, the memory and the log it is given.
"""

from __future__ import annotations

import re
import time
from dataclasses import replace
from typing import Any

from trajadapt.backends.base import ChatMessage, ChatRequest
from trajadapt.checks.contradictions import contradictions
from trajadapt.checks.effect import measure_effect
from trajadapt.checks.review import ReviewNote, review_notes
from trajadapt.clauses.shape import STEPS_PER_CLAUSE, asking_clauses, shape_findings
from trajadapt.errors import AnswerParseError, BackendError, SessionStateError
from trajadapt.llm.answer import Plan
from trajadapt.llm.answer_grammar import MAX_STEPS
from trajadapt.model.trajectory import Trajectory
from trajadapt.prompts import render
from trajadapt.readers import ReaderNote
from trajadapt.readers.clause_split import split_clauses
from trajadapt.safe_text import ANSWER_CHARS, safe_text
from trajadapt.session.clause_check import count, findings_by_clause
from trajadapt.session.conversation import Conversation
from trajadapt.session.execution import Execution, execute
from trajadapt.session.records import (
    AdaptationResult,
    Explanation,
    Failure,
    Outcome,
    Timings,
    Turn,
)
from trajadapt.skills import SKILLS, signature_line, summary
from trajadapt.skills.explain import explain_code


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


class AdaptationSession(Conversation):
    """The conversation about one case, and what comes of it: approval, repairs, the result."""

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
        self.log.start(self.case, self.backend.name, self.backend.model, self.settings.describe())
        plan = self._ask("draft", self.case.instruction, first=True)
        clauses = self._clauses()
        if clauses and self.settings.clause_check:
            plan = self._second_answer_by_clause(plan, clauses)
        elif self.settings.shape_check and self.settings.mode == "skills":
            plan = self._second_answer_by_shape(plan)
        return plan

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

    def preview(self) -> Outcome:
        """Run the current plan's code once, without repair: the proposed trajectory, or what went wrong."""
        return self._execute(self._require_plan()).outcome

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

    def failure(self, failure: Failure) -> AdaptationResult:
        """The result of a session that ended without running code (e.g. the LLM gave no readable plan)."""
        return self._result(self.plan, Execution(failure), 0)

    def _run_approved(self) -> AdaptationResult:
        plan = self._require_plan()
        attempts = 0
        while True:
            attempts += 1
            self.on_progress(f"running the code (attempt {attempts})")
            run = self._execute(plan)
            if isinstance(run.outcome, Trajectory):
                plan, run = self._second_look(plan, run)
                return self._result(plan, run, attempts)
            failed = run.outcome
            if attempts > self.settings.repair_attempts:
                return self._result(plan, run, attempts)
            self.on_progress(f"the code failed, asking for a repair: {failed}")
            problem = failed.message + (
                skill_hints(plan.code, failed.message) if self.settings.mode == "skills" else ""
            )
            self.messages.append(ChatMessage("user", render(
                "repair", problem=problem, instruction=self.request
            )))  # fmt: skip
            try:
                plan = self._ask("repair", failed.message)
            except AnswerParseError as exc:
                unreadable = Failure("RepairUnreadable", f"repair answer unreadable: {exc}")
                return self._result(plan, replace(run, outcome=unreadable), attempts)
            except BackendError as exc:  # keep what failed; the repair itself could not be asked
                unasked = Failure(failed.kind, f"{failed} (no repair: {type(exc).__name__}: {exc})")
                return self._result(plan, replace(run, outcome=unasked), attempts)

    def _second_look(self, plan: Plan, run: Execution) -> tuple[Plan, Execution]:
        """With ``repair_contradictions``: one more answer when the result contradicts the instruction.

        The new code is kept only if it runs and its result contradicts the words less; otherwise the
        first result stands, with its own notes, output and plan (and its flags go to the reviewer).
        """
        if not self.settings.repair_contradictions:
            return plan, run
        flags = self._effect(run)["contradictions"]
        if not flags:
            return plan, run
        self.on_progress("the result contradicts the instruction, asking once more")
        kept = self._mark()
        problems = "\n".join(f"- {flag}" for flag in flags)
        self.messages.append(ChatMessage("user", render(
            "contradiction", problems=problems, instruction=self.request
        )))  # fmt: skip
        try:
            second = self._ask("repair", "; ".join(flags))
        except (AnswerParseError, BackendError):
            self._rewind_to(kept)
            return plan, run
        again = self._execute(second)
        if again.trajectory is not None and len(self._effect(again)["contradictions"]) < len(flags):
            return second, again
        self._rewind_to(kept)
        return plan, run

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
            "clause_contradiction", problems=problems, instruction=self.request
        )))  # fmt: skip
        try:
            second = self._ask("draft", problems, first=True)
        except (AnswerParseError, BackendError):
            second = None
        again = self._clause_findings(self.turns[-1], clauses) if second is not None else None
        if second is not None and again is not None and count(again) < count(first):
            said = f"a step contradicted its words ({problems[2:]}); asked once more"
            self._left_out.append(ReaderNote("clause-check", said))
            return second
        self._rewind_to(kept)
        said = f"a step contradicts its words ({problems[2:]}); asked once more, no better"
        self._left_out = [*self._left_out, ReaderNote("clause-check", said)]
        return plan

    def _second_answer_by_shape(self, plan: Plan) -> Plan:
        """The first answer asked afresh when it changes nothing or repeats a step (``clauses.shape``).

        The task is sent again with what was wrong and the requests it holds (``prompts/shape.md``),
        without the first answer in view (a small model shown its answer repeats it), under a grammar
        that admits one to two steps per request. The answer with fewer findings is kept, as if it had
        been the first; the other leaves only a note (the log keeps both).
        """
        asking = asking_clauses(split_clauses(self.request, self._names), self._names)
        first = shape_findings(plan.code, asking)
        if not first:
            return plan
        self.on_progress("the answer does not fit the request, asking afresh")
        said = f"the answer did not fit the request ({'; '.join(first)})"
        before = (list(self.messages), list(self.turns), list(self._checkpoints), list(self._left_out))
        task = self.messages[1]  # after the system prompt: draft() is the session's first request
        self._rewind_to((1, 0, 0, []))
        requests = "\n".join(f"{i}. {clause}" for i, clause in enumerate(asking, start=1))
        note = render("shape", problems="; ".join(first), requests=requests)
        self.messages.append(ChatMessage("user", f"{task.content}\n\n{note}"))
        most = min(MAX_STEPS, STEPS_PER_CLAUSE * len(asking))
        try:
            second: Plan | None = self._ask("draft", said, step_range=(1, most))
        except (AnswerParseError, BackendError):
            second = None
        if second is not None and len(shape_findings(second.code, asking)) < len(first):
            self.messages[1] = task  # the conversation goes on from the user's own words
            self._left_out.append(ReaderNote("shape-check", f"{said}; asked afresh, kept the new answer"))
            return second
        self.messages, self.turns, self._checkpoints, left_out = before
        self._left_out = [*left_out, ReaderNote("shape-check", f"{said}; asked afresh, no better")]
        return plan

    def _clause_findings(self, turn: Turn, clauses: tuple[str, ...]) -> list[tuple[str, list[str]]]:
        if turn.completion is None or turn.plan is None:
            return []
        found, seconds = findings_by_clause(
            turn.completion.text, clauses, self.case, self.sandbox, self.settings
        )
        self._exec_s += seconds
        return found

    def _execute(self, plan: Plan) -> Execution:
        s = self.settings
        held = s.mode == "skills" and s.grammar and self.backend.follows_grammar
        run = execute(plan.code, self.case, self.sandbox, s, self._asked, held)
        self._exec_s += run.seconds
        self.log.execution(plan.code, run)
        return run

    def _result(self, plan: Plan | None, run: Execution, attempts: int) -> AdaptationResult:
        trajectory = run.trajectory
        return AdaptationResult(
            case=self.case,
            status="ok" if trajectory is not None else "error",
            plan=plan,
            trajectory=trajectory,
            failure=run.outcome if isinstance(run.outcome, Failure) else None,
            attempts=attempts,
            backend=self.backend.name,
            model=self.backend.model,
            timings=Timings(self._llm_s, self._exec_s, time.perf_counter() - self._started),
            notes=self._notes(run),
            stdout=run.stdout,
            tokens=dict(self._tokens),
            settings=self.settings.describe(),
            explanation=self._explanation_of(plan),
            recalled=self.recalled,
            answer=plan.raw_text if plan is not None else "",
            **self._effect(run),
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

    def _effect(self, run: Execution) -> dict[str, Any]:
        """The measured effect of the result and what it contradicts in the user's words."""
        if run.trajectory is None:
            return {}
        axes = self.settings.axes.frame
        effect = measure_effect(self.case.trajectory, run.trajectory, self.case.scene.objects, axes)
        effect = replace(effect, constraint_moves=run.moves)
        return {
            "effect": effect,
            "contradictions": tuple(contradictions(self._asked, effect, axes)),
        }

    def _notes(self, run: Execution) -> tuple[ReviewNote, ...]:
        if run.trajectory is None:
            return ()
        notes = tuple(ReviewNote(note.reader, note.message) for note in self._left_out)
        notes += tuple(ReviewNote("sandbox", note) for note in run.notes)
        return notes + tuple(review_notes(self.case.trajectory, run.trajectory))
