"""Load a scenario script (``scenarios/NAME.py``) as a module, so tests call its ``main(argv)`` directly."""

import importlib.util
from pathlib import Path

SCENARIOS = Path(__file__).resolve().parents[1] / "scenarios"


def load_scenario(name):
    """The module of ``scenarios/<name>.py``, executed once per call."""
    spec = importlib.util.spec_from_file_location(f"scenario_{name}", SCENARIOS / f"{name}.py")
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    return mod
