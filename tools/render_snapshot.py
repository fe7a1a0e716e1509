#!/usr/bin/python3
"""Draws one snapshot of a run the way ParaView shows run.xdmf: the spheres coloured by species, the contact
network as lines coloured by the contact force magnitude, and the sheared periodic cell; everything is read through
the XDMF's references (so the picture tests what a user opens). Headless (matplotlib Agg, 3-D).
Usage: tools/render_snapshot.py RUN_DIR [--snapshot K (default: the last)] [--out FILE.png] [--force]"""
import argparse
import os
import sys
import xml.etree.ElementTree as ET

from debian_python import require

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "python"))
from suspend.output_rules import refuse_file, starts_with  # noqa: E402


def values(item, base):
    """The array a DataItem refers to (HDF5 or inline XML)."""
    import h5py
    import numpy as np
    dims = tuple(int(d) for d in item.get("Dimensions").split())
    if item.get("Format") == "HDF":
        file_name, dataset = item.text.strip().split(":", 1)
        with h5py.File(os.path.join(base, file_name), "r") as f:
            return np.asarray(f[dataset]).reshape(dims)
    return np.array(item.text.split(), dtype=float).reshape(dims)


def attribute(grid, name, base):
    for a in grid.findall("Attribute"):
        if a.get("Name") == name:
            return values(a.find("DataItem"), base)
    return None


def collection(root, name):
    """The steps of the temporal collection `name`, in order."""
    for c in root.iter("Grid"):
        if c.get("Name") == name and c.get("CollectionType") == "Temporal":
            return c.findall("Grid")
    return []


def read_snapshot(root, base, index):
    """Snapshot `index` of the XDMF as a dict (name, strain, time, position, radius, species, corners: the box's 8
    corners or None, ends: the contact lines (M,2,3) or None, force: their |contact force|), None past the end.
    The box and contacts steps are matched by name: a snapshot without contacts has no contacts step, so the
    collections' indices need not line up."""
    import numpy as np
    grids = collection(root, "particles")
    if not grids or not -len(grids) <= index < len(grids):
        return None
    particles = grids[index]
    name = particles.get("Name")
    time = particles.find("Information[@Name='time']")
    snap = {"name": name, "strain": float(particles.find("Time").get("Value")),
            "time": float(time.get("Value")) if time is not None else None,
            "position": values(particles.find("Geometry/DataItem"), base),
            "radius": attribute(particles, "radius", base), "species": attribute(particles, "species", base),
            "corners": None, "ends": None, "force": None}
    box = next((g for g in collection(root, "box") if g.get("Name") == name), None)
    if box is not None:
        snap["corners"] = values(box.find("Geometry/DataItem"), base)
    contacts = next((g for g in collection(root, "contacts") if g.get("Name") == name), None)
    if contacts is not None:
        snap["ends"] = values(contacts.find("Geometry/DataItem"), base).reshape(-1, 2, 3)
        snap["force"] = np.linalg.norm(attribute(contacts, "contact_force", base), axis=1)
    return snap


FORCE_LABEL = "|contact force| (eta_0 gammadot_ref a_1^2)"


def draw(fig, snap, title, norm=None):
    """Draws `snap` (from read_snapshot) on `fig` in 3-D. norm: a fixed force colour scale (a movie keeps one, and
    then shows the colour bar, with an arrow for the forces above it, on every frame); default the snapshot's own
    force range."""
    import matplotlib.cm
    import numpy as np
    from mpl_toolkits.mplot3d.art3d import Line3DCollection
    ax = fig.add_subplot(projection="3d")
    ax.set_proj_type("ortho")
    position, radius, corners = snap["position"], snap["radius"], snap["corners"]
    # Marker area in points^2 from the sphere's diameter on the axes (approximate: the view is orthographic).
    span = float(np.ptp(corners[:, 0])) if corners is not None else float(np.ptp(position[:, 0]))
    points_per_length = 0.55 * 72 * 6.0 / span
    colours = np.where(snap["species"] > 0, "#d95f02", "#1b9e77")
    ax.scatter(position[:, 0], position[:, 1], position[:, 2], s=(2 * radius * points_per_length) ** 2,
               c=colours, alpha=0.35, edgecolors="none", depthshade=False)
    bar = {"ax": ax, "shrink": 0.6, "label": FORCE_LABEL, "extend": "neither" if norm is None else "max"}
    if snap["ends"] is not None:
        lines = Line3DCollection(snap["ends"], cmap="inferno_r", norm=norm, linewidths=1.6)
        lines.set_array(snap["force"])
        ax.add_collection3d(lines)
        fig.colorbar(lines, **bar)
    elif norm is not None:
        fig.colorbar(matplotlib.cm.ScalarMappable(norm, "inferno_r"), **bar)
    if corners is not None:
        for i, j in [(0, 1), (1, 2), (2, 3), (3, 0), (4, 5), (5, 6), (6, 7), (7, 4), (0, 4), (1, 5), (2, 6), (3, 7)]:
            ax.plot(*zip(corners[i], corners[j]), color="0.3", linewidth=0.8)
    ax.set_xlabel("x (flow)")
    ax.set_ylabel("y (gradient)")
    ax.set_zlabel("z (vorticity)")
    if corners is not None:
        ax.set_box_aspect(tuple(np.ptp(corners, axis=0)))
    ax.view_init(elev=20, azim=15, vertical_axis="y")  # shear plane facing the viewer: x right, y up
    ax.set_title(title)
    return ax


def main():
    if len(sys.argv) < 2 or sys.argv[1] in ("-h", "--help"):
        print(__doc__.splitlines()[-1].strip(), file=sys.stderr)
        sys.exit(2)
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("run", help="run directory (with run.xdmf and run.h5)")
    parser.add_argument("--snapshot", type=int, default=-1, help="snapshot index from 0 (default: the last)")
    parser.add_argument("--out", help="PNG to write (default RUN_DIR/snapshot.png)")
    parser.add_argument("--force", action="store_true", help="replace an existing --out that is not a PNG")
    args = parser.parse_args()
    xdmf = os.path.join(args.run, "run.xdmf")
    if not os.path.isfile(xdmf):
        parser.exit(2, f"error: {xdmf}: no such file (suspend run writes it at the end or at a stop)\n")
    out = args.out or os.path.join(args.run, "snapshot.png")
    refusal = refuse_file(out, starts_with(b"\x89PNG"), args.force, "a PNG")
    if refusal:
        parser.exit(2, f"error: --out {out}: {refusal}\n")
    require("h5py", "numpy", "matplotlib")
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    base = os.path.dirname(os.path.abspath(xdmf))
    root = ET.parse(xdmf).getroot()
    snap = read_snapshot(root, base, args.snapshot)
    if snap is None:
        parser.exit(2, f"error: --snapshot {args.snapshot}: the run has {len(collection(root, 'particles'))} "
                       "snapshots\n")
    line_count = 0 if snap["ends"] is None else len(snap["ends"])
    fig = plt.figure(figsize=(7, 6), dpi=110)
    draw(fig, snap, f"{os.path.basename(os.path.abspath(args.run))}: strain {snap['strain']:.3g}, "
                    f"{len(snap['radius'])} spheres, {line_count} contacts")
    fig.savefig(out)
    print(f"{out}: snapshot {snap['name']}, strain {snap['strain']:.4g}, {len(snap['radius'])} spheres, "
          f"{line_count} contacts")


if __name__ == "__main__":
    main()
