"""results.json's object with its tables as numpy arrays (what ``drillflex.run`` returns).

A list of numbers becomes a 1-D array, a list of equal-length lists of numbers a 2-D array, and a
list of records (dicts of the same keys holding numbers, text or lists of numbers, as
``static.nodes``) a structured array: ``nodes[0]["axial_force"]`` and ``nodes["axial_force"][0]``
are both the file's value. Everything else stays as ``json.load`` reads it.
"""
from __future__ import annotations

import csv
import io
import json
from numbers import Number
from typing import Any, Dict, List, Optional, Sequence, Tuple

import numpy as np


def _is_number(value: Any) -> bool:
    return isinstance(value, Number) and not isinstance(value, bool)


def _number_dtype(values: Sequence[Any]) -> Optional[type]:
    """int64 or float64 when every value is a number, else None."""
    if not values or not all(_is_number(v) for v in values):
        return None
    return np.int64 if all(isinstance(v, int) for v in values) else np.float64


def _field_dtype(values: List[Any]) -> Optional[Tuple[Any, ...]]:
    """The dtype (and shape) of one field of a list of records, or None when it has none."""
    number = _number_dtype(values)
    if number is not None:
        return (number,)
    if all(isinstance(v, bool) for v in values):
        return (np.bool_,)
    if all(isinstance(v, str) for v in values):
        return (f"U{max(1, max(len(v) for v in values))}",)
    if all(isinstance(v, list) for v in values) and len({len(v) for v in values}) == 1 and len(values[0]) > 0:
        inner = _number_dtype([x for v in values for x in v])
        if inner is not None:
            return (inner, (len(values[0]),))
    return None


def _records(items: List[Dict[str, Any]]) -> Optional[np.ndarray]:
    keys = list(items[0].keys())
    if any(list(item.keys()) != keys for item in items):
        return None
    fields = []
    for key in keys:
        dtype = _field_dtype([item[key] for item in items])
        if dtype is None:
            return None
        fields.append((key, *dtype))
    return np.array([tuple(item[key] for key in keys) for item in items], dtype=fields)


def tabulate(value: Any) -> Any:
    """``value`` (as json.load reads it) with its lists of numbers and of records as numpy arrays."""
    if isinstance(value, dict):
        return {key: tabulate(item) for key, item in value.items()}
    if not isinstance(value, list) or not value:
        return value
    number = _number_dtype(value)
    if number is not None:
        return np.array(value, dtype=number)
    if all(isinstance(v, list) for v in value) and len({len(v) for v in value}) == 1:
        inner = _number_dtype([x for v in value for x in v])
        if inner is not None and value[0]:
            return np.array(value, dtype=inner)
    if all(isinstance(v, dict) for v in value):
        table = _records(value)
        if table is not None:
            return table
    return [tabulate(v) for v in value]


def read_csv_table(text: str) -> np.ndarray:
    """A CSV table of the command line (a line of names, a line of units, rows) as a structured array
    (numbers as float64, text as str). The units are results.json's ``column_units``."""
    rows = list(csv.reader(io.StringIO(text)))
    names, rows = rows[0], rows[2:]
    columns = list(zip(*rows)) if rows else [() for _ in names]
    fields, arrays = [], []
    for name, column in zip(_unique(names), columns):
        try:
            array = np.array([float(cell) for cell in column], dtype=np.float64)
        except ValueError:
            array = np.array(column, dtype=str)
        fields.append((name, array.dtype))
        arrays.append(array)
    table = np.empty(len(rows), dtype=fields)
    for (name, _), array in zip(fields, arrays):
        table[name] = array
    return table


def _unique(names: List[str]) -> List[str]:
    seen: Dict[str, int] = {}
    unique = []
    for name in names:
        seen[name] = seen.get(name, 0) + 1
        unique.append(name if seen[name] == 1 else f"{name}_{seen[name]}")
    return unique


def results_dict(json_text: str, tables: List[Tuple[str, str]]) -> Dict[str, Any]:
    """results.json's object, tabulated, with ``tables``: each CSV file's table by its file name."""
    results = tabulate(json.loads(json_text))
    results["tables"] = {name: read_csv_table(text) for name, text in tables if name.endswith(".csv")}
    return results
