#!/usr/bin/python3
"""Draws one snapshot of a run the way ParaView shows run.xdmf: the spheres coloured by species, the contact
network as lines coloured by the contact force magnitude, and the sheared periodic cell; everything is read through
the XDMF's references (so the picture tests what a user opens). Headless (matplotlib Agg, 3-D).
Usage: tools/render_snapshot.py RUN_DIR [--snapshot K (default: the last)] [--out FILE.png]"""
import argparse
import os
import sys
import xml.etree.ElementTree as ET

from debian_python import require


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


def step_grid(root, collection, index):
    for c in root.iter("Grid"):
        if c.get("Name") == collection and c.get("CollectionType") == "Temporal":
            grids = c.findall("Grid")
            return grids, (grids[index] if grids and -len(grids) <= index < len(grids) else None)
    return [], None


def attribute(grid, name, base):
    for a in grid.findall("Attribute"):
        if a.get("Name") == name:
            return values(a.find("DataItem"), base)
    return None


def main():
    if len(sys.argv) < 2 or sys.argv[1] in ("-h", "--help"):
        print(__doc__.splitlines()[-1].strip(), file=sys.stderr)
        sys.exit(2)
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("run", help="run directory (with run.xdmf and run.h5)")
    parser.add_argument("--snapshot", type=int, default=-1, help="snapshot index from 0 (default: the last)")
    parser.add_argument("--out", help="PNG to write (default RUN_DIR/snapshot.png)")
    args = parser.parse_args()
    xdmf = os.path.join(args.run, "run.xdmf")
    if not os.path.isfile(xdmf):
        parser.exit(2, f"error: {xdmf}: no such file (suspend run writes it at the end or at a stop)\n")
    require("h5py", "numpy", "matplotlib")
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    import numpy as np
    from mpl_toolkits.mplot3d.art3d import Line3DCollection

    base = os.path.dirname(os.path.abspath(xdmf))
    root = ET.parse(xdmf).getroot()
    grids, particles = step_grid(root, "particles", args.snapshot)
    if particles is None:
        parser.exit(2, f"error: --snapshot {args.snapshot}: the run has {len(grids)} snapshots\n")
    name = particles.get("Name")
    strain = float(particles.find("Time").get("Value"))
    position = values(particles.find("Geometry/DataItem"), base)
    radius = attribute(particles, "radius", base)
    species = attribute(particles, "species", base)

    fig = plt.figure(figsize=(7, 6), dpi=110)
    ax = fig.add_subplot(projection="3d")
    ax.set_proj_type("ortho")
    # Marker area in points^2 from the sphere's diameter on the axes (approximate: the view is orthographic).
    _, box = step_grid(root, "box", args.snapshot)
    corners = values(box.find("Geometry/DataItem"), base) if box is not None else None
    span = float(np.ptp(corners[:, 0])) if corners is not None else float(np.ptp(position[:, 0]))
    points_per_length = 0.55 * 72 * 6.0 / span
    colours = np.where(species > 0, "#d95f02", "#1b9e77")
    ax.scatter(position[:, 0], position[:, 1], position[:, 2], s=(2 * radius * points_per_length) ** 2,
               c=colours, alpha=0.35, edgecolors="none", depthshade=False)
    _, contacts = step_grid(root, "contacts", args.snapshot)
    line_count = 0
    if contacts is not None and contacts.get("Name") == name:
        ends = values(contacts.find("Geometry/DataItem"), base).reshape(-1, 2, 3)
        force = np.linalg.norm(attribute(contacts, "contact_force", base), axis=1)
        lines = Line3DCollection(ends, cmap="inferno_r", linewidths=1.6)
        lines.set_array(force)
        ax.add_collection3d(lines)
        fig.colorbar(lines, ax=ax, shrink=0.6, label="|contact force| (eta_0 gammadot_ref a_1^2)")
        line_count = len(ends)
    if corners is not None:
        for i, j in [(0, 1), (1, 2), (2, 3), (3, 0), (4, 5), (5, 6), (6, 7), (7, 4), (0, 4), (1, 5), (2, 6), (3, 7)]:
            ax.plot(*zip(corners[i], corners[j]), color="0.3", linewidth=0.8)
    ax.set_xlabel("x (flow)")
    ax.set_ylabel("y (gradient)")
    ax.set_zlabel("z (vorticity)")
    if corners is not None:
        ax.set_box_aspect(tuple(np.ptp(corners, axis=0)))
    ax.view_init(elev=20, azim=15, vertical_axis="y")  # shear plane facing the viewer: x right, y up
    ax.set_title(f"{os.path.basename(os.path.abspath(args.run))}: strain {strain:.3g}, "
                 f"{len(radius)} spheres, {line_count} contacts")
    out = args.out or os.path.join(args.run, "snapshot.png")
    fig.savefig(out)
    print(f"{out}: snapshot {name}, strain {strain:.4g}, {len(radius)} spheres, {line_count} contacts")


if __name__ == "__main__":
    main()
