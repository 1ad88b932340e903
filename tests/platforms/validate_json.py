#!/usr/bin/env python3
"""Validates JSON files against a JSON Schema (draft 2020-12): validate_json.py SCHEMA FILE...
Prints every violation with its path and exits 1 when there is one."""
import json
import sys

import jsonschema

schema = json.load(open(sys.argv[1], encoding="utf-8"))
validator = jsonschema.Draft202012Validator(schema)
bad = 0
for path in sys.argv[2:]:
    for error in validator.iter_errors(json.load(open(path, encoding="utf-8"))):
        where = "/".join(str(p) for p in error.absolute_path) or "(root)"
        print(f"{path}: {where}: {error.message}")
        bad += 1
sys.exit(1 if bad else 0)
