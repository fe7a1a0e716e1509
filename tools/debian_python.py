"""Makes a tool run under Debian's /usr/bin/python3 when the python3 first on PATH (pyenv, conda, a venv) lacks the
Debian packages it needs (python3-h5py, python3-numpy, python3-matplotlib): `require("h5py")` re-executes the
script there, or exits with one line saying what to install."""
import importlib
import os
import sys

DEBIAN_PYTHON = "/usr/bin/python3"


def require(*modules):
    missing = []
    for name in modules:
        try:
            importlib.import_module(name)
        except ImportError:
            missing.append(name)
    if not missing:
        return
    if os.path.realpath(sys.executable) != os.path.realpath(DEBIAN_PYTHON) and os.access(DEBIAN_PYTHON, os.X_OK):
        os.execv(DEBIAN_PYTHON, [DEBIAN_PYTHON] + sys.argv)
    print("error: %s needs the Python module(s) %s (Debian: apt-get install %s)"
          % (os.path.basename(sys.argv[0]), ", ".join(missing), " ".join("python3-" + m for m in missing)),
          file=sys.stderr)
    sys.exit(2)
