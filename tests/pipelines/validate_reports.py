#!/usr/bin/env python3
"""Validates report.json files against docs/report.schema.json (JSON Schema 2020-12).

    validate_reports.py SCHEMA DIR [--at-least N] [--commands run,tessellate,...]

DIR holds the reports the tests wrote (each copied there by the tests' scratch
directories as they were removed; tests/pipelines/test_report_schema.cpp checks that they
are, and that this script fails a report that breaks the schema). Fails on any report that
breaks the schema, naming the file, the field and why; on fewer than N reports (default 0:
a selection of tests may write none); and on a listed command none of the reports comes
from.
"""
import argparse
import json
import pathlib
import sys

import jsonschema


def deepest(errors):
    """The error deepest in the report (into oneOf's alternatives): the field at fault,
    rather than an enclosing object it makes invalid."""
    leaves = []
    stack = list(errors)
    while stack:
        e = stack.pop()
        if e.context:
            stack.extend(e.context)
        else:
            leaves.append(e)
    return max(leaves or errors, key=lambda e: len(e.absolute_path))


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("schema")
    parser.add_argument("dir")
    parser.add_argument("--at-least", type=int, default=0)
    parser.add_argument("--commands", default="")
    args = parser.parse_args()

    schema = json.loads(pathlib.Path(args.schema).read_text())
    jsonschema.Draft202012Validator.check_schema(schema)
    validator = jsonschema.Draft202012Validator(schema)

    reports = sorted(pathlib.Path(args.dir).glob("*.json")) if pathlib.Path(args.dir).is_dir() else []
    bad = 0
    seen = {}
    for path in reports:
        try:
            report = json.loads(path.read_text())
        except json.JSONDecodeError as e:
            print(f"{path.name}: not valid JSON: {e}")
            bad += 1
            continue
        command = report.get("command", "?") if isinstance(report, dict) else "?"
        seen[command] = seen.get(command, 0) + 1
        errors = list(validator.iter_errors(report))
        if errors:
            e = deepest(errors)
            where = "/".join(str(p) for p in e.absolute_path) or "(top)"
            more = f" (and {len(errors) - 1} more)" if len(errors) > 1 else ""
            print(f"{path.name} ({command}): {where}: {e.message[:300]}{more}")
            bad += 1

    print(f"validate_reports: {len(reports)} reports ({', '.join(f'{k} {v}' for k, v in sorted(seen.items()))}), "
          f"{bad} invalid")
    missing = [c for c in filter(None, args.commands.split(",")) if c not in seen]
    if missing:
        print(f"validate_reports: no report of {', '.join(missing)} was seen")
    if len(reports) < args.at_least:
        print(f"validate_reports: fewer than {args.at_least} reports: the tests' reports were not collected")
    return 1 if bad or missing or len(reports) < args.at_least else 0


if __name__ == "__main__":
    sys.exit(main())
