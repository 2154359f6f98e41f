"""The platform fingerprint: what an attempt's result depends on beyond its seeds. Two
runs re-ride each other's attempts exactly only when these agree (docs/experiment.md,
"Reproducibility"), so every row of a results file names the fingerprint it was made on,
and a run refuses to add rows made on another one unless told to."""

from __future__ import annotations

import hashlib
import json
import os
import subprocess
from pathlib import Path

# What decides a ride, and so what must agree for two rows to be comparable bit for bit.
COMPARED = (
    "code",
    "native_build",
    "rustc",
    "ode_configuration",
    "godot",
    "c_library",
    "cpu_model",
    "math_path",
)
# The project files a ride runs: the native sources, the scenes and scripts, and the
# project settings (physics tick, autoloads) and the learned controller's model.
# Documentation and tools do not ride.
RIDE_PATHS = ("native", "scenes", "scripts", "addons/cpbp/cpbp.gdextension", "project.godot",
              "models")
NATIVE_LIBRARY = Path("addons/cpbp/bin/libcpbp.so")
# Rows of results files made before fingerprints were recorded carry this name.
UNRECORDED = "unrecorded"


class FingerprintError(Exception):
    """The platform could not be described (the message says why)."""


def _git(root: Path, *arguments: str) -> str:
    result = subprocess.run(["git", "-C", str(root), *arguments], capture_output=True,
                            text=True, check=False)
    if result.returncode != 0:
        raise FingerprintError(f"git {' '.join(arguments)} failed: {result.stderr.strip()}")
    return result.stdout


def code_identity(root: Path) -> str:
    """Git's tree ids of the files a ride runs, plus a digest of any uncommitted change to
    them, so two checkouts agree exactly when the riding code does."""
    try:
        # A riding path the commit does not have yet (the model, before one is trained)
        # is left out, so older commits keep the identity they had.
        present = set(_git(root, "ls-tree", "--name-only", "HEAD", "--", *RIDE_PATHS).split())
        trees = _git(root, "rev-parse",
                     *(f"HEAD:{p}" for p in RIDE_PATHS if p in present)).split()
        changed = _git(root, "diff", "HEAD", "--binary", "--", *RIDE_PATHS)
        untracked = _git(root, "ls-files", "--others", "--exclude-standard", "--",
                         *RIDE_PATHS).split()
    except (FingerprintError, OSError) as error:
        return f"unknown ({error})"
    identity = hashlib.sha256(" ".join(trees).encode()).hexdigest()[:16]
    if not changed and not untracked:
        return identity
    digest = hashlib.sha256(changed.encode())
    for name in sorted(untracked):
        digest.update(name.encode() + b"\0" + (root / name).read_bytes())
    return f"{identity}+uncommitted-{digest.hexdigest()[:12]}"


def commit(root: Path) -> str:
    try:
        return _git(root, "rev-parse", "--short=12", "HEAD").strip()
    except (FingerprintError, OSError):
        return "unknown"


def native_build(root: Path) -> str:
    """SHA-256 of the built extension: the same sources, compiler and ODE build give the
    same bytes, a rebuild with anything else different does not."""
    library = root / NATIVE_LIBRARY
    try:
        return hashlib.sha256(library.read_bytes()).hexdigest()[:16]
    except OSError as error:
        raise FingerprintError(f"no native library to fingerprint ({error}); run make build")


def fingerprint(root: Path, worker_platform: dict) -> dict:
    """The whole fingerprint: what the worker reports of the engine, the native module and
    the machine (NativeModule.platform()), with the project's code and build."""
    missing = [k for k in COMPARED if k not in ("code", "native_build")
               and k not in worker_platform]
    if missing:
        raise FingerprintError(f"the worker did not report {', '.join(missing)}")
    description = {key: str(value) for key, value in worker_platform.items()}
    description.update(code=code_identity(root), native_build=native_build(root),
                       commit=commit(root), cores=str(os.cpu_count()))
    return description


def identity(description: dict) -> str:
    """A short name for a fingerprint: equal exactly when every compared field is."""
    compared = {key: description.get(key, "") for key in COMPARED}
    return hashlib.sha256(json.dumps(compared, sort_keys=True).encode()).hexdigest()[:10]


def differences(made_on: dict, now: dict) -> list[str]:
    """What differs between two fingerprints, one line per compared field."""
    return [f"{key}: {made_on.get(key, '(not recorded)')} → now {now.get(key, '?')}"
            for key in COMPARED if made_on.get(key) != now.get(key)]


class PlatformStore:
    """`platforms.json` beside the results: every fingerprint its rows name, by identity.
    Written to a temporary file and renamed, so a kill never leaves half a file."""

    def __init__(self, path: Path):
        self.path = path

    def load(self) -> dict[str, dict]:
        if not self.path.exists():
            return {}
        try:
            data = json.loads(self.path.read_text(encoding="utf-8"))
        except (OSError, ValueError) as error:
            raise FingerprintError(f"{self.path} is unreadable ({error}); restore it from "
                                   "version control or move it aside") from error
        if not isinstance(data, dict) or not all(isinstance(v, dict) for v in data.values()):
            raise FingerprintError(f"{self.path} is not a map of fingerprints")
        return data

    def add(self, description: dict) -> str:
        known = self.load()
        name = identity(description)
        # The first description of an identity stays: it names the commit that made the
        # first of its rows (later commits that ride the same code share its identity).
        if name not in known:
            known[name] = description
            self.path.parent.mkdir(parents=True, exist_ok=True)
            temporary = self.path.with_suffix(".json.tmp")
            temporary.write_text(json.dumps(known, indent=2, sort_keys=True) + "\n",
                                 encoding="utf-8")
            os.replace(temporary, self.path)
        return name


def refusal(row_platforms: set[str], now: dict, known: dict[str, dict], path: Path) -> str:
    """Why rows made on the fingerprints `row_platforms` must not be mixed with rows made
    `now`, or "" when they all match it."""
    others = sorted(row_platforms - {identity(now)})
    if not others:
        return ""
    lines = [f"{path} has rows made on another platform than this one:"]
    for name in others:
        if name == UNRECORDED:
            lines.append("- rows made before platforms were recorded (their platform is "
                         "unknown)")
        elif name not in known:
            lines.append(f"- rows of platform {name}, which platforms.json does not describe")
        else:
            lines += [f"- platform {name}:"] + [f"    {d}" for d in differences(known[name], now)]
    lines.append("Rows from two platforms need not repeat each other's rides (see "
                 "docs/experiment.md). Check with `tools/experiment verify`, then add "
                 "--allow-mixed to append anyway (the report notes the mix), or choose "
                 "another --out.")
    return "\n".join(lines)
