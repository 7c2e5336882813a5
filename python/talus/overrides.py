"""Scenario overrides given as a dict, turned into the `KEY=VALUE` assignments of the
command line's `--set`, VALUE written as TOML so that the scenario reader takes it as typed."""
import math
import numbers


def assignments(overrides):
    """{"contact.friction": 0.3} -> ["contact.friction=0.3"]; a list of "KEY=VALUE" strings
    passes unchanged."""
    if overrides is None:
        return []
    if isinstance(overrides, dict):
        return [f"{key}={toml_value(value)}" for key, value in overrides.items()]
    return [str(assignment) for assignment in overrides]


def toml_value(value):
    # bool first: True is also an int.
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, numbers.Integral):
        return str(int(value))
    if isinstance(value, numbers.Real):
        x = float(value)
        if math.isnan(x):
            return "nan"
        if math.isinf(x):
            return "inf" if x > 0 else "-inf"
        return repr(x)  # shortest text that reads back as the same double
    if isinstance(value, str):
        escaped = value.replace("\\", "\\\\").replace('"', '\\"').replace("\n", "\\n")
        return '"' + escaped + '"'
    if isinstance(value, dict):
        return "{" + ", ".join(f"{key} = {toml_value(item)}" for key, item in value.items()) + "}"
    if hasattr(value, "__iter__"):
        return "[" + ", ".join(toml_value(item) for item in value) + "]"
    raise TypeError(f"override value {value!r} has no TOML form")
