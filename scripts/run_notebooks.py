"""Execute Jupyter notebooks with nbclient; used by scripts/notebooks.sh.

Runs with the python of the notebook environment that scripts/notebooks.sh
made, on the kernel `subdlab-notebooks` of that environment (checked below),
one notebook after the other, each in its own folder as the working directory
(as Jupyter does). Executed copies go to $SUBDLAB_TARGET_DIR/notebooks-executed/,
also for a notebook that fails, so its outputs up to the failing cell can be
read. Exit status 1 when any cell raises, with the notebook, the cell and the
error on standard error.

Each notebook that runs through is also rendered for reading in a browser:
Markdown (its text cells, its code, its printed output) with its figures
as files beside it, into $SUBDLAB_NOTEBOOKS_RENDERED (default
$SUBDLAB_TARGET_DIR/notebooks-rendered; `scripts/notebooks.sh --publish`
renders into reports/notebooks/). The rendering depends only on the notebook
and what it computed: absolute paths of the repository and the target folder
are written relative, the build's commit as "(commit of this build)", and
consecutive stream outputs are joined (how a kernel chunks them varies), so
tests/notebooks.rs can compare it byte for byte with the committed one.
"""

import base64
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


COMMIT = re.compile(r"\(commit [0-9a-f]{7,40}(?:[-+]dirty)?\)")


def normalised(text, repo, target):
    """Text of an output with the run's own paths and commit left out."""
    text = text.replace(str(target), "target").replace(str(repo) + "/", "").replace(str(repo), ".")
    return COMMIT.sub("(commit of this build)", text)


def fenced(text, lang=""):
    fence = "```"
    while fence in text:
        fence += "`"
    return f"{fence}{lang}\n{text.rstrip()}\n{fence}\n"


def render(nb, name, out_dir, repo, target):
    """Markdown of an executed notebook at out_dir/NAME.md, figures in out_dir/NAME/."""
    figures_dir = out_dir / name
    if figures_dir.exists():
        for f in figures_dir.iterdir():
            f.unlink()
    else:
        figures_dir.mkdir(parents=True)
    parts = [f"<!-- rendered from notebooks/{name}.ipynb by scripts/notebooks.sh; do not edit -->\n"]
    figure = 0
    for cell in nb.cells:
        if cell.cell_type == "markdown":
            parts.append(cell.source.rstrip() + "\n")
            continue
        if cell.cell_type != "code":
            continue
        parts.append(fenced(cell.source, "python"))
        stream, stream_name = [], None

        def flush():
            if stream:
                parts.append(fenced(normalised("".join(stream), repo, target)))
                stream.clear()

        for o in cell.get("outputs", []):
            if o.output_type == "stream":
                if o.name != stream_name:
                    flush()
                    stream_name = o.name
                stream.append(o.text)
                continue
            flush()
            stream_name = None
            data = o.get("data", {})
            if "image/svg+xml" in data or "image/png" in data:
                figure += 1
                if "image/svg+xml" in data:
                    file = f"figure-{figure}.svg"
                    (figures_dir / file).write_text(data["image/svg+xml"], encoding="utf-8")
                else:
                    file = f"figure-{figure}.png"
                    (figures_dir / file).write_bytes(base64.b64decode(data["image/png"]))
                parts.append(f"![figure {figure}]({name}/{file})\n")
            elif "text/plain" in data:
                parts.append(fenced(normalised(data["text/plain"], repo, target)))
        flush()
    if figure == 0:
        figures_dir.rmdir()
    (out_dir / f"{name}.md").write_text("\n".join(parts), encoding="utf-8")


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
    rendered_dir = Path(os.environ.get("SUBDLAB_NOTEBOOKS_RENDERED") or target / "notebooks-rendered")
    rendered_dir.mkdir(parents=True, exist_ok=True)
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
        render(nb, path.stem, rendered_dir, repo, target)
        summaries = [m.group(0) for c in nb.cells if c.cell_type == "code" for m in SUMMARY.finditer(stream_text(c))]
        summary = summaries[-1] if summaries else "(no summary line)"
        print(f"ok     {name} ({seconds:.1f} s): {summary}")
    passed = len(notebooks) - len(failures)
    print(
        f"notebooks: {passed} passed, {len(failures)} failed in {time.monotonic() - total:.1f} s; "
        f"executed copies in {out_dir}, rendered in {rendered_dir}"
    )
    if failures:
        sys.exit(1)


if __name__ == "__main__":
    main()
