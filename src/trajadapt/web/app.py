"""The review page's HTTP API (FastAPI) over the same session API the CLI uses.

Routes: the page and its static files (plotly.js comes from the installed plotly package: no CDN);
``/api/cases`` (a folder of case files), ``/api/upload`` (a case file's text, checked), and
``/api/sessions`` (start, state, feedback, undo, approve, cancel, result download, simulate). Errors are
JSON ``{"error": "..."}`` in words; a stack trace never reaches the page.
"""

from __future__ import annotations

import json
import time
from collections.abc import Collection
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any, Literal

from fastapi import FastAPI, Request
from fastapi.exceptions import RequestValidationError
from fastapi.responses import FileResponse, JSONResponse, Response
from pydantic import BaseModel, Field

from trajadapt.checks.constraints import Constraints
from trajadapt.checks.robot_limits import user_constraints
from trajadapt.errors import BackendError, BackendTimeout, InputError, SessionStateError, TrajadaptError
from trajadapt.model.case import Case, case_from_dict
from trajadapt.model.scene import NAME_CHARS
from trajadapt.model.trajectory import parse_json_text
from trajadapt.safe_text import safe_text
from trajadapt.web.guards import (
    LOOPBACK_HOSTS,
    MAX_BODY_BYTES,
    BodyLimit,
    attachment,
    install_host_check,
    install_origin_check,
    install_security_headers,
    install_token_check,
)
from trajadapt.web.history import stored_session
from trajadapt.web.live import Jobs, LiveSession, add_version, make_room, result_file_name, work_folder
from trajadapt.web.services import Services

STATIC = Path(__file__).parent / "static"
MAX_UPLOAD_BYTES = MAX_BODY_BYTES


class LimitsBody(BaseModel):
    """The page's limits: a robot's defaults and the user's own; unset fields keep the server's."""

    robot: str | None = None
    clearance: float | None = None
    max_speed: float | None = None
    fixed_ends: Literal["none", "start", "goal", "both"] = "none"
    workspace: tuple[float, float, float, float, float, float] | None = None
    reach_base: tuple[float, float, float] | None = None
    reach: tuple[float, float] | None = None

    def constraints(self) -> Constraints:
        """The user's limits, checked (raises InputError in words)."""
        return user_constraints(**self.model_dump(exclude={"robot"}))


class StartBody(BaseModel):
    """Start a session on a case with an instruction, under the page's limits."""

    case: dict[str, Any]
    instruction: str
    name: str = "case"
    limits: LimitsBody | None = None


class TextBody(BaseModel):
    """Feedback text, and whether it changes the original trajectory or the current result."""

    text: str
    on: Literal["original", "current"] = "original"


class UndoBody(BaseModel):
    """The version to go back to."""

    version: int


class ForgetBody(BaseModel):
    """The remembered example to forget."""

    example: str = Field(min_length=1, max_length=64)


class SimulateBody(BaseModel):
    """The robot to run the result on."""

    robot: str


@dataclass
class ServerState:
    """Everything the routes share."""

    services: Services
    token: str | None = None
    live: dict[str, LiveSession] = field(default_factory=dict)
    jobs: Jobs = field(default_factory=Jobs)


def create_app(services: Services, token: str | None = None, allowed_hosts: Collection[str] = ()) -> FastAPI:
    """The review server's app.

    Args:
        services: the backend, sandbox, log and simulator the sessions use.
        token: if set, it must come with every API request.
        allowed_hosts: host names the server answers to besides the loopback names (the bound
            address, names given with --allowed-host).
    """
    app = FastAPI(title="trajadapt review", docs_url=None, redoc_url=None)
    state = ServerState(services, token)
    _install_errors(app)
    install_token_check(app, token)
    install_origin_check(app, (*LOOPBACK_HOSTS, *allowed_hosts))
    install_host_check(app, (*LOOPBACK_HOSTS, *allowed_hosts))
    install_security_headers(app)
    app.add_middleware(BodyLimit, limit=MAX_UPLOAD_BYTES)
    _page_routes(app)
    _case_routes(app, state)
    _session_routes(app, state)
    _output_routes(app, state)
    return app


def _install_errors(app: FastAPI) -> None:
    @app.exception_handler(TrajadaptError)
    async def trajadapt_error(_: Request, exc: TrajadaptError) -> JSONResponse:
        return JSONResponse({"error": safe_text(exc)}, status_code=_status_of(exc))

    @app.exception_handler(RequestValidationError)
    async def validation_error(_: Request, exc: RequestValidationError) -> JSONResponse:
        problems = "; ".join(f"{'.'.join(str(p) for p in e['loc'][1:])}: {e['msg']}" for e in exc.errors())
        return JSONResponse({"error": f"bad request: {problems}"}, status_code=422)

    @app.exception_handler(Exception)
    async def internal_error(_: Request, exc: Exception) -> JSONResponse:
        return JSONResponse(
            {"error": f"internal error ({type(exc).__name__}); see the server's log"}, status_code=500
        )


def _status_of(exc: TrajadaptError) -> int:
    """The HTTP status for one of our errors: the client's fault (4xx) or the LLM server's (5xx)."""
    statuses: list[tuple[type[TrajadaptError], int]] = [
        (SessionStateError, 409), (BackendTimeout, 504), (BackendError, 502),
    ]  # fmt: skip
    return next((status for kind, status in statuses if isinstance(exc, kind)), 400)


def _page_routes(app: FastAPI) -> None:
    @app.get("/", include_in_schema=False)
    def page() -> FileResponse:
        return FileResponse(STATIC / "index.html")

    @app.get("/static/{name}", include_in_schema=False)
    def static(name: str) -> FileResponse:
        if name == "plotly.min.js":
            return FileResponse(_plotly_js(), media_type="text/javascript")
        path = STATIC / name
        if name not in {p.name for p in STATIC.iterdir()}:
            raise InputError(f"no static file {name!r}")
        return FileResponse(path)


def _plotly_js() -> Path:
    import plotly

    return Path(plotly.__file__).parent / "package_data" / "plotly.min.js"


def _case_routes(app: FastAPI, state: ServerState) -> None:
    @app.get("/api/cases")
    def cases() -> dict[str, Any]:
        return {"folder": str(state.services.cases_dir or ""), "cases": state.services.case_names()}

    @app.get("/api/cases/{name:path}")
    def case(name: str) -> dict[str, Any]:
        loaded = state.services.load_named_case(name)
        return {"name": loaded.name, **loaded.to_dict()}

    @app.post("/api/upload")
    async def upload(request: Request) -> dict[str, Any]:
        body = await request.body()
        try:
            data = parse_json_text(body.decode("utf-8"), "the upload")
        except (UnicodeDecodeError, InputError) as exc:
            raise InputError(f"the file is not JSON ({exc}); upload a case file in the OVITA format") from exc
        name = safe_text(Path(request.query_params.get("name", "uploaded")).stem, NAME_CHARS) or "uploaded"
        uploaded = case_from_dict(data, f"uploaded file {name!r}", name=name)
        return {"name": uploaded.name, **uploaded.to_dict()}


def _session_routes(app: FastAPI, state: ServerState) -> None:
    @app.get("/api/sessions")
    def sessions() -> dict[str, Any]:
        live = [{"id": s.id, "case_name": s.case.name, "instruction": s.case.instruction,
                 "status": s.status, "live": True} for s in state.live.values()]  # fmt: skip
        known = {session_id for s in state.live.values() for session_id in s.session.session_ids}
        stored = [
            {**s.to_dict(), "live": False} for s in state.services.stored_sessions() if s.id not in known
        ]
        return {"sessions": live + stored}

    @app.post("/api/sessions")
    def start(body: StartBody) -> dict[str, Any]:
        case = case_from_dict(body.case, "the case", name=body.name).with_instruction(body.instruction)
        if not case.instruction:
            raise InputError("type an instruction first")
        limits = body.limits or LimitsBody()
        live = _new_live(state, case, limits.constraints(), limits.robot)
        return live.to_dict()

    @app.get("/api/sessions/{session_id}")
    def session(session_id: str) -> dict[str, Any]:
        live = state.live.get(session_id)
        if live is not None:
            return live.to_dict()
        return stored_session(state.services.store, session_id)

    @app.post("/api/sessions/{session_id}/feedback")
    def feedback(session_id: str, body: TextBody) -> dict[str, Any]:
        live = _find(state, session_id)
        text = body.text.strip()
        if not text:
            raise InputError("the feedback is empty; say what should change in the plan")
        before = len(live.session.versions) - 1

        def work() -> None:
            plan = live.session.feedback(text, on=body.on)
            live.result = None
            add_version(live, text, plan, body.on)

        state.jobs.start(live, "asking for a new plan", work, lambda: _drop_after(live, before))
        return live.to_dict()

    @app.post("/api/sessions/{session_id}/undo")
    def undo(session_id: str, body: UndoBody) -> dict[str, Any]:
        live = _find(state, session_id)
        if live.status == "working":
            raise SessionStateError("wait for the running request or cancel it first")
        if not 0 <= body.version < len(live.versions):
            raise InputError(f"there is no version {body.version}")
        with live.lock:
            live.session.rewind(live.versions[body.version].checkpoint)
            del live.versions[body.version + 1 :]
            live.current, live.result, live.simulation, live.status = body.version, None, None, "ready"
        return live.to_dict()

    @app.post("/api/sessions/{session_id}/approve")
    def approve(session_id: str) -> dict[str, Any]:
        live = _find(state, session_id)

        def work() -> None:
            result = live.session.approve()
            if not result.ok:
                raise SessionStateError(f"the approved code did not give a trajectory: {result.error}")
            live.result = result

        state.jobs.start(live, "running the approved code", work, lambda: setattr(live, "result", None))
        return live.to_dict()

    @app.post("/api/sessions/{session_id}/forget")
    def forget(session_id: str, body: ForgetBody) -> dict[str, Any]:
        live = _find(state, session_id)
        if not state.services.forget(body.example):
            raise InputError(f"no remembered example {body.example!r} (or memory is off on this server)")
        live.forgotten.add(body.example)
        return live.to_dict()

    @app.post("/api/sessions/{session_id}/cancel")
    def cancel(session_id: str) -> dict[str, Any]:
        live = _find(state, session_id)
        state.jobs.cancel(live)
        return live.to_dict()


def _new_live(state: ServerState, case: Case, limits: Constraints, robot: str | None) -> LiveSession:
    make_room(state.live)
    session = state.services.new_session(case, limits, robot)
    live = LiveSession(case=case, session=session, status="ready")
    session.report_progress_to(live.say)

    def work() -> None:
        add_version(live, case.instruction, session.draft())

    state.live[live.id] = live
    state.jobs.start(live, "asking for a plan", work, lambda: None)
    return live


def _drop_after(live: LiveSession, checkpoint: int) -> None:
    """Roll back what a cancelled feedback request added."""
    if len(live.session.versions) - 1 > checkpoint >= 0:
        live.session.rewind(checkpoint)
    while live.versions and live.versions[-1].checkpoint > checkpoint:
        live.versions.pop()
    live.current = len(live.versions) - 1


def _find(state: ServerState, session_id: str) -> LiveSession:
    live = state.live.get(session_id)
    if live is None:
        raise SessionStateError(
            f"session {session_id!r} is not open on this server; a stored session can be viewed, not "
            "changed: start a new one with the same case"
        )
    live.used = time.monotonic()
    return live


def _output_routes(app: FastAPI, state: ServerState) -> None:
    @app.get("/api/sessions/{session_id}/result")
    def result(session_id: str) -> Response:
        live = _find(state, session_id)
        if live.result is None:
            raise SessionStateError("there is no approved result yet")
        text = json.dumps(live.session.to_dict(live.result), indent=1)
        headers = {"Content-Disposition": attachment(result_file_name(live))}
        return Response(text, media_type="application/json", headers=headers)

    @app.post("/api/sessions/{session_id}/simulate")
    def simulate(session_id: str, body: SimulateBody) -> dict[str, Any]:
        live = _find(state, session_id)
        if live.result is None or live.result.trajectory is None:
            raise SessionStateError("approve a plan first; the simulator runs the approved result")
        folder = work_folder(state.services.work_dir, live)
        result = live.result

        def work() -> None:
            live.simulation = state.services.simulate(result, body.robot, folder)
            live.result = result

        state.jobs.start(live, f"simulating on the {body.robot}", work, lambda: None)
        return live.to_dict()

    @app.get("/api/sessions/{session_id}/files/{name}")
    def output_file(session_id: str, name: str) -> FileResponse:
        live = _find(state, session_id)
        folder = work_folder(state.services.work_dir, live)
        if name not in {p.name for p in folder.iterdir()}:
            raise InputError(f"no file {name!r} for this session")
        return FileResponse(folder / name)
