#!/usr/bin/env python3
# Copyright (c) 2026 MDCS contributors.
# SPDX-License-Identifier: GPL-3.0-or-later
"""Writes the API reference of the mdcs package (python/API.md) from its docstrings, the text help() shows.

    PYTHONPATH=<build>/python python3 python/tools/api_reference.py [OUTPUT]     (default: python/API.md)
"""

import importlib
import inspect
import os
import sys

MODULES = ["mdcs", "mdcs.geodesics", "mdcs.mwt", "mdcs.variational", "mdcs.silhouettes", "mdcs.min_cut", "mdcs.io",
           "mdcs.dask", "mdcs.compat.gdist", "mdcs.compat.pygeodesic", "mdcs.compat.pygeodesic.geodesic",
           "mdcs._progress"]


def doc(obj):
    return inspect.cleandoc(obj.__doc__ or "").strip()


def signature(obj):
    try:
        return str(inspect.signature(obj))
    except (TypeError, ValueError):
        return "(...)"


def members(cls):
    for name, value in vars(cls).items():
        if name.startswith("_") and name not in ("__init__",):
            continue
        if isinstance(value, property):
            yield name, value, "property"
        elif inspect.isfunction(value) or isinstance(value, (classmethod, staticmethod)):
            yield name, getattr(cls, name), "method"


def main():
    root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    output = sys.argv[1] if len(sys.argv) > 1 else os.path.join(root, "API.md")
    lines = ["# mdcs: API reference", "",
             "Generated from the docstrings by `python/tools/api_reference.py` (the same text as `help()`).", ""]
    seen = {}
    for name in MODULES:
        module = importlib.import_module(name)
        lines += [f"## `{name}`", "", doc(module), ""]
        for item in getattr(module, "__all__", []):
            obj = getattr(module, item)
            if inspect.ismodule(obj) or item.startswith("__"):
                continue
            home = getattr(obj, "__module__", name)
            if home != name and home in MODULES and MODULES.index(home) > MODULES.index(name):
                lines += [f"- `{name}.{item}`: see `{home}.{obj.__qualname__}`", ""]
                continue
            if (inspect.isclass(obj) or callable(obj)) and id(obj) in seen:
                lines += [f"- `{name}.{item}`: see `{seen[id(obj)]}`", ""]
                continue
            if inspect.isclass(obj) or callable(obj):
                seen[id(obj)] = f"{name}.{item}"
            if inspect.isclass(obj):
                lines += [f"### class `{name}.{item}{signature(obj)}`", "", doc(obj), ""]
                for member, value, kind in members(obj):
                    text = doc(value)
                    if kind == "property":
                        lines += [f"- property `{member}`" + (f": {text}" if text else "")]
                    elif member != "__init__":
                        lines += [f"#### `{item}.{member}{signature(value)}`", "", text, ""]
                lines.append("")
            elif callable(obj):
                lines += [f"### `{name}.{item}{signature(obj)}`", "", doc(obj), ""]
            else:
                lines += [f"- `{item}` = `{obj!r}`", ""]
    with open(output, "w") as f:
        f.write("\n".join(lines).rstrip() + "\n")
    print(f"wrote {output}")


if __name__ == "__main__":
    main()
