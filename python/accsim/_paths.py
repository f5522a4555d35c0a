"""Where the bundled example scenarios are: inside the installed package
(``accsim/data/examples``) or, in a source checkout, ``scenarios/examples``."""
from __future__ import annotations

import json
import os
from pathlib import Path
from typing import Any, Sequence


def examples_dir() -> Path:
    env = os.environ.get("ACCSIM_DATA_DIR")
    candidates = [Path(env) / "scenarios" / "examples"] if env else []
    here = Path(__file__).resolve().parent
    candidates += [here / "data" / "examples", here.parent.parent / "scenarios" / "examples"]
    for c in candidates:
        if c.is_dir() and any(c.glob("*.json")):
            return c
    raise FileNotFoundError("accsim: the bundled example scenarios were not found; pass scenario= or suite=")


def bundled_scenarios() -> list[str]:
    """Paths of the four bundled example scenarios, one per family."""
    return sorted(str(p) for p in examples_dir().glob("*.json"))


def scenario_paths(scenario: str | os.PathLike | Sequence[str | os.PathLike] | None,
                   suite: str | os.PathLike | None) -> list[str]:
    paths: list[str] = []
    if scenario is not None:
        items = [scenario] if isinstance(scenario, (str, os.PathLike)) else list(scenario)
        paths += [os.fspath(p) for p in items]
    if suite is not None:
        paths.append(os.fspath(suite))
    if not paths:
        paths = bundled_scenarios()
    for p in paths:
        if not os.path.isfile(p):
            raise FileNotFoundError(f"scenario: no such file: {p}")
    return paths


def config_args(config: str | os.PathLike | dict[str, Any] | None) -> tuple[str, str]:
    """(yaml path, json text) for the C++ constructors."""
    if config is None:
        return "", ""
    if isinstance(config, dict):
        return "", json.dumps(config)
    if isinstance(config, (str, os.PathLike)):
        if not os.path.isfile(config):
            raise FileNotFoundError(f"config: no such file: {config}")
        return os.fspath(config), ""
    raise TypeError(f"config: expected a YAML path or a dict, got {type(config).__name__}")
