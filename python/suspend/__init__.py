"""Reading suspend's output into numpy arrays (docs/output.md).

    import sys; sys.path.insert(0, "python")          # from the source tree
    import suspend
    run = suspend.load_run("runs/q")
    run.series["eta_r"], run.series["strain"]         # numpy arrays, one value per row
    run.units["eta_r"]                                 # "eta_0"
    run.stress["contact_normal"][:, 3]                 # (rows, 6): xx yy zz xy xz yz, in eta_0 gammadot_ref
    s = run.snapshot(-1)                               # dict: position (N,3), radius, species, box, shear_offset,
                                                       #       strain, contact_pairs (M,2), contact_force (M,3), ...
    run.summary["eta_r"]["mean"], run.case["particles"]["phi"]
    table = suspend.load_campaign("runs/campaign")     # dict of numpy arrays, one entry per point

Lengths are in a_1, times in 1/gammadot_ref, stresses in eta_0 gammadot_ref; every series dataset says its own in
its `units` attribute. Needs Debian's python3-h5py and python3-numpy (and python3-yaml only for `run.case` from
files without a summary.json)."""
import json
import os

__all__ = ["Run", "load_run", "load_campaign"]


def _text(value):
    return value.decode() if isinstance(value, bytes) else str(value)


class Run:
    """One `suspend run --out DIR`: its series, snapshots, summary and case."""

    def __init__(self, directory):
        import h5py
        import numpy as np
        self.directory = directory
        self.path = os.path.join(directory, "run.h5") if os.path.isdir(directory) else directory
        if not os.path.isfile(self.path):
            raise FileNotFoundError(f"{self.path}: no run.h5 (suspend run --out DIR writes it)")
        self.series, self.units, self.stress = {}, {}, {}
        with h5py.File(self.path, "r") as f:
            self.attributes = {k: _text(v) if isinstance(v, (bytes, str)) else v for k, v in f.attrs.items()}
            for name, item in f["series"].items():
                if isinstance(item, h5py.Dataset):
                    self.series[name] = np.asarray(item)
                    self.units[name] = _text(item.attrs.get("units", ""))
            for name, item in f["series/stress"].items():
                self.stress[name] = np.asarray(item)
                self.units["stress/" + name] = _text(item.attrs.get("units", f["series/stress"].attrs.get("units", "")))
            self.snapshot_count = len(f["snapshots"]) if "snapshots" in f else 0
            for k in range(self.snapshot_count):  # numbered from 000000 without gaps, as the run writes them
                if f"{k:06d}" not in f["snapshots"]:
                    raise ValueError(f"snapshots/{k:06d} is missing, yet /snapshots holds {self.snapshot_count} "
                                     "entries: the file is damaged")
        summary = os.path.join(os.path.dirname(self.path), "summary.json")
        self.summary = json.load(open(summary)) if os.path.isfile(summary) else None

    @property
    def case(self):
        """The resolved case (summary.json's copy, or the YAML stored in run.h5)."""
        if self.summary and "case" in self.summary:
            return self.summary["case"]
        import yaml
        return yaml.safe_load(self.attributes["case"])

    def snapshot(self, index):
        """Snapshot `index` (negative counts from the end) as a dict of numpy arrays and its attributes."""
        import h5py
        import numpy as np
        if not -self.snapshot_count <= index < self.snapshot_count:
            raise IndexError(f"snapshot {index}: the run has {self.snapshot_count}")
        index %= self.snapshot_count
        with h5py.File(self.path, "r") as f:
            g = f[f"snapshots/{index:06d}"]
            out = {name: np.asarray(item) for name, item in g.items()}
            out.update({name: value for name, value in g.attrs.items()})
        out["index"] = index
        return out

    def snapshots(self):
        for k in range(self.snapshot_count):
            yield self.snapshot(k)


def load_run(directory):
    return Run(directory)


def load_campaign(path):
    """A campaign's table (suspend sweep's campaign.json) as a dict of numpy arrays, one entry per point:
    name, status, the varied parameters, and each summary observable's mean and sem (e.g. eta_r, eta_r_sem)."""
    import numpy as np
    table_path = os.path.join(path, "campaign.json") if os.path.isdir(path) else path
    with open(table_path) as f:
        table = json.load(f)
    rows = []
    for p in table["points"]:
        row = {"name": p["name"], "status": p["status"], "wall_seconds": p.get("wall_seconds", np.nan)}
        row.update(p.get("parameters", {}))
        for key, value in (p.get("summary") or {}).items():
            if isinstance(value, dict) and "mean" in value:
                row[key], row[key + "_sem"] = value["mean"], value.get("sem", np.nan)
        rows.append(row)
    keys = []
    for row in rows:
        keys += [k for k in row if k not in keys]
    out = {}
    for k in keys:
        column = [row.get(k) for row in rows]
        numeric = all(isinstance(v, (int, float)) or v is None for v in column)
        out[k] = np.array([np.nan if v is None else v for v in column], dtype=float) if numeric else np.array(
            ["" if v is None else str(v) for v in column])
    return out
