"""A throwaway sshd on 127.0.0.1 for the editor benchmark: a real SSH link, end to end.

The benchmark measures what an SSH user sees, so the bytes and the delays go through a real
`sshd` and a real `ssh -tt` (encryption, the channel's windows, a remote pty). Everything the
daemon needs lives in a temporary folder: a fresh host key, a fresh client key as the only
authorized key, a config that listens on 127.0.0.1 only. It runs in the foreground (`-D`) as
a child of the benchmark, and `stop()` ends it, also when a measurement fails (use it as a
context manager). The test suite never starts it.
"""

from __future__ import annotations

import getpass
import os
import shutil
import socket
import subprocess
import tempfile
import time
from pathlib import Path

START_WITHIN_S = 10.0


class SshdUnavailable(RuntimeError):
    """sshd is not installed or would not start; the message says what to do."""


def free_port() -> int:
    with socket.socket() as probe:
        probe.bind(("127.0.0.1", 0))
        return probe.getsockname()[1]


def find_sshd() -> str:
    for candidate in (shutil.which("sshd"), "/usr/sbin/sshd"):
        if candidate and os.access(candidate, os.X_OK):
            return candidate
    raise SshdUnavailable("sshd is not installed: as root, `apt-get install -y openssh-server` "
                          "(the benchmark starts its own sshd on 127.0.0.1 and stops it)")


class LoopbackSshd:
    """`with LoopbackSshd() as link: link.ssh_argv("command")`: sshd up inside, down after."""

    def __init__(self) -> None:
        self.folder = Path(tempfile.mkdtemp(prefix="floatpage-sshd-"))
        self.port = free_port()
        self.user = getpass.getuser()
        self.process: subprocess.Popen | None = None

    def __enter__(self) -> "LoopbackSshd":
        try:
            self.start()
        except BaseException:
            self.stop()
            raise
        return self

    def __exit__(self, *exc_info) -> None:
        self.stop()

    def keygen(self, name: str) -> Path:
        key = self.folder / name
        subprocess.run(["ssh-keygen", "-q", "-t", "ed25519", "-N", "", "-f", str(key)],
                       check=True, stdin=subprocess.DEVNULL)
        return key

    def start(self) -> None:
        sshd = find_sshd()
        os.chmod(self.folder, 0o700)
        host_key, self.client_key = self.keygen("host_key"), self.keygen("client_key")
        authorized = self.folder / "authorized_keys"
        authorized.write_text(Path(f"{self.client_key}.pub").read_text())
        authorized.chmod(0o600)
        config = self.folder / "sshd_config"
        config.write_text("\n".join([
            f"Port {self.port}", "ListenAddress 127.0.0.1", f"HostKey {host_key}",
            f"AuthorizedKeysFile {authorized}", f"PidFile {self.folder / 'sshd.pid'}",
            "PasswordAuthentication no", "KbdInteractiveAuthentication no", "UsePAM no",
            "PermitRootLogin prohibit-password", "StrictModes no", "PrintMotd no",
            "PrintLastLog no", "X11Forwarding no", "AllowTcpForwarding no", "MaxSessions 4",
            "LogLevel ERROR", ""]))
        Path("/run/sshd").mkdir(mode=0o755, exist_ok=True)  # its privilege separation folder
        self.log = open(self.folder / "sshd.log", "wb")
        self.process = subprocess.Popen([sshd, "-D", "-e", "-f", str(config)],
                                        stdin=subprocess.DEVNULL, stdout=self.log,
                                        stderr=subprocess.STDOUT)
        deadline = time.monotonic() + START_WITHIN_S
        while time.monotonic() < deadline:
            if self.process.poll() is not None:
                raise SshdUnavailable(f"sshd exited at start: {self.log_text()}")
            try:
                with socket.create_connection(("127.0.0.1", self.port), timeout=0.2):
                    break
            except OSError:
                time.sleep(0.05)
        else:
            raise SshdUnavailable(f"sshd did not listen within {START_WITHIN_S:.0f} s")
        check = subprocess.run(self.ssh_argv("true", tty=False), stdin=subprocess.DEVNULL,
                               capture_output=True, timeout=30)
        if check.returncode != 0:
            raise SshdUnavailable(f"ssh into the test sshd failed: {check.stderr.decode()!r}; "
                                  f"sshd says {self.log_text()!r}")

    def log_text(self) -> str:
        self.log.flush()
        return (self.folder / "sshd.log").read_text(errors="replace")[-2000:]

    def ssh_argv(self, command: str, *, tty: bool = True) -> list[str]:
        """The client command line that runs `command` over the link (`-tt`: a remote pty)."""
        return ["ssh", *(["-tt"] if tty else ["-T"]), "-F", "/dev/null",
                "-i", str(self.client_key), "-p", str(self.port),
                "-o", "StrictHostKeyChecking=no", "-o", "UserKnownHostsFile=/dev/null",
                "-o", "BatchMode=yes", "-o", "LogLevel=ERROR",
                f"{self.user}@127.0.0.1", command]

    def stop(self) -> None:
        """End sshd (and with it the sessions it serves) and remove the keys."""
        if self.process is not None and self.process.poll() is None:
            self.process.terminate()
            try:
                self.process.wait(timeout=5)
            except subprocess.TimeoutExpired:
                self.process.kill()
                self.process.wait(timeout=5)
        if getattr(self, "log", None) is not None:
            self.log.close()
        shutil.rmtree(self.folder, ignore_errors=True)
