"""Results that draw themselves in a notebook: ``FuzzyCurve.measure`` and
``FuzzyCurve.section`` return a plain dict or list of the command's keys,
as an instance of the subclasses below, whose ``_repr_html_`` shows the
figure of ``t2spline plot`` for it (drawn by the Rust figure code when the
notebook asks). Otherwise they are the dict or the list: equal to it, and
pickled and copied as it."""

from __future__ import annotations

from typing import Any, Dict, List, Protocol, Tuple, Union


class _Picture(Protocol):
    def _repr_html_(self) -> str: ...


class PicturedDict(Dict[str, Any]):
    """A result dict that shows its figure in a notebook."""

    _picture: _Picture

    def _repr_html_(self) -> str:
        return self._picture._repr_html_()

    def __reduce__(self) -> Tuple[Any, Tuple[Any, ...]]:
        return (dict, (dict(self),))


class PicturedList(List[Any]):
    """A result list that shows its figure in a notebook."""

    _picture: _Picture

    def _repr_html_(self) -> str:
        return self._picture._repr_html_()

    def __reduce__(self) -> Tuple[Any, Tuple[Any, ...]]:
        return (list, (list(self),))


def pictured(value: Union[Dict[str, Any], List[Any]], picture: _Picture) -> Union[PicturedDict, PicturedList]:
    """``value`` (a dict or a list) that shows ``picture`` in a notebook."""
    out: Union[PicturedDict, PicturedList]
    out = PicturedDict(value) if isinstance(value, dict) else PicturedList(value)
    out._picture = picture
    return out
