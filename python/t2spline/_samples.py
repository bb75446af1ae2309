"""The dict that ``Solution.sample`` and ``SurfaceSolution.sample`` return.

Its keys are the result file's (``curves`` of ``t2spline run``):
``type_reduced`` holds ``left`` and ``right``. The flat keys of earlier
releases, ``type_reduced_left`` and ``type_reduced_right``, still answer for
one release, with a ``DeprecationWarning``.
"""

from __future__ import annotations

import warnings
from typing import Any, Dict, Tuple

_OLD_KEYS: Dict[str, Tuple[str, str]] = {
    "type_reduced_left": ("type_reduced", "left"),
    "type_reduced_right": ("type_reduced", "right"),
}


class SampledStages(Dict[str, Any]):
    """A dict of sampled stages; see ``Solution.sample``."""

    def __missing__(self, key: str) -> Any:
        if key in _OLD_KEYS:
            outer, inner = _OLD_KEYS[key]
            warnings.warn(
                f"the key {key!r} is deprecated and will be removed in the next release: "
                f"use [{outer!r}][{inner!r}]",
                DeprecationWarning,
                stacklevel=2,
            )
            return self[outer][inner]
        raise KeyError(key)
