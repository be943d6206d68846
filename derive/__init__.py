"""Symbolic derivations of the chapter's relations (SymPy).

Each family module (``boussinesq``, ``hertz``, ...) has a function ``relations()`` that derives
its relations from their starting point and returns them as
:class:`~hertzmdr.derive.relation.Relation` records. ``python -m hertzmdr.derive`` prints
them into ``numeric/_generated.py``, ``docs/derivations.md`` and ``docs/errata.md``;
``--check`` fails when those files are stale.
"""

from hertzmdr.derive.relation import Relation, all_relations

__all__ = ["Relation", "all_relations"]
