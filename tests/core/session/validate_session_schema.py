#!/usr/bin/python3
"""Validates JSON documents against docs/session.schema.json (which refers to profile.schema.json).

Usage: validate_session_schema.py SESSION_SCHEMA PROFILE_SCHEMA FILE...
Prints one line per file: "FILE: valid" or "FILE: invalid at PATH: MESSAGE" (the first error).
Exit status 0 when it could check every file, 2 when it could not (jsonschema missing: 3).
Works with Debian 12's python3-jsonschema (4.10, RefResolver) and newer (referencing).
"""
import json
import sys

try:
    import jsonschema
except ImportError:
    print("python3-jsonschema is not installed", file=sys.stderr)
    sys.exit(3)


def validator(session_schema, profile_schema):
    cls = jsonschema.Draft202012Validator
    try:
        from referencing import Registry, Resource
        registry = Registry().with_resources([
            (profile_schema["$id"], Resource.from_contents(profile_schema)),
            (session_schema["$id"], Resource.from_contents(session_schema)),
        ])
        return cls(session_schema, registry=registry)
    except ImportError:
        store = {profile_schema["$id"]: profile_schema, session_schema["$id"]: session_schema}
        resolver = jsonschema.RefResolver.from_schema(session_schema, store=store)
        return cls(session_schema, resolver=resolver)


def main():
    if len(sys.argv) < 4:
        print(__doc__, file=sys.stderr)
        return 2
    with open(sys.argv[1], encoding="utf-8") as f:
        session_schema = json.load(f)
    with open(sys.argv[2], encoding="utf-8") as f:
        profile_schema = json.load(f)
    check = validator(session_schema, profile_schema)
    for path in sys.argv[3:]:
        with open(path, encoding="utf-8") as f:
            document = json.load(f)
        errors = sorted(check.iter_errors(document), key=lambda e: list(map(str, e.absolute_path)))
        if not errors:
            print(f"{path}: valid")
        else:
            where = "".join(f"[{p}]" if isinstance(p, int) else f".{p}" for p in errors[0].absolute_path).lstrip(".")
            print(f"{path}: invalid at {where or '(top)'}: {errors[0].message[:200]}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
