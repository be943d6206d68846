"""Example scenes: the chapter's Problems 1-8 and figures. Installed as hertzmdr.numeric.tour,
the built-in tour that ``hertzmdr run`` (and ``make demo``) runs without a scene file."""
