#!/usr/bin/python3
"""Seals a checkpoint again after a test edited it: its last line "checksum <hex>" replaced by the
FNV-1a 64 of everything above (written here independently of plugin/core/files.hpp, which the
bad-inputs rows thereby check too). A crafted file whose seal is right must still be refused by
the typed reader (docs/errors.md: a word where a number belongs, a huge length, a file outside).

Usage: tests/reseal.py CHECKPOINT
"""
import sys


def fnv1a64(data):
    h = 0xcbf29ce484222325
    for byte in data:
        h = ((h ^ byte) * 0x100000001b3) & 0xFFFFFFFFFFFFFFFF
    return f"{h:016x}"


def main(path):
    with open(path, "rb") as f:
        lines = f.read().splitlines(keepends=True)
    if not lines or not lines[-1].startswith(b"checksum "):
        sys.exit(f"error: {path} has no checksum line to replace")
    body = b"".join(lines[:-1])
    with open(path, "wb") as f:
        f.write(body + b"checksum " + fnv1a64(body).encode() + b"\n")


if __name__ == "__main__":
    main(sys.argv[1])
