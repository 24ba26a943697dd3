"""A kernel-level system-call allow-list for the sandbox child (Linux seccomp, x86-64 and arm64).

The layer that holds when every Python layer is bypassed. It is installed in the child after numpy is
loaded and the result pipe is in place, and from then on the kernel lets through only what computing
and writing a result needs: memory management, signals, clocks, random bytes, reading and writing
already-open descriptors, and exit. Everything else (open/openat, stat by path, io_uring, sockets,
fork/clone/exec, kill/ptrace, prctl, ioctl, ...) fails with EPERM; a call from another architecture's
table (x32, 32-bit compat) kills the process.

The filter is a short classic-BPF program written here rather than through libseccomp: an allow-list
of about thirty numbers needs no argument checks (no descriptor to a file can be obtained, so ``mmap``
and ``read`` of a file are unreachable), and this keeps the layer free of a native dependency that a
machine may lack. ``tests/sandbox`` runs hostile code against it with the Python layers turned off.
"""

from __future__ import annotations

import ctypes
import errno
import platform
import struct
from dataclasses import dataclass

PR_SET_NO_NEW_PRIVS = 38
PR_SET_SECCOMP = 22
SECCOMP_MODE_FILTER = 2
SECCOMP_RET_ALLOW = 0x7FFF0000
SECCOMP_RET_KILL_PROCESS = 0x80000000
SECCOMP_RET_ERRNO = 0x00050000
X32_SYSCALL_BIT = 0x40000000

BPF_LD_W_ABS = 0x20
BPF_JEQ_K = 0x15
BPF_JGE_K = 0x35
BPF_RET_K = 0x06
OFFSET_NR = 0
OFFSET_ARCH = 4

# What the child may still do once the filter is in: the calls seen when running the skill library and
# numpy (traced with strace), plus the signal and clock calls the interpreter needs to be stopped cleanly.
ALLOWED_CALLS = (
    "read", "write", "close", "mmap", "munmap", "mremap", "mprotect", "brk", "madvise",
    "rt_sigaction", "rt_sigprocmask", "rt_sigreturn", "sigaltstack", "restart_syscall",
    "futex", "sched_yield", "getrandom", "clock_gettime", "clock_getres", "gettimeofday",
    "nanosleep", "clock_nanosleep", "getrusage", "times", "getpid", "gettid", "exit", "exit_group",
)  # fmt: skip


@dataclass(frozen=True)
class SyscallTable:
    """One architecture's audit identifier and the numbers of the allowed calls."""

    audit_arch: int
    numbers: dict[str, int]


# From the kernel's tables: arch/x86/entry/syscalls/syscall_64.tbl and include/uapi/asm-generic/unistd.h.
SYSCALL_TABLES: dict[str, SyscallTable] = {
    "x86_64": SyscallTable(
        0xC000003E,
        {
            "read": 0, "write": 1, "close": 3, "mmap": 9, "mprotect": 10, "munmap": 11, "brk": 12,
            "rt_sigaction": 13, "rt_sigprocmask": 14, "rt_sigreturn": 15, "sched_yield": 24,
            "mremap": 25, "madvise": 28, "nanosleep": 35, "getpid": 39, "exit": 60,
            "gettimeofday": 96, "getrusage": 98, "times": 100, "sigaltstack": 131, "gettid": 186,
            "futex": 202, "restart_syscall": 219, "clock_gettime": 228, "clock_getres": 229,
            "clock_nanosleep": 230, "exit_group": 231, "getrandom": 318,
        },
    ),
    "aarch64": SyscallTable(
        0xC00000B7,
        {
            "read": 63, "write": 64, "close": 57, "mmap": 222, "mprotect": 226, "munmap": 215,
            "brk": 214, "rt_sigaction": 134, "rt_sigprocmask": 135, "rt_sigreturn": 139,
            "sched_yield": 124, "mremap": 216, "madvise": 233, "nanosleep": 101, "getpid": 172,
            "exit": 93, "gettimeofday": 169, "getrusage": 165, "times": 153, "sigaltstack": 132,
            "gettid": 178, "futex": 98, "restart_syscall": 128, "clock_gettime": 113,
            "clock_getres": 114, "clock_nanosleep": 115, "exit_group": 94, "getrandom": 278,
        },
    ),
}  # fmt: skip


class _SockFprog(ctypes.Structure):
    _fields_ = [("len", ctypes.c_ushort), ("filter", ctypes.c_void_p)]


def _instruction(code: int, jump_true: int, jump_false: int, k: int) -> bytes:
    return struct.pack("HBBI", code, jump_true, jump_false, k)


def supported() -> bool:
    """True where the allow-list can be installed (Linux on x86-64 or arm64)."""
    return platform.system() == "Linux" and platform.machine() in SYSCALL_TABLES


def build_filter(machine: str) -> bytes:
    """Return the BPF program for ``machine`` (as ``platform.machine()`` names it).

    Raises:
        KeyError: no syscall table is known for that machine.
    """
    table = SYSCALL_TABLES[machine]
    kill = _instruction(BPF_RET_K, 0, 0, SECCOMP_RET_KILL_PROCESS)
    program = [
        _instruction(BPF_LD_W_ABS, 0, 0, OFFSET_ARCH),
        _instruction(BPF_JEQ_K, 1, 0, table.audit_arch),
        kill,
        _instruction(BPF_LD_W_ABS, 0, 0, OFFSET_NR),
    ]
    if machine == "x86_64":
        program += [_instruction(BPF_JGE_K, 0, 1, X32_SYSCALL_BIT), kill]
    for number in sorted({table.numbers[name] for name in ALLOWED_CALLS}):
        program.append(_instruction(BPF_JEQ_K, 0, 1, number))
        program.append(_instruction(BPF_RET_K, 0, 0, SECCOMP_RET_ALLOW))
    program.append(_instruction(BPF_RET_K, 0, 0, SECCOMP_RET_ERRNO | errno.EPERM))
    return b"".join(program)


def install_filter() -> bool:
    """Install the allow-list on the calling process; False where it is not supported or refused."""
    if not supported():
        return False
    program = build_filter(platform.machine())
    buffer = ctypes.create_string_buffer(program, len(program))
    fprog = _SockFprog(len(program) // 8, ctypes.cast(buffer, ctypes.c_void_p))
    libc = ctypes.CDLL(None, use_errno=True)
    if libc.prctl(PR_SET_NO_NEW_PRIVS, 1, 0, 0, 0) != 0:
        return False
    return bool(libc.prctl(PR_SET_SECCOMP, SECCOMP_MODE_FILTER, ctypes.byref(fprog), 0, 0) == 0)
