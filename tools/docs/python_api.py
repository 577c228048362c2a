#!/usr/bin/python3
"""Writes docs/python-api.md: the public API of the sma package (python/sma), from its docstrings.

Usage: tools/docs/python_api.py [--out FILE] [--check]
  --out FILE  write there instead of docs/python-api.md ('-': standard output)
  --check     write nothing; exit 1 naming what differs when docs/python-api.md is not current,
              or naming every public function, class or method without a docstring

The page lists the package's docstring, then every name of sma.__all__ in that order: a function
with its signature and docstring, a class with its docstring and its public methods. Docstrings
are copied as written (indented text stays a code block). Deterministic: the same sources give
the same bytes. Regenerate with `make docs`; tests/python_package_test.py fails when the page is
stale.
"""
import argparse
import importlib
import inspect
import os
import pkgutil
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
sys.path.insert(0, os.path.join(ROOT, "python"))  # this checkout's package, not an installed one
import sma  # noqa: E402

OUTPUT = os.path.join(ROOT, "docs", "python-api.md")


def doc(obj):
    """The docstring of obj, dedented, or "" (inspect.getdoc would inherit a parent's)."""
    text = obj.__doc__ if isinstance(getattr(obj, "__doc__", None), str) else ""
    return inspect.cleandoc(text) if text else ""


def signature(name, obj):
    try:
        return f"{name}{inspect.signature(obj)}"
    except (TypeError, ValueError):
        return name


def methods(cls):
    """The public methods of cls defined in the class itself, in source order."""
    return [(n, f) for n, f in vars(cls).items() if not n.startswith("_") and inspect.isfunction(f)]


def undocumented():
    """Every public function, class and method of the package's modules without a docstring."""
    missing = []
    for module in pkgutil.iter_modules(sma.__path__):
        importlib.import_module(f"sma.{module.name}")
    for module_name in sorted(m for m in sys.modules if m == "sma" or m.startswith("sma.")):
        module = sys.modules[module_name]
        if not doc(module):
            missing.append(module_name)
        for n, obj in vars(module).items():
            if n.startswith("_") or getattr(obj, "__module__", None) != module_name:
                continue
            if inspect.isfunction(obj) or inspect.isclass(obj):
                if not doc(obj):
                    missing.append(f"{module_name}.{n}")
                if inspect.isclass(obj):
                    missing += [f"{module_name}.{n}.{m}" for m, f in methods(obj) if not doc(f)]
    return missing


def markdown():
    lines = ["# The sma Python package (python/sma)", "",
             "Generated from the package's docstrings by `tools/docs/python_api.py` (`make docs`); do not edit.",
             "Use: this checkout's python/ on the path, or `make python` to install it for the user",
             "(docs/parameters.md, \"The Python package\"); files, columns and units:",
             "docs/outputs.md.", "", doc(sma), "", "## Contents", ""]
    lines += [f"- [`{n}`](#{n.lower()})" for n in sma.__all__]
    for name in sma.__all__:
        obj = getattr(sma, name)
        lines += ["", f"## {name}", ""]
        if inspect.isfunction(obj):
            lines += ["```python", signature(f"sma.{name}", obj), "```", "", doc(obj)]
        elif inspect.isclass(obj):
            lines += [f"class `sma.{name}`" + (f" ({obj.__bases__[0].__name__})" if obj.__bases__ != (object,) else ""),
                      "", doc(obj)]
            for m, f in methods(obj):
                lines += ["", f"### {name}.{m}", "", "```python", signature(m, f), "```", "", doc(f)]
        else:
            lines += [f"`sma.{name}`: {type(obj).__name__}, the value of this checkout (here the"
                      f" {'path of tools/ff' if name == 'FF' else 'repository folder'}, found from the package's"
                      " own location)."]
    return "\n".join(lines).rstrip() + "\n"


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--out", default=OUTPUT)
    parser.add_argument("--check", action="store_true")
    args = parser.parse_args()
    text = markdown()
    if args.check:
        missing = undocumented()
        current = open(OUTPUT, encoding="utf-8").read() if os.path.exists(OUTPUT) else ""
        if missing:
            print("error: without a docstring: " + ", ".join(missing), file=sys.stderr)
        if text != current:
            print(f"error: {OUTPUT} is not what the docstrings give: run `make docs`", file=sys.stderr)
        return 1 if missing or text != current else 0
    if args.out == "-":
        sys.stdout.write(text)
    else:
        with open(args.out + ".partial", "w", encoding="utf-8") as f:
            f.write(text)
        os.replace(args.out + ".partial", args.out)
    return 0


if __name__ == "__main__":
    sys.exit(main())
