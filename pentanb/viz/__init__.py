"""Drawing: numpy data, then matplotlib, then widgets; a module imports only those above it.

* :mod:`~pentanb.viz.colors`: one colour per number of sides (numpy);
* :mod:`~pentanb.viz.camera`: the camera of a 3D view and the frame it draws in (numpy);
* :mod:`~pentanb.viz.drawing`: what a 3D picture shows, and its WebGL buffers (numpy);
* :mod:`~pentanb.viz.stages`: the step-through's stages of Sections 5.1 and 5.2 (numpy);
* :mod:`~pentanb.viz.controls`: the explorer's ranges, argument checks and export plan
  (no widgets);
* :mod:`~pentanb.viz.mpl`: the paper's figures as static images (matplotlib);
* :mod:`~pentanb.viz.three`: the 3D view, :func:`~pentanb.viz.three.view` (pythreejs);
* :mod:`~pentanb.viz.widgets`: :func:`~pentanb.viz.widgets.panel`, the notebooks'
  slider wiring, and the checks of the widgets' arguments (ipywidgets);
* :mod:`~pentanb.viz.explorer`: :func:`~pentanb.viz.explorer.explore`;
* :mod:`~pentanb.viz.steps`: :func:`~pentanb.viz.steps.step_through`;
* :mod:`~pentanb.viz.html`: stand-alone pages, :func:`~pentanb.viz.html.export_html`.

Importing this package imports none of them.
"""
