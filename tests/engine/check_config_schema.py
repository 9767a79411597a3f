# SPDX-License-Identifier: Apache-2.0
"""Validates the shared config cases and every preset against the JSON Schema
of the config format: valid cases and presets pass, each invalid case fails at
a place on the path of the key the engine names (engine.config_cases checks
the engine on the same cases).

usage: check_config_schema.py SCHEMA CASES PRESET_DIR"""
import json
import pathlib
import sys

import jsonschema


def merge_patch(target, patch):
    """RFC 7386 merge patch, as nlohmann::json::merge_patch."""
    if not isinstance(patch, dict):
        return patch
    result = dict(target) if isinstance(target, dict) else {}
    for key, value in patch.items():
        if value is None:
            result.pop(key, None)
        else:
            result[key] = merge_patch(result.get(key), value)
    return result


def main(schema_path, cases_path, preset_dir):
    schema = json.loads(pathlib.Path(schema_path).read_text())
    jsonschema.Draft202012Validator.check_schema(schema)
    validator = jsonschema.Draft202012Validator(schema)
    cases = json.loads(pathlib.Path(cases_path).read_text())
    failures = []
    documents = [(f"valid case {i}", merge_patch(cases["base"], p)) for i, p in enumerate(cases["valid"])]
    presets = sorted(pathlib.Path(preset_dir).glob("*.json"))
    if not presets:
        failures.append(f"no preset in {preset_dir}")
    documents += [(str(p), json.loads(p.read_text())) for p in presets]
    for name, doc in documents:
        errors = list(validator.iter_errors(doc))
        if errors:
            failures.append(f"{name} is refused by the schema: {errors[0].message} at /{'/'.join(map(str, errors[0].path))}")
    for i, case in enumerate(cases["invalid"]):
        doc = merge_patch(cases["base"], case["patch"])
        errors = list(validator.iter_errors(doc))
        where = case["where"]
        if not errors:
            failures.append(f"invalid case {i} ({where}) passes the schema")
            continue
        paths = ["/" + "/".join(map(str, e.path)) for e in errors]
        if not any(where == p or where.startswith(p.rstrip("/") + "/") for p in paths):
            failures.append(f"invalid case {i}: the engine names {where}, the schema {paths}")
    for f in failures:
        print("FAIL:", f)
    print(f"{len(documents)} valid documents, {len(cases['invalid'])} invalid ones: {len(failures)} failures")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main(*sys.argv[1:]))
