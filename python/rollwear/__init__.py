"""rollwear from Python: the commands `contact`, `transient`, `run` and `sweep` as functions (docs/python.md).

    import rollwear
    r = rollwear.contact("cases/paper.yaml")
    r["summary"]["a_m"], r["strips"]["power_W_per_m"], r["fields"]["pressure_Pa"]

A case is a case file's path, or a dict of the same sections (README.md, "The case file"). The results are
dicts of NumPy arrays named as the columns of the files the command line writes; the functions write no
files (but `sweep`, which writes its folder as `rollwear sweep` does).

Errors: InputError (a ValueError) for bad input, with .file, .line, .column and .key (None where not known);
SolverError for a solver that failed on valid input; Error, the base of both, for any other failure.
Ctrl-C interrupts a long call (KeyboardInterrupt). The GIL is released while the engine runs. The engine's
messages go to Python's logging, logger "rollwear".
"""

import csv
import json
import math
import os
import numbers

import numpy as np

from ._rollwear import Error, InputError, SolverError
from . import _rollwear

__all__ = ["contact", "transient", "run", "sweep", "Error", "InputError", "SolverError", "case_yaml"]


def _scalar(v):
    if isinstance(v, (bool, np.bool_)):
        return "true" if v else "false"
    if isinstance(v, numbers.Integral):
        return str(int(v))
    if isinstance(v, numbers.Real):
        f = float(v)
        if math.isnan(f):
            return ".nan"
        if math.isinf(f):
            return ".inf" if f > 0 else "-.inf"
        return repr(f)  # the shortest text that reads back exactly
    if isinstance(v, str):
        return json.dumps(v)  # a double-quoted YAML string: always a string, never a number
    if v is None:
        return "null"
    raise TypeError(f"rollwear: a case value must be a number, a bool, a string, a list or a dict, got {type(v).__name__}")


def _flow(v):
    if isinstance(v, dict):
        return "{" + ", ".join(f"{_key(k)}: {_flow(x)}" for k, x in v.items()) + "}"
    if isinstance(v, (list, tuple, np.ndarray)):
        return "[" + ", ".join(_flow(x) for x in (v.tolist() if isinstance(v, np.ndarray) else v)) + "]"
    return _scalar(v)


def _key(k):
    if not isinstance(k, str):
        raise TypeError(f"rollwear: a case key must be a string, got {k!r}")
    return json.dumps(k) if not k or not all(c.isalnum() or c in "_-." for c in k) else k


def case_yaml(case):
    """The YAML text a dict case is read as: a mapping per line down to the keys, lists and the values of
    the innermost mappings in flow style. An InputError's .line is a line of this text."""
    lines = []

    def block(d, indent):
        for k, v in d.items():
            if isinstance(v, dict) and v and any(isinstance(x, dict) for x in v.values()):
                lines.append(" " * indent + f"{_key(k)}:")
                block(v, indent + 2)
            else:
                lines.append(" " * indent + f"{_key(k)}: {_flow(v)}")

    if not isinstance(case, dict):
        raise TypeError("rollwear: a case is a path or a dict")
    block(case, 0)
    return "\n".join(lines) + "\n"


def _source(case, base_dir):
    """(text or path, is_text, base_dir) for the engine"""
    if isinstance(case, dict):
        return case_yaml(case), True, os.fspath(base_dir) if base_dir is not None else os.getcwd()
    if isinstance(case, (str, os.PathLike)):
        return os.fspath(case), False, ""
    raise TypeError("rollwear: a case is a path (str, os.PathLike) or a dict")


def contact(case, *, fields=True, subsurface=True, base_dir=None):
    """One steady contact (`rollwear contact`): {"summary": summary.csv's values, "strips": strips.csv's
    columns, "fields": fields.csv's as (nx, ny) arrays, a[i, j] at x_m[i], y_m[j] (with fields=True),
    "subsurface": {"body1", "body2"}: subsurface.csv's maxima, each {"value_Pa", "x_m", "y_m", "z_m"}, and
    with the body's shear_yield_Pa fatigue.csv's values as "fatigue" (with subsurface=True and the case's
    output.subsurface)}. base_dir: the folder a dict case's profile files are relative to (default: the
    working directory)."""
    text, is_text, base = _source(case, base_dir)
    return _rollwear.contact(text, is_text, base, fields, subsurface)


def transient(case, *, fields=True, base_dir=None, force=False):
    """One transient run (`rollwear transient`): {"summary", "timeseries": timeseries.csv's columns,
    "strips": {"y_m", "energy_J_per_m", "power_W_per_m" (steps, ny)}, "snapshots": a list of fields}.
    A run whose output is estimated above output.max_bytes (default 1 GiB) raises InputError before it
    starts, as the command refuses it; force=True runs it (`--force`)."""
    text, is_text, base = _source(case, base_dir)
    return _rollwear.transient(text, is_text, base, fields, bool(force))


def run(case, *, base_dir=None):
    """One wear life (`rollwear run`, without checkpoints or files): {"summary": report.txt's values,
    "steps": summary.csv's columns (step 0 unworn), "profiles": {"body1": {"y_m", "z_original_m",
    "revolutions" (k), "depth_m" (k, nodes), "z_m" (k, nodes)}} at the start, the snapshot revolutions and
    the end}. A failed life raises SolverError, its .result holding what the life reached."""
    text, is_text, base = _source(case, base_dir)
    return _rollwear.run(text, is_text, base)


def sweep(path, *, output_dir=None, threads=0, shard=(1, 1), force=False):
    """A sweep (`rollwear sweep`, docs/sweeps.md): runs it into its folder (output_dir, else the sweep's
    output.directory, else out/<sweep file stem>; a finished case is not run again) and returns
    {"directory": the folder, "results": results.csv's columns (numbers as arrays, ended_by, status and
    message as lists of str)}. threads 0: every core. shard: (K, N) or "K/N", the K-th of N parts as `rollwear
    sweep --shard K/N` runs it. Ctrl-C stops it after the running cases; the same
    call resumes it. A shard of more than 10000 cases raises InputError before any case is read, unless
    force=True (`--force`)."""
    k, n = _shard_of(shard)
    if isinstance(threads, bool) or not isinstance(threads, numbers.Integral):
        raise _input_error(f"sweep: threads: expected a whole number >= 0 (0: every core), got {threads!r}", "threads")
    directory = _rollwear.sweep(os.fspath(path), os.fspath(output_dir) if output_dir is not None else "",
                                int(threads), int(k), int(n), bool(force))
    return {"directory": directory, "results": read_results(os.path.join(directory, "results.csv"))}


def _input_error(message, key):
    """an InputError as the engine raises it, with no file or line (an argument, not a case file's key)"""
    e = InputError(message)
    e.file, e.line, e.column, e.key = None, None, None, key
    return e


def _shard_of(shard):
    """(K, N) from (K, N) or "K/N" (as `rollwear sweep --shard` takes it); the engine checks 1 <= K <= N"""
    if isinstance(shard, str):
        k, slash, n = shard.partition("/")
        if slash and k.strip().isdigit() and n.strip().isdigit():
            return int(k), int(n)
    elif isinstance(shard, (tuple, list)) and len(shard) == 2 and all(
            isinstance(x, numbers.Integral) and not isinstance(x, bool) for x in shard):
        return int(shard[0]), int(shard[1])
    raise _input_error(f'sweep: shard: expected (K, N) or "K/N", e.g. (2, 8) or "2/8", got {shard!r}', "shard")


_TEXT_COLUMNS = ("ended_by", "status", "message", "fidelity")


def read_results(path):
    """A sweep's results.csv as a dict of columns: numbers as NumPy arrays, the words as lists of str."""
    with open(path, newline="") as f:
        rows = [r for r in csv.reader(f) if r and not r[0].startswith("#")]
    header, body = rows[0], rows[1:]
    out = {}
    for i, name in enumerate(header):
        column = [r[i] if i < len(r) else "" for r in body]
        if name in _TEXT_COLUMNS:
            out[name] = column
        elif name == "index":
            out[name] = np.array([int(v) for v in column], dtype=np.int64)
        else:
            out[name] = np.array([float(v) if v != "" else math.nan for v in column])
    return out
