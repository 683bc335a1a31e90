"""Execute Jupyter notebooks with nbclient; used by scripts/notebooks.sh.

Runs with the python of the notebook environment that scripts/notebooks.sh
made, on the kernel `subdlab-notebooks` of that environment (checked below),
one notebook after the other, each in its own folder as the working directory
(as Jupyter does). Executed copies go to $SUBDLAB_TARGET_DIR/notebooks-executed/,
also for a notebook that fails, so its outputs up to the failing cell can be
read. Exit status 1 when any cell raises, with the notebook, the cell and the
error on standard error.
"""

import os
import re
import sys
import time
from pathlib import Path

import nbformat
from jupyter_client.kernelspec import KernelSpecManager
from nbclient import NotebookClient
from nbclient.exceptions import CellExecutionError, CellTimeoutError, DeadKernelError

KERNEL = "subdlab-notebooks"
SUMMARY = re.compile(r"^notebook [\w.-]+: \d+ checks passed$", re.M)


def fail(message):
    print(f"scripts/notebooks.sh: {message}", file=sys.stderr)
    sys.exit(1)


def kernel_is_ours():
    """The kernel spec must start this environment's python, not another one."""
    try:
        spec = KernelSpecManager().get_kernel_spec(KERNEL)
    except Exception as e:  # noqa: BLE001 - report whatever jupyter_client says
        fail(f"kernel '{KERNEL}' not found in the notebook environment ({e}); delete {sys.prefix} to remake it")
    if os.path.abspath(spec.argv[0]) != os.path.abspath(sys.executable):
        fail(f"kernel '{KERNEL}' runs {spec.argv[0]}, not the notebook environment's {sys.executable}")


def cell_source_head(cell):
    lines = [line for line in cell.source.splitlines() if line.strip()]
    return lines[0] if lines else "(empty)"


def stream_text(cell):
    return "".join(o.get("text", "") for o in cell.get("outputs", []) if o.get("output_type") == "stream")


def execute(path, out_dir, timeout):
    """Execute one notebook; return None on success, else a description of the failure."""
    nb = nbformat.read(path, as_version=4)
    client = NotebookClient(
        nb,
        timeout=timeout,
        startup_timeout=120,
        kernel_name=KERNEL,
        # the kernel talks to this process over localhost TCP; ipykernel warns at
        # every start that this is unencrypted, which says nothing about the notebook
        extra_arguments=["--IPKernelApp.log_level=ERROR"],
        allow_errors=False,
        resources={"metadata": {"path": str(path.parent)}},
    )
    current = {"index": None}

    def on_cell_start(cell, cell_index, **_):
        current["index"] = cell_index

    client.on_cell_start = on_cell_start
    out_path = out_dir / path.name
    if out_path.exists():
        out_path.unlink()
    error = None
    try:
        client.execute()
    except CellExecutionError as e:
        error = f"{e.ename}: {e.evalue}"
    except CellTimeoutError:
        error = f"timed out after {timeout} s (NOTEBOOK_CELL_TIMEOUT)"
    except DeadKernelError as e:
        error = f"the kernel died: {e}"
    except Exception as e:  # noqa: BLE001 - e.g. the kernel did not start
        error = f"{type(e).__name__}: {e}"
    finally:
        nbformat.write(nb, out_path)
    if error is None:
        return None
    where = "before the first cell (kernel start)"
    i = current["index"]
    if i is not None:
        cell = nb.cells[i]
        code_number = sum(1 for c in nb.cells[: i + 1] if c.cell_type == "code")
        where = f"cell {i + 1} of {len(nb.cells)} (code cell {code_number}, starting '{cell_source_head(cell)}')"
    return f"{where}: {error}"


def main():
    repo = Path(__file__).resolve().parent.parent
    target = Path(os.environ["SUBDLAB_TARGET_DIR"])
    out_dir = target / "notebooks-executed"
    out_dir.mkdir(parents=True, exist_ok=True)
    timeout = int(os.environ.get("NOTEBOOK_CELL_TIMEOUT", "300"))
    if sys.argv[1:]:
        notebooks = [Path(a).resolve() for a in sys.argv[1:]]
        for p in notebooks:
            if not p.is_file() or p.suffix != ".ipynb":
                fail(f"{p}: not a notebook file (.ipynb)")
    else:
        notebooks = sorted((repo / "notebooks").glob("*.ipynb"))
        if not notebooks:
            fail(f"no notebooks in {repo / 'notebooks'}")
    kernel_is_ours()

    failures = []
    total = time.monotonic()
    for path in notebooks:
        name = os.path.relpath(path, repo) if path.is_relative_to(repo) else str(path)
        start = time.monotonic()
        problem = execute(path, out_dir, timeout)
        seconds = time.monotonic() - start
        executed = out_dir / path.name
        if problem is not None:
            print(f"FAILED {name} ({seconds:.1f} s): {problem}", file=sys.stderr)
            print(f"       outputs up to the failing cell: {executed}", file=sys.stderr)
            failures.append(name)
            continue
        nb = nbformat.read(executed, as_version=4)
        summaries = [m.group(0) for c in nb.cells if c.cell_type == "code" for m in SUMMARY.finditer(stream_text(c))]
        summary = summaries[-1] if summaries else "(no summary line)"
        print(f"ok     {name} ({seconds:.1f} s): {summary}")
    passed = len(notebooks) - len(failures)
    print(f"notebooks: {passed} passed, {len(failures)} failed in {time.monotonic() - total:.1f} s; executed copies in {out_dir}")
    if failures:
        sys.exit(1)


if __name__ == "__main__":
    main()
