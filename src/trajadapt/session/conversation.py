"""The conversation about one case: messages, turns, a checkpoint after each plan, and undo.

Every answer is read against the user's words (``trajadapt.readers``) before it becomes a plan; a
checkpoint keeps where the conversation stood, the words said by then and the readers' notes, so
``rewind`` cuts back everything said after a version, including the words the readers read.
"""

from __future__ import annotations

import time
from dataclasses import replace

from trajadapt.backends.base import Backend, ChatMessage, ChatRequest, Completion
from trajadapt.clauses.grammar import MAX_CLAUSES, clause_answer_grammar
from trajadapt.code_parse import same_program
from trajadapt.errors import AnswerParseError, SessionStateError
from trajadapt.files.store import Store
from trajadapt.llm.answer import Plan, answer_json, parse_answer
from trajadapt.llm.answer_grammar import answer_grammar
from trajadapt.llm.plan_stream import PlanStream
from trajadapt.memory import MemoryBank, answer_to_same_words, asks_all_of
from trajadapt.model.case import Case
from trajadapt.prompts import chosen_examples, first_messages, render
from trajadapt.readers import ReaderNote, read_against_words
from trajadapt.readers.clause_split import split_clauses
from trajadapt.readers.request_words import request_words
from trajadapt.safe_text import ANSWER_CHARS, INSTRUCTION_CHARS, safe_text
from trajadapt.sandbox.runner import Sandbox
from trajadapt.session.log import SessionLog
from trajadapt.session.records import Checkpoint, Explanation, ProgressCallback, Turn, TurnKind
from trajadapt.session.settings import SessionSettings

Mark = tuple[int, int, int, list[ReaderNote]]
Steps = tuple[int, int]  # the fewest and the most skill calls an answer may have


class Conversation:
    """Messages to and from the model about one case, each answer read against the user's words."""

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
        self.case, self.backend, self.sandbox, self.memory = case, backend, sandbox, memory
        self.settings = settings or SessionSettings()
        self.log = SessionLog(store)
        self.on_progress = on_progress or (lambda _message: None)
        remembered = memory.examples() if memory is not None else []
        s = self.settings
        self.request = request_words(case.instruction, case.scene.names())
        """What the model is asked: the instruction less what it only says about the path as it is now."""
        asked = case.with_instruction(self.request)
        chosen = chosen_examples(asked, s.mode, s.examples, remembered, s.retrieval)
        self.messages: list[ChatMessage] = list(
            first_messages(asked, s.axes, s.mode, s.waypoints_in_prompt, chosen=chosen)
        )
        self.turns: list[Turn] = []
        self.recalled_examples = tuple(example for example in chosen if example.remembered)
        self._remembered_as = ""
        self._llm_s = self._exec_s = 0.0
        self._tokens = {"prompt": 0, "completion": 0}
        self._asked: list[str] = [case.instruction]  # the user's words: instruction, then feedback
        self._left_out: list[ReaderNote] = []  # what the readers changed in the current plan
        self._model_explanations: dict[str, Explanation] = {}
        self._started = time.perf_counter()
        self._checkpoints: list[Checkpoint] = []  # right after each plan

    @property
    def recalled(self) -> tuple[str, ...]:
        """Ids of the user's remembered examples the first prompt showed."""
        return tuple(example.remembered for example in self.recalled_examples)

    @property
    def session_id(self) -> str | None:
        """This session's id in the log (None when nothing is logged)."""
        return self.log.session_id

    @property
    def plan(self) -> Plan | None:
        """The latest plan the LLM proposed."""
        return next((turn.plan for turn in reversed(self.turns) if turn.plan), None)

    @property
    def versions(self) -> list[Plan]:
        """Every plan of the conversation so far, oldest first (index = version)."""
        return [checkpoint.plan for checkpoint in self._checkpoints]

    @property
    def _names(self) -> list[str]:
        return self.case.scene.names()

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
            instruction=self.request,
            previous_plan=previous.numbered() or "(no plan)",
        )))  # fmt: skip
        return self._ask("feedback", text.strip())

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
        code = self._require_plan().code
        self.log.exchange("undo", code, {"user_text": f"back to version {version}"}, None, {})
        return self._require_plan()

    def _clauses(self) -> tuple[str, ...] | None:
        """The instruction's clauses when the first answer keeps a step per clause, else None.

        That is in skills mode with the grammar, where the backend follows it (``clause_steps``).
        """
        settings = self.settings
        if not (settings.mode == "skills" and settings.grammar and settings.clause_steps):
            return None
        if not self.backend.follows_grammar:
            return None
        clauses = split_clauses(self.request, self._names)
        return clauses if len(clauses) <= MAX_CLAUSES else None

    def _mark(self) -> Mark:
        """What a second answer that is not kept must leave as it was."""
        return len(self.messages), len(self.turns), len(self._checkpoints), list(self._left_out)

    def _rewind_to(self, mark: Mark) -> None:
        messages, turns, checkpoints, self._left_out = mark
        del self.messages[messages:], self.turns[turns:], self._checkpoints[checkpoints:]

    def _require_plan(self) -> Plan:
        plan = self.plan
        if plan is None:
            raise SessionStateError("there is no plan yet; call draft() first")
        return plan

    def _ask(
        self, kind: TurnKind, user_text: str, first: bool = False, step_range: Steps | None = None
    ) -> Plan:
        """Send the conversation (its last user message already in place) and parse the answer.

        ``first``: the first answer, under the grammar from the instruction's clauses where it applies;
        ``step_range``: the fewest and the most skill calls the answer may have (the scene's grammar).
        """
        for retry in range(self.settings.format_retries + 1):
            completion = self._complete(first, step_range)
            self.messages.append(ChatMessage("assistant", completion.text))
            try:
                plan = self._read_against_words(parse_answer(completion.text))
            except AnswerParseError as exc:
                self._record(Turn(kind, user_text, None, completion, str(exc)))
                if retry >= self.settings.format_retries:
                    raise
                self.messages.append(ChatMessage("user", render(
                    "retry_format", problem=str(exc), instruction=self.request
                )))  # fmt: skip
                kind, user_text = "format-retry", str(exc)
                continue
            self._record(Turn(kind, user_text, plan, completion))
            self._checkpoints.append(Checkpoint(
                len(self.messages), len(self.turns), plan, tuple(self._asked), tuple(self._left_out)
            ))  # fmt: skip
            return plan
        raise AssertionError("unreachable")

    def _record(self, turn: Turn) -> None:
        self.turns.append(turn)
        self.log.turn(turn, self.messages)

    def _read_against_words(self, plan: Plan) -> Plan:
        """The plan after the readers of ``trajadapt.readers`` (skills mode), their changes noted."""
        self._left_out = []
        if self.settings.mode != "skills" or not self.settings.read_against_words:
            return plan
        approved = next(
            (
                e
                for e in self.recalled_examples
                if same_program(e.code, plan.code) and asks_all_of(e, self.case.instruction)
            ),
            None,
        )
        if approved is not None:  # the user's own approved program for a request asking all this one does
            kept = f"the program of remembered example {approved.remembered}, kept as approved"
            self._left_out = [ReaderNote("memory", kept)]
            return plan
        code, self._left_out = read_against_words(plan.code, self._asked, self._names)
        return replace(plan, code=code) if self._left_out else plan

    def _complete(self, first: bool = False, step_range: Steps | None = None) -> Completion:
        """Send the conversation so far and count the time and tokens of the answer.

        The first answer to words the user has approved an answer to before is that answer, from
        memory, without asking the model (``memory.answer_to_same_words``).
        """
        same = answer_to_same_words(self.case.instruction, self.recalled_examples) if first else None
        if same is not None:
            self.on_progress(f"answered from remembered example {same.remembered} (the same words)")
            text = answer_json(same.high_level_plan, same.code)
            return Completion(text=text, model=f"memory:{same.remembered}")
        self.on_progress(f"asking {self.backend.name} ({self.backend.model})")
        steps: list[str] = []

        def show(step: str) -> None:  # the plan so far, while the code is still being written
            steps.append(step)
            self.on_progress("plan: " + " ".join(steps))

        request = ChatRequest(
            messages=tuple(self.messages),
            temperature=self.settings.temperature,
            max_tokens=self.settings.max_tokens,
            seed=self.settings.seed,
            grammar=self._answer_grammar(first, step_range),
            on_text=PlanStream(show).feed,
        )
        started = time.perf_counter()
        completion = self.backend.complete(request)
        completion = replace(completion, text=safe_text(completion.text, ANSWER_CHARS))
        self._llm_s += time.perf_counter() - started
        self._tokens["prompt"] += completion.usage.prompt_tokens or 0
        self._tokens["completion"] += completion.usage.completion_tokens or 0
        return completion

    def _answer_grammar(self, first: bool = False, step_range: Steps | None = None) -> str | None:
        """The scene's answer grammar; for the first answer, the one from the instruction's clauses."""
        if self.settings.mode != "skills" or not self.settings.grammar:
            return None
        clauses = self._clauses() if first else None
        if clauses:
            return clause_answer_grammar(clauses, tuple(self._names)).to_gbnf()
        if step_range is not None:
            return answer_grammar(tuple(self._names), step_range).to_gbnf()
        return answer_grammar(tuple(self._names)).to_gbnf()
