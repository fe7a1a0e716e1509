#!/usr/bin/python3
"""Checks that an XDMF file written by suspend parses as XML and that every HDF5 dataset it names exists with the
shape it declares. Usage: tools/check_xdmf.py RUN_DIR/run.xdmf   (exit 0 when valid, 1 with a message otherwise)."""
import os
import sys
import xml.etree.ElementTree as ET

from debian_python import require


def main(path):
    import h5py
    try:
        root = ET.parse(path).getroot()
    except (OSError, ET.ParseError) as e:
        return f"{path}: {e}"
    if root.tag != "Xdmf":
        return f"{path}: root element is {root.tag}, not Xdmf"
    base = os.path.dirname(os.path.abspath(path))
    items = root.iter("DataItem")
    count = 0
    for item in items:
        if item.get("Format") != "HDF":
            continue
        file_name, dataset = item.text.strip().split(":", 1)
        dims = tuple(int(d) for d in item.get("Dimensions").split())
        with h5py.File(os.path.join(base, file_name), "r") as f:
            if dataset not in f:
                return f"{path}: {file_name}:{dataset} does not exist"
            if f[dataset].shape != dims:
                return f"{path}: {dataset} has shape {f[dataset].shape}, the XDMF says {dims}"
        count += 1
    for item in root.iter("DataItem"):  # inline values: as many as the dimensions say
        if item.get("Format") == "XML":
            want = 1
            for d in item.get("Dimensions").split():
                want *= int(d)
            if len(item.text.split()) != want:
                return f"{path}: an inline DataItem holds {len(item.text.split())} values, its Dimensions say {want}"
    collections = [g for g in root.iter("Grid") if g.get("CollectionType") == "Temporal"]
    if not collections or not any(len(c.findall("Grid")) for c in collections):
        return f"{path}: no snapshot grids"
    steps = ", ".join(f"{c.get('Name')} {len(c.findall('Grid'))}" for c in collections)
    print(f"{path}: valid XDMF, time steps: {steps}; {count} datasets checked")
    return None


if __name__ == "__main__":
    if len(sys.argv) != 2 or sys.argv[1] in ("-h", "--help"):
        print("usage: tools/check_xdmf.py RUN_DIR/run.xdmf", file=sys.stderr)
        sys.exit(2)
    if not os.path.isfile(sys.argv[1]):
        print(f"error: {sys.argv[1]}: no such file", file=sys.stderr)
        sys.exit(2)
    require("h5py")
    error = main(sys.argv[1])
    if error:
        print(error, file=sys.stderr)
        sys.exit(1)
