"""What stands between the review server and a hostile browser or client.

- **Allowed hosts**: a request whose ``Host`` header is not one of the server's names is refused
  (421), so a page on another site cannot reach a loopback server through DNS rebinding. The header
  is parsed strictly: a name or address, then at most ``:port`` (``[::1]evil.example`` is no host).
- **Origin**: a state-changing request (POST, PUT, PATCH, DELETE) that comes from a page of another
  origin (its ``Origin`` is not the server's, or ``Sec-Fetch-Site`` says cross-site) is refused (403),
  so another site cannot approve a session with a no-cors form post.
- **Framing**: every answer forbids being framed by another origin (``X-Frame-Options: DENY``,
  ``frame-ancestors 'none'``), and says not to guess content types or send referrers.
- **Body deadline**: a body not received within ``BODY_TIMEOUT_S`` is refused (408) and its
  connection's memory released, so half-sent bodies cannot hold the server.
- **Body limit**: no request body larger than ``MAX_BODY_BYTES`` is read, whether it declares its
  length or streams it (413).
- **Token**: with a token set, every ``/api/`` request must carry it; the comparison takes constant
  time and any wrong or malformed token (non-ASCII included) is a 401.
- **Download names**: ``Content-Disposition`` per RFC 6266, an ASCII fallback plus ``filename*``.
"""

from __future__ import annotations

import asyncio
import hmac
import re
from collections.abc import Awaitable, Callable, Collection, MutableMapping
from typing import Any
from urllib.parse import quote

from fastapi import FastAPI, Request
from fastapi.responses import JSONResponse, Response

MAX_BODY_BYTES = 8 * 1024 * 1024
BODY_TIMEOUT_S = 30.0
STATE_CHANGING = frozenset({"POST", "PUT", "PATCH", "DELETE"})
SECURITY_HEADERS = {
    "x-frame-options": "DENY",
    "content-security-policy": "frame-ancestors 'none'",
    "x-content-type-options": "nosniff",
    "referrer-policy": "no-referrer",
}
HOST = re.compile(
    r"^(?:\[(?P<ipv6>[0-9a-f:.]+)\](?::\d{1,5})?"  # [::1] or [::1]:8765
    r"|(?P<bare>[0-9a-f]*:[0-9a-f]*:[0-9a-f:.]*)"  # ::1, unbracketed and so without a port
    r"|(?P<name>[a-z0-9](?:[a-z0-9.-]*[a-z0-9])?\.?)(?::\d{1,5})?)$"
)
LOOPBACK_HOSTS = ("127.0.0.1", "localhost", "::1")
TOKEN_HEADER = "x-trajadapt-token"

Scope = MutableMapping[str, Any]
Message = MutableMapping[str, Any]
Receive = Callable[[], Awaitable[Message]]
Send = Callable[[Message], Awaitable[None]]
ASGIApp = Callable[[Scope, Receive, Send], Awaitable[None]]


def host_name(header: str) -> str:
    """The host part of a ``Host`` header, lower case, without port, brackets or a trailing dot.

    '' for anything that is not exactly a host name or address and an optional port.
    """
    found = HOST.match(header.strip().lower())
    if found is None:
        return ""
    return found.group("ipv6") or found.group("bare") or (found.group("name") or "").rstrip(".")


def install_security_headers(app: FastAPI) -> None:
    """Add ``SECURITY_HEADERS`` to every answer."""

    @app.middleware("http")
    async def add_headers(request: Request, call_next: Callable[[Request], Awaitable[Response]]) -> Response:
        response = await call_next(request)
        for name, value in SECURITY_HEADERS.items():
            response.headers.setdefault(name, value)
        return response


def install_origin_check(app: FastAPI, allowed: Collection[str]) -> None:
    """Refuse state-changing requests sent by a page of another origin."""
    names = {host_name(name) for name in allowed}

    @app.middleware("http")
    async def check_origin(request: Request, call_next: Callable[[Request], Awaitable[Response]]) -> Response:
        if request.method in STATE_CHANGING and not same_origin(request.headers, names):
            return JSONResponse(
                {"error": "a page of another site cannot change this server's sessions"}, status_code=403
            )
        return await call_next(request)


def same_origin(headers: Any, names: Collection[str]) -> bool:
    """Whether a request comes from the server's own page, or from no page at all (a script, curl)."""
    if headers.get("sec-fetch-site", "").lower() == "cross-site":
        return False
    origin = headers.get("origin")
    if origin is None:
        return True
    scheme, _, rest = origin.strip().lower().partition("://")
    return scheme in ("http", "https") and host_name(rest) in names


def install_host_check(app: FastAPI, allowed: Collection[str]) -> None:
    """Refuse requests addressed to any other host name than ``allowed``."""
    names = {host_name(name) for name in allowed}

    @app.middleware("http")
    async def check_host(request: Request, call_next: Callable[[Request], Awaitable[Response]]) -> Response:
        if host_name(request.headers.get("host", "")) not in names:
            return JSONResponse(
                {"error": "this server does not answer to that host name; open the URL the server printed"},
                status_code=421,
            )
        return await call_next(request)


def install_token_check(app: FastAPI, token: str | None) -> None:
    """Require ``token`` (header or ``?token=``) on every API request, when one is set."""
    if token is None:
        return
    expected = token.encode("utf-8")

    @app.middleware("http")
    async def check_token(request: Request, call_next: Callable[[Request], Awaitable[Response]]) -> Response:
        given = request.headers.get(TOKEN_HEADER) or request.query_params.get("token") or ""
        if request.url.path.startswith("/api/") and not tokens_match(given, expected):
            return JSONResponse(
                {"error": "missing or wrong token; open the URL the server printed"}, status_code=401
            )
        return await call_next(request)


def tokens_match(given: str, expected: bytes) -> bool:
    """Constant-time comparison that accepts any text (a non-ASCII token is simply wrong)."""
    return hmac.compare_digest(given.encode("utf-8", "replace"), expected)


class BodyLimit:
    """ASGI middleware: refuse a body over ``limit`` bytes, declared or streamed.

    The body is read here in full (at most ``limit`` bytes) and handed on to the app, so an
    over-long stream is answered with a 413 before any route sees it.
    """

    def __init__(self, app: ASGIApp, limit: int = MAX_BODY_BYTES) -> None:
        self.app = app
        self.limit = limit

    async def __call__(self, scope: Scope, receive: Receive, send: Send) -> None:
        """Check the declared length, read the body within the limit, then pass the request on."""
        if scope["type"] != "http":
            await self.app(scope, receive, send)
            return
        declared = _declared_length(scope)
        if declared is None:
            await _refuse(400, "Content-Length is not a number", scope, receive, send)
            return
        if declared > self.limit:
            await _refuse(413, _too_big(declared, self.limit), scope, receive, send)
            return
        try:
            body = await asyncio.wait_for(_read_body(receive, self.limit), BODY_TIMEOUT_S)
        except TimeoutError:
            await _refuse(
                408, f"the request body did not arrive within {BODY_TIMEOUT_S:g} s", scope, receive, send
            )
            return
        if body is None:
            await _refuse(413, _too_big(self.limit + 1, self.limit), scope, receive, send)
            return
        await self.app(scope, _replay(body, receive), send)


async def _read_body(receive: Receive, limit: int) -> bytes | None:
    """The whole request body, or None once it passes ``limit`` bytes."""
    chunks: list[bytes] = []
    size = 0
    while True:
        message = await receive()
        if message["type"] != "http.request":
            return b"".join(chunks)
        chunk = message.get("body", b"")
        size += len(chunk)
        if size > limit:
            return None
        chunks.append(chunk)
        if not message.get("more_body", False):
            return b"".join(chunks)


def _replay(body: bytes, receive: Receive) -> Receive:
    sent = False

    async def replayed() -> Message:
        nonlocal sent
        if sent:
            return await receive()  # the app waits for a disconnect after the body
        sent = True
        return {"type": "http.request", "body": body, "more_body": False}

    return replayed


async def _refuse(status: int, problem: str, scope: Scope, receive: Receive, send: Send) -> None:
    await JSONResponse({"error": problem}, status_code=status)(scope, receive, send)


def _declared_length(scope: Scope) -> int | None:
    """The Content-Length header's value; 0 when absent; None when malformed."""
    for key, value in scope.get("headers", ()):
        if key.lower() == b"content-length":
            text = value.decode("latin-1").strip()
            return int(text) if text.isdigit() and len(text) < 20 else None
    return 0


def _too_big(size: int, limit: int) -> str:
    return f"the request body is {size / 1e6:.1f} MB or more; the limit is {limit / 1e6:.0f} MB"


def attachment(filename: str) -> str:
    """A ``Content-Disposition`` value for a download called ``filename`` (RFC 6266 / RFC 5987)."""
    fallback = re.sub(r"[^A-Za-z0-9._-]", "_", filename) or "download"
    if fallback == filename:
        return f'attachment; filename="{fallback}"'
    encoded = quote(filename.encode("utf-8", "replace"), safe="")
    return f"attachment; filename=\"{fallback}\"; filename*=UTF-8''{encoded}"
