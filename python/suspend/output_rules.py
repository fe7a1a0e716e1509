"""What a command may write over (docs/output.md, "Overwriting"): the files of a run, a campaign, a cross-validation
and a phi_m fit are never the target of another command, forced or not; an earlier output of the same kind is
replaced; any other existing file only when told (--force)."""
import os

# What a run, campaign, cross-validation or fit folder holds.
RESULT_FILES = {"run.h5", "checkpoint.h5", "run.xdmf", "summary.json", "point.json", "log.txt", "campaign.json",
                "campaign.csv", "sweep.json", "phim.json", "phim.csv", "crossval.json"}


def refuse_file(path, is_own_kind, force, kind="an earlier output of this tool"):
    """Why `path` may not be written (None when it may): a result file never, a folder or a missing folder never,
    another existing file that `is_own_kind(path)` does not recognise only with `force`."""
    if os.path.basename(path) in RESULT_FILES or path.endswith((".h5", ".hdf5")):
        return "a run's or campaign's own file name; choose another"
    if os.path.isdir(path):
        return "is a directory; give a file name"
    parent = os.path.dirname(os.path.abspath(path))
    if not os.path.isdir(parent):
        return f"the folder {parent} does not exist"
    if os.path.exists(path) and not force and not is_own_kind(path):
        return f"exists and is not {kind}; choose another name or pass --force to replace it"
    return None


def starts_with(magic):
    """An is_own_kind test: the file begins with these bytes."""
    def test(path):
        try:
            with open(path, "rb") as f:
                return f.read(len(magic)) == magic
        except OSError:
            return False
    return test
