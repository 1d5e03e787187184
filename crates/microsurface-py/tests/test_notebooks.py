"""The notebooks of examples/notebooks: committed without outputs, and each runs top to bottom
without an error (their cells assert their own checks) in a fresh kernel of this interpreter.

Run: pip install ./crates/microsurface-py pytest scipy matplotlib nbclient nbformat ipykernel
&& pytest crates/microsurface-py/tests/test_notebooks.py. Without nbclient (or ipykernel) the
runs are skipped, unless MICROSURFACE_NOTEBOOKS is set (CI sets it), when a missing package
fails. Each notebook's run time is printed.
"""

import glob
import json
import os
import sys
import time

import pytest

ROOT = os.path.join(os.path.dirname(__file__), "..", "..", "..")
NOTEBOOKS = sorted(glob.glob(os.path.join(ROOT, "examples", "notebooks", "*.ipynb")))
IDS = [os.path.basename(p) for p in NOTEBOOKS]
REQUIRED = "MICROSURFACE_NOTEBOOKS" in os.environ


def test_notebooks_exist():
    assert len(NOTEBOOKS) >= 4, NOTEBOOKS


@pytest.mark.parametrize("path", NOTEBOOKS, ids=IDS)
def test_committed_without_outputs(path):
    # Plain JSON: this check needs no Jupyter package.
    with open(path, encoding="utf-8") as f:
        nb = json.load(f)
    assert nb["nbformat"] == 4
    assert nb["metadata"].get("kernelspec", {}).get("name") == "python3"
    for i, cell in enumerate(nb["cells"]):
        assert "execution" not in cell.get("metadata", {}), (path, i, "execution timing left in")
        if cell["cell_type"] == "code":
            assert cell["outputs"] == [], (path, i, "outputs left in: clear them before committing")
            assert cell["execution_count"] is None, (path, i, "execution count left in")


def _require(module):
    if REQUIRED:
        return __import__(module)  # CI: a missing package is a failure
    return pytest.importorskip(module)


@pytest.mark.parametrize("path", NOTEBOOKS, ids=IDS)
def test_notebook_runs(path, tmp_path, monkeypatch, capsys):
    nbclient = _require("nbclient")
    nbformat = _require("nbformat")
    _require("ipykernel")
    # A kernelspec "python3" that runs this interpreter (the one with microsurface installed),
    # found first: JUPYTER_PATH precedes the user's and the system's kernel directories.
    spec = tmp_path / "jupyter" / "kernels" / "python3"
    spec.mkdir(parents=True)
    (spec / "kernel.json").write_text(json.dumps({
        "argv": [sys.executable, "-m", "ipykernel_launcher", "-f", "{connection_file}"],
        "display_name": "Python 3 (microsurface tests)",
        "language": "python",
        "env": {"MPLBACKEND": "Agg"},
    }))
    monkeypatch.setenv("JUPYTER_PATH", str(tmp_path / "jupyter"))
    monkeypatch.setenv("MPLBACKEND", "Agg")
    work = tmp_path / "cwd"
    work.mkdir()
    nb = nbformat.read(path, as_version=4)
    nb.cells.append(nbformat.v4.new_code_cell("import sys; print(sys.executable, end='')"))
    client = nbclient.NotebookClient(
        nb, timeout=600, kernel_name="python3", resources={"metadata": {"path": str(work)}})
    start = time.perf_counter()
    client.execute()  # raises CellExecutionError, with the cell and its traceback, on any error
    seconds = time.perf_counter() - start
    with capsys.disabled():
        print(f"\n{os.path.basename(path)}: ran in {seconds:.1f} s")
    # Every cell ran, in a kernel of this interpreter (the appended last cell says which).
    assert all(c.execution_count is not None for c in nb.cells if c.cell_type == "code")
    assert nb.cells[-1].outputs[0]["text"] == sys.executable
