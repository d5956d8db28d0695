#!/usr/bin/env python3
"""Writes a folder as the folder image the package_folder fuzz harness reads (tests/fuzz/FuzzPackageFolder.cpp):
per entry a type byte ('f' file, 'd' folder, 'l' symbolic link), a name length byte, the name, a 4-byte
little-endian size and the content (a link's target). Files larger than --max-bytes are cut, so seeds stay small.

    python3 tests/fuzz/pack-folder.py PACKAGE_FOLDER OUT.bin [--max-bytes N]
"""
import argparse
import os
import struct


def entries(root):
    for folder, dirs, files in os.walk(root):
        dirs.sort()
        for name in sorted(dirs) + sorted(files):
            path = os.path.join(folder, name)
            yield os.path.relpath(path, root).replace(os.sep, "/"), path


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("folder")
    parser.add_argument("out")
    parser.add_argument("--max-bytes", type=int, default=1 << 30)
    args = parser.parse_args()
    image = bytearray()
    # The manifest first: the harness reads it back to fix sizes and checksums, whatever follows.
    items = sorted(entries(args.folder), key=lambda e: (e[0] != "manifest.json", e[0]))
    for name, path in items:
        raw = name.encode()
        if len(raw) > 255:
            continue
        if os.path.islink(path):
            kind, data = b"l", os.readlink(path).encode()
        elif os.path.isdir(path):
            kind, data = b"d", b""
        else:
            kind = b"f"
            with open(path, "rb") as f:
                data = f.read(args.max_bytes)
        image += kind + bytes([len(raw)]) + raw + struct.pack("<I", len(data)) + data
    with open(args.out, "wb") as f:
        f.write(image)


if __name__ == "__main__":
    main()
