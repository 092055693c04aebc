"""Configs from Python: a dict (nested by section, or flat "section.key" keys) as the INI
text the grainmesh command reads, and the embedded default as such a dict."""

import configparser
import math
import os

from . import _grainmesh


def _parsed(text):
    """{section: {key: value text}} of a config file's text (comments dropped)."""
    parser = configparser.ConfigParser(interpolation=None, comment_prefixes=("#", ";"), inline_comment_prefixes=("#",))
    parser.optionxform = str  # keys keep their case (phase.WC)
    parser.read_string(text)
    return {section: dict(parser[section]) for section in parser.sections()}


def default_config():
    """The config `run` uses without one (data/default.ini), as a dict to change."""
    return _parsed(_grainmesh.default_config)


def read_config(path):
    """A config file as a dict to change and hand back (its values as text)."""
    with open(path, encoding="utf-8") as f:
        return _parsed(f.read())


def value_text(value):
    """A value as the config file writes it: true/false, numbers to the last bit, lists
    (a sweep's) separated by commas."""
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, float):
        if not math.isfinite(value):
            raise ValueError(f"config value {value!r}: not a finite number")
        return repr(value)
    if isinstance(value, (list, tuple)):
        return ", ".join(value_text(v) for v in value)
    if isinstance(value, os.PathLike):
        return os.fspath(value)
    text = str(value)
    if "\n" in text:
        raise ValueError(f"config value {text!r}: a line break")
    return text


def sections(config):
    """{section: {key: value}} from a nested or flat dict ("phase.WC.E": 700e9 is section
    phase.WC, key E)."""
    out = {}
    for name, value in config.items():
        if isinstance(value, dict):
            for key, v in value.items():
                out.setdefault(str(name), {})[str(key)] = v
        else:
            section, dot, key = str(name).rpartition(".")
            if not dot:
                raise ValueError(f"config key '{name}': not SECTION.KEY (nor a section's dict)")
            out.setdefault(section, {})[key] = value
    return out


def ini_text(config):
    """The INI text of a config dict."""
    lines = []
    for section, keys in sections(config).items():
        lines.append(f"[{section}]")
        lines.extend(f"{key} = {value_text(v)}" for key, v in keys.items())
        lines.append("")
    return "\n".join(lines)


def set_arguments(overrides):
    """--set KEY=VALUE arguments from a dict (nested or flat), in its order."""
    args = []
    for section, keys in sections(overrides or {}).items():
        for key, v in keys.items():
            args += ["--set", f"{section}.{key}={value_text(v)}"]
    return args
