"""Data shipped with pentanb: ``rabbit.obj``, the irregular low-polygon rabbit of
Figure 12 (read it with :func:`pentanb.shapes.rabbit`), and
:mod:`~pentanb.data.make_rabbit`, the script that builds it (MIT licence,
like the rest of the package; see ``README.md`` in this folder)."""
