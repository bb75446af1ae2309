"""Jobs in Arrow tables: ``run_table`` runs one job per row (its JSON text)
and returns one summary row per job, and if asked the samples of every job
as one long table, both as pyarrow Tables.

The job texts are read from the column's Arrow buffers without a copy and
run by ``t2spline.run_many``'s path (the job file's rules, the settings,
``Job.run``, every number finite) on all cores with the GIL released; the
numbers come back as numpy arrays that pyarrow takes without a copy.
Anything with the Arrow PyCapsule interface (``__arrow_c_stream__``: a
pandas or polars DataFrame, a DuckDB result, a ``RecordBatchReader``) is
accepted as the table. pyarrow is needed (``pip install t2spline[arrow]``).
"""

from __future__ import annotations

import importlib
from typing import Any, Dict, List, Literal, Optional, Tuple, Union, overload

import numpy as np

from . import _t2spline

#: A ``pyarrow.Table`` (pyarrow ships no type information, so it is ``Any``
#: to a type checker).
ArrowTable = Any

#: The summary's columns after ``job``, in order: as ``t2spline run``'s
#: summary of many jobs, with ``h`` (the smallest lower height of the job's
#: numbers) and where the distance is largest (``error_max_at``: t, or u of
#: a surface with ``error_max_at_v`` its v).
SUMMARY_COLUMNS = (
    "regime",
    "alpha",
    "h",
    "error_max",
    "error_max_at",
    "error_max_at_v",
    "error_rms",
    "status",
    "message",
    "type_reduction",
)

_FLOATS = ("alpha", "h", "error_max", "error_max_at", "error_max_at_v", "error_rms")


def _arrow() -> Any:
    try:
        return importlib.import_module("pyarrow")
    except ImportError as e:  # pragma: no cover - the tests have pyarrow
        raise ImportError("run_table needs pyarrow: pip install t2spline[arrow]") from e


def _as_table(table: Any) -> ArrowTable:
    pa = _arrow()
    if isinstance(table, pa.Table):
        return table
    if isinstance(table, pa.RecordBatch):
        return pa.Table.from_batches([table])
    if hasattr(table, "__arrow_c_stream__"):
        return pa.RecordBatchReader.from_stream(table).read_all()
    raise TypeError(
        "table: expected a pyarrow Table or an object with the Arrow PyCapsule "
        f"interface (__arrow_c_stream__), got {type(table).__name__}"
    )


def _texts(table: ArrowTable, column: str) -> Any:
    pa = _arrow()
    if column not in table.column_names:
        raise ValueError(
            f"column: the table has no column {column!r} (it has {', '.join(map(repr, table.column_names))})"
        )
    texts = table.column(column)
    kind = texts.type
    if pa.types.is_string(kind) or pa.types.is_large_string(kind):
        return texts
    if pa.types.is_string_view(kind):
        return texts.cast(pa.large_string())
    raise TypeError(f"column: {column!r} holds {kind}, not job texts (string)")


def _floats(values_valid: Tuple[np.ndarray, np.ndarray]) -> Any:
    pa = _arrow()
    values, valid = values_valid
    if valid.all():
        return pa.array(values, type=pa.float64())
    return pa.array(values, type=pa.float64(), mask=~valid)


def _merge(parts: List[Dict[str, Any]]) -> Dict[str, Any]:
    """The columns of several chunks' rows, concatenated."""
    if len(parts) == 1:
        return parts[0]
    out: Dict[str, Any] = {}
    for key in ("status", "message", "type_reduction", "regime"):
        out[key] = [v for p in parts for v in p[key]]
    for key in _FLOATS:
        out[key] = tuple(np.concatenate([p[key][i] for p in parts]) for i in range(2))
    if "samples" in parts[0]:
        rows = np.concatenate([p["samples"][0] for p in parts])
        columns = {
            name: tuple(np.concatenate([p["samples"][1][name][i] for p in parts]) for i in range(2))
            for name in parts[0]["samples"][1]
        }
        out["samples"] = (rows, columns)
    return out


@overload
def run_table(
    table: Any,
    column: str = ...,
    samples: Literal[False] = ...,
    *,
    id: Optional[str] = ...,
    sample_count: Union[int, Tuple[int, int], None] = ...,
    alpha: Optional[float] = ...,
    type_reduction: Optional[str] = ...,
) -> ArrowTable: ...


@overload
def run_table(
    table: Any,
    column: str = ...,
    samples: Literal[True] = ...,
    *,
    id: Optional[str] = ...,
    sample_count: Union[int, Tuple[int, int], None] = ...,
    alpha: Optional[float] = ...,
    type_reduction: Optional[str] = ...,
) -> Tuple[ArrowTable, ArrowTable]: ...


def run_table(
    table: Any,
    column: str = "job",
    samples: bool = False,
    *,
    id: Optional[str] = "id",
    sample_count: Union[int, Tuple[int, int], None] = None,
    alpha: Optional[float] = None,
    type_reduction: Optional[str] = None,
) -> Union[ArrowTable, Tuple[ArrowTable, ArrowTable]]:
    """Runs one job per row of an Arrow table, as ``run`` runs one.

    Parameters
    ----------
    table : pyarrow.Table, or anything with ``__arrow_c_stream__``
        One job per row: its JSON text (a job file's content) in ``column``.
    column : str
        The column of job texts (``string``, ``large_string`` or
        ``string_view``).
    samples : bool
        Also return every job's samples as one long table.
    id : str or None
        A column carried through as the ``job`` key of every output row
        (default ``"id"``, when the table has it); otherwise ``job`` is the
        row's index.
    sample_count, alpha, type_reduction : optional
        ``run``'s ``samples=``, ``alpha=`` and ``type_reduction=`` for every
        job (in place of each job's own).

    Returns
    -------
    pyarrow.Table, or (pyarrow.Table, pyarrow.Table) with ``samples=True``
        The summary, one row per job in the table's order: ``job``, then
        ``SUMMARY_COLUMNS``: ``regime``, ``alpha`` (null when the type
        reduction does not use it), ``h`` (the smallest lower height of the
        job's numbers), ``error_max``, ``error_max_at`` (t, or a surface's
        u), ``error_max_at_v`` (a surface's v), ``error_rms``, ``status``
        (``"ok"``, or ``"invalid"`` or ``"internal"`` as ``t2spline run``
        writes it for a job that fails), ``message`` (the error's lines
        joined by ``"; "``, the job named ``<row k>``) and
        ``type_reduction``. The samples: ``job``, then one schema whatever
        the job (``t2spline_io``'s sample columns: ``t``, ``u``, ``v``,
        the seven layers, the alpha-cut layers, left, right, defuzzified,
        each ``_x``, ``_y``, ``_z``, and ``distance``), a column null where a
        job does not have it (a plane curve's ``_z``, a lower cut above h).

    Raises
    ------
    TypeError, ValueError
        For a table, column or keyword that is not one; a job that fails is
        a row with its status and message, not an exception.
    """
    pa = _arrow()
    if not isinstance(samples, (bool, np.bool_)):
        raise TypeError(
            f"samples: expected True or False (whether to return the samples), got {samples!r}; "
            "the number of samples per job is sample_count="
        )
    if not isinstance(column, str):
        raise TypeError(f"column: expected the name of a column (str), got {type(column).__name__}")
    if id is not None and not isinstance(id, str):
        raise TypeError(f"id: expected the name of a column (str) or None, got {type(id).__name__}")
    table = _as_table(table)
    texts = _texts(table, column)
    parts: List[Dict[str, Any]] = []
    first = 0
    for chunk in texts.chunks:
        n = len(chunk)
        _, offsets_buffer, data_buffer = chunk.buffers()[:3]
        wide = pa.types.is_large_string(chunk.type)
        width = np.int64 if wide else np.int32
        raw = (
            np.frombuffer(offsets_buffer, dtype=width)
            if offsets_buffer is not None
            else np.zeros(chunk.offset + n + 1, dtype=width)
        )
        # Arrow lets a buffer start anywhere (pickle protocol 5 and IPC give
        # 8-byte offsets at odd addresses); the offsets are copied when they
        # are not aligned, the texts never are.
        offsets = np.require(
            raw[chunk.offset : chunk.offset + n + 1].astype(np.int64, copy=False),
            requirements=["ALIGNED", "C_CONTIGUOUS"],
        )
        data = (
            np.frombuffer(data_buffer, dtype=np.uint8)
            if data_buffer is not None
            else np.empty(0, dtype=np.uint8)
        )
        valid = chunk.is_valid().to_numpy(zero_copy_only=False) if chunk.null_count else None
        parts.append(
            _t2spline._run_rows(
                data, offsets, valid, first, samples,
                samples=sample_count, alpha=alpha, type_reduction=type_reduction,
            )
        )
        first += n
    if not parts:
        parts.append(
            _t2spline._run_rows(
                np.empty(0, np.uint8), np.zeros(1, np.int64), None, 0, samples,
                samples=sample_count, alpha=alpha, type_reduction=type_reduction,
            )
        )
    rows = _merge(parts)
    if id is not None and id in table.column_names:
        keys = table.column(id)
    else:
        keys = pa.array(np.arange(table.num_rows, dtype=np.int64))
    summary: Dict[str, Any] = {"job": keys}
    for name in SUMMARY_COLUMNS:
        if name in _FLOATS:
            summary[name] = _floats(rows[name])
        else:
            summary[name] = pa.array(rows[name], type=pa.string())
    summary_table = pa.table(summary)
    if not samples:
        return summary_table
    index, columns = rows["samples"]
    long: Dict[str, Any] = {"job": keys.take(pa.array(index))}
    for name, values_valid in columns.items():
        long[name] = _floats(values_valid)
    return summary_table, pa.table(long)
