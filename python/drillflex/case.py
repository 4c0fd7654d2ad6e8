"""drillflex.Case: a case read from a file, YAML text or a dict (docs/case-format.md)."""
from __future__ import annotations

import json
import os
from typing import Any, Mapping, Union

from drillflex._core import Case

CaseLike = Union[Case, str, "os.PathLike[str]"]


def _from_dict(values: Mapping[str, Any], directory: str = ".") -> Case:
    """A case from a dict of the case file's keys (JSON is YAML: the dict is read as its JSON text).

    ``directory`` resolves a ``well.survey_file``. Errors name the file ``<dict>``.
    """
    return Case.from_yaml(json.dumps(values), "<dict>", directory)


Case.from_dict = staticmethod(_from_dict)  # type: ignore[attr-defined]


def as_case(case: CaseLike) -> Case:
    """``case`` itself, or the case file at that path."""
    if isinstance(case, Case):
        return case
    if isinstance(case, (str, os.PathLike)):
        return Case.from_file(os.fspath(case))
    raise TypeError(f"expected a drillflex.Case or a case file's path, got {type(case).__name__}")
